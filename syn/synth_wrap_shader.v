// synth_wrap_shader - a place-and-route harness for spec_shader (either configuration) on small packages,
// as syn/synth_wrap.v is for the cores: the pixel, tlast and flags are XOR-reduced into registers, the span-ends
// beat comes from a serial shift register, so the timing report measures the shader's own register-to-register
// paths. Not a usable top level: only for area and Fmax (make synth). SETUP_ONLY = 1: the configuration's setup
// alone (spec_setup or spec_setup_small), its descriptor and flags XOR-reduced the same way.
// The beat is lean (the small shader fills the UP5K): its BW bits are the XORs of distinct pairs of NS shifted
// bits (NS (NS - 1) / 2 >= BW), one LUT each that packs into the logic cell of the shader's register taking
// the bit, instead of BW flip-flops. Every beat bit is a different function of the pins' registers, and the
// shader registers every beat bit it uses before any arithmetic, so no shader logic can be simplified away.
`timescale 1ns / 1ps
`default_nettype none
`include "setup_params.vh"
`include "setup_small_params.vh"
`include "spec_params.vh"
module synth_wrap_shader #(
    parameter ITERATIVE = 0,
    parameter BACKEND = 0,
    parameter DELAY_RAM = 0,
    parameter SETUP_ONLY = 0,
    parameter TBL_AW = `SPEC_TBL_AW,
    parameter INTERP = `SPEC_INTERP,
    parameter INTERP_FRAC = `SPEC_INTERP_FRAC,
    parameter DELTA_W = `SPEC_DELTA_W,
    parameter SCALE_W = `SPEC_SCALE_W,
    parameter SCALE_FRAC = `SPEC_SCALE_FRAC,
    parameter ROM9_FILE = `SPEC_ROM9_FILE,
    parameter ROM12_FILE = `SPEC_ROM12_FILE,
    parameter EFU_FILE = `SETUP_EFU_FILE,
    parameter EXP2_FILE = `SETUP_EXP2_FILE,
    parameter UC_FILE = `SETUP_UC_FILE,
    parameter SMALL_LOG2_FILE = `SMALL_LOG2_FILE,
    parameter SMALL_EXP2_FILE = `SMALL_EXP2_FILE
) (
    input  wire clk,
    input  wire rst_n,
    input  wire din,
    input  wire strobe,
    output reg  dout,
    output reg  flag
);
    localparam BW = `SETUP_BEAT_W;
    localparam NS = 24;
    // the k-th pair (i, j), i < j < NS, in the order (0, 1), (0, 2), ..., (1, 2), ...
    function integer pair_of(input integer k, input integer second);
        integer i, j, n;
        begin
            n = 0;
            pair_of = 0;
            for (i = 0; i < NS; i = i + 1)
                for (j = i + 1; j < NS; j = j + 1) begin
                    if (n == k) pair_of = (second != 0) ? j : i;
                    n = n + 1;
                end
        end
    endfunction
    reg [NS-1:0] sh;
    reg strobe_q, rst_q, s_valid, m_ready;
    always @(posedge clk) begin
        sh <= {sh[NS-2:0], din};
        strobe_q <= strobe;
        rst_q <= rst_n;
        s_valid <= strobe_q;
        m_ready <= sh[NS-1] | strobe_q;
    end
    wire [BW-1:0] beat;
    genvar b;
    generate
        if (NS * (NS - 1) / 2 < BW) begin : g_check
            synth_wrap_shader_needs_more_pairs too_few_shift_bits ();
        end
        for (b = 0; b < BW; b = b + 1) begin : g_beat
            assign beat[b] = sh[pair_of(b, 0)] ^ sh[pair_of(b, 1)];
        end
    endgenerate
    wire s_ready, m_valid;
    reg out_x;
    generate
        if (SETUP_ONLY == 0) begin : g_shader
            wire m_last;
            wire [15:0] m_data;
            wire [6:0] m_user;
            spec_shader #(
                .ITERATIVE(ITERATIVE), .BACKEND(BACKEND), .DELAY_RAM(DELAY_RAM), .TBL_AW(TBL_AW), .INTERP(INTERP),
                .INTERP_FRAC(INTERP_FRAC), .DELTA_W(DELTA_W), .SCALE_W(SCALE_W), .SCALE_FRAC(SCALE_FRAC),
                .ROM9_FILE(ROM9_FILE), .ROM12_FILE(ROM12_FILE), .EFU_FILE(EFU_FILE), .EXP2_FILE(EXP2_FILE),
                .UC_FILE(UC_FILE), .SMALL_LOG2_FILE(SMALL_LOG2_FILE), .SMALL_EXP2_FILE(SMALL_EXP2_FILE)
            ) u_shader (
                .clk(clk), .rst_n(rst_q), .s_axis_tvalid(s_valid), .s_axis_tready(s_ready), .s_axis_tdata(beat),
                .m_axis_tvalid(m_valid), .m_axis_tready(m_ready), .m_axis_tdata(m_data), .m_axis_tlast(m_last),
                .m_axis_tuser(m_user)
            );
            always @(posedge clk) out_x <= ^{m_data, m_last, m_user};
        end else begin : g_setup
            wire [`SPEC_DESC_W-1:0] m_data;
            wire [6:0] m_user;
            if (ITERATIVE == 0) begin : g_mul
                spec_setup #(.EFU_FILE(EFU_FILE), .EXP2_FILE(EXP2_FILE), .UC_FILE(UC_FILE)) u_setup (
                    .clk(clk), .rst_n(rst_q), .s_axis_tvalid(s_valid), .s_axis_tready(s_ready), .s_axis_tdata(beat),
                    .m_axis_tvalid(m_valid), .m_axis_tready(m_ready), .m_axis_tdata(m_data), .m_axis_tuser(m_user)
                );
            end else begin : g_small
                spec_setup_small #(.LOG2_FILE(SMALL_LOG2_FILE), .EXP2_FILE(SMALL_EXP2_FILE)) u_setup (
                    .clk(clk), .rst_n(rst_q), .s_axis_tvalid(s_valid), .s_axis_tready(s_ready), .s_axis_tdata(beat),
                    .m_axis_tvalid(m_valid), .m_axis_tready(m_ready), .m_axis_tdata(m_data), .m_axis_tuser(m_user)
                );
            end
            always @(posedge clk) out_x <= ^{m_data, m_user};
        end
    endgenerate
    always @(posedge clk) begin
        dout <= out_x;
        flag <= s_ready ^ m_valid;
    end
endmodule
`default_nettype wire
