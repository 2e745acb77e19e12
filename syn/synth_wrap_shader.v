// synth_wrap_shader - a place-and-route harness for spec_shader (spec_setup -> spec_stream) on small packages,
// as syn/synth_wrap.v is for the cores: the 256-bit span-ends beat is shifted in serially, the pixel, tlast
// and flags are XOR-reduced, every shader port is registered on both sides, so the timing report measures the
// shader's own register-to-register paths. Not a usable top level: only for area and Fmax (make synth).
`timescale 1ns / 1ps
`default_nettype none
`include "setup_params.vh"
`include "spec_params.vh"
module synth_wrap_shader #(
    parameter ITERATIVE = 0,
    parameter DELAY_RAM = 0,
    parameter TBL_AW = `SPEC_TBL_AW,
    parameter INTERP = `SPEC_INTERP,
    parameter INTERP_FRAC = `SPEC_INTERP_FRAC,
    parameter DELTA_W = `SPEC_DELTA_W,
    parameter SCALE_W = `SPEC_SCALE_W,
    parameter SCALE_FRAC = `SPEC_SCALE_FRAC,
    parameter ROM9_FILE = `SPEC_ROM9_FILE,
    parameter ROM12_FILE = `SPEC_ROM12_FILE,
    parameter LOG2_FILE = `SETUP_LOG2_FILE,
    parameter EXP2_FILE = `SETUP_EXP2_FILE
) (
    input  wire clk,
    input  wire rst_n,
    input  wire din,
    input  wire strobe,
    output reg  dout,
    output reg  flag
);
    localparam BW = `SETUP_BEAT_W;
    reg [BW-1:0] sh;
    reg strobe_q, rst_q, s_valid, m_ready;
    always @(posedge clk) begin
        sh <= {sh[BW-2:0], din};
        strobe_q <= strobe;
        rst_q <= rst_n;
        s_valid <= strobe_q;
        m_ready <= sh[BW-1] | strobe_q;
    end
    wire s_ready, m_valid, m_last;
    wire [15:0] m_data;
    wire [6:0] m_user;
    spec_shader #(
        .ITERATIVE(ITERATIVE), .DELAY_RAM(DELAY_RAM), .TBL_AW(TBL_AW), .INTERP(INTERP), .INTERP_FRAC(INTERP_FRAC), .DELTA_W(DELTA_W),
        .SCALE_W(SCALE_W), .SCALE_FRAC(SCALE_FRAC), .ROM9_FILE(ROM9_FILE), .ROM12_FILE(ROM12_FILE),
        .LOG2_FILE(LOG2_FILE), .EXP2_FILE(EXP2_FILE)
    ) u_shader (
        .clk(clk), .rst_n(rst_q), .s_axis_tvalid(s_valid), .s_axis_tready(s_ready), .s_axis_tdata(sh),
        .m_axis_tvalid(m_valid), .m_axis_tready(m_ready), .m_axis_tdata(m_data), .m_axis_tlast(m_last),
        .m_axis_tuser(m_user)
    );
    always @(posedge clk) begin
        dout <= ^{m_data, m_last, m_user};
        flag <= s_ready ^ m_valid;
    end
endmodule
`default_nettype wire
