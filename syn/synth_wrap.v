// synth_wrap - a place-and-route harness for spec_stream (and spec_unit, spec_stream_seq) on small packages.
// The iCE40 UP5K in SG48 has 39 I/O pins, far fewer than the core's ports, so the descriptor is shifted in
// serially and the pixel bus is XOR-reduced; every core port is registered on both sides, so the timing
// report measures the core's own register-to-register paths. Not a usable top level: only for area/Fmax.
`timescale 1ns / 1ps
`default_nettype none
`include "spec_params.vh"
module synth_wrap #(
    parameter UNIT = 0,   // 0: spec_stream, 1: spec_unit, 2: spec_stream_seq (the same ports as spec_stream)
    parameter LANES = 1,  // spec_stream's LANES and PACK
    parameter PACK = 0,
    parameter TBL_AW = `SPEC_TBL_AW,
    parameter INTERP = `SPEC_INTERP,
    parameter INTERP_FRAC = `SPEC_INTERP_FRAC,
    parameter DELTA_W = `SPEC_DELTA_W,
    parameter SCALE_W = `SPEC_SCALE_W,
    parameter SCALE_FRAC = `SPEC_SCALE_FRAC,
    parameter POW = `SPEC_POW,              // pow mode (docs/pow.md) and its log table's size
    parameter POW_IDX_W = `SPEC_POW_IDX_W,
    parameter ROM9_FILE = `SPEC_ROM9_FILE,
    parameter ROM12_FILE = `SPEC_ROM12_FILE
) (
    input  wire clk,
    input  wire rst_n,
    input  wire din,
    input  wire strobe,
    output reg  dout,
    output reg  flag
);
    reg [127:0] sh;
    reg strobe_q, rst_q;
    always @(posedge clk) begin
        sh <= {sh[126:0], din};
        strobe_q <= strobe;
        rst_q <= rst_n;
    end
    generate
        if (UNIT == 0 || UNIT == 2) begin : g_stream
            reg s_valid, m_ready;
            wire s_ready, m_valid, m_last;
            wire [LANES*16-1:0] m_data;
            wire [LANES-1:0] m_keep;
            always @(posedge clk) begin
                s_valid <= strobe_q;
                m_ready <= sh[127] | strobe_q;
            end
            if (UNIT == 0) begin : g_pipelined
                spec_stream #(
                    .TBL_AW(TBL_AW), .INTERP(INTERP), .INTERP_FRAC(INTERP_FRAC), .DELTA_W(DELTA_W),
                    .SCALE_W(SCALE_W), .SCALE_FRAC(SCALE_FRAC), .POW(POW), .POW_IDX_W(POW_IDX_W), .ROM9_FILE(ROM9_FILE),
                    .ROM12_FILE(ROM12_FILE),
                    .LANES(LANES), .PACK(PACK)
                ) u_core (
                    .clk(clk), .rst_n(rst_q), .s_axis_tvalid(s_valid), .s_axis_tready(s_ready),
                    .s_axis_tdata(sh), .m_axis_tvalid(m_valid), .m_axis_tready(m_ready),
                    .m_axis_tdata(m_data), .m_axis_tkeep(m_keep), .m_axis_tlast(m_last)
                );
            end else begin : g_seq
                spec_stream_seq #(
                    .TBL_AW(TBL_AW), .INTERP(INTERP), .INTERP_FRAC(INTERP_FRAC), .DELTA_W(DELTA_W),
                    .SCALE_W(SCALE_W), .SCALE_FRAC(SCALE_FRAC), .POW(POW), .POW_IDX_W(POW_IDX_W), .ROM9_FILE(ROM9_FILE),
                    .ROM12_FILE(ROM12_FILE)
                ) u_core (
                    .clk(clk), .rst_n(rst_q), .s_axis_tvalid(s_valid), .s_axis_tready(s_ready),
                    .s_axis_tdata(sh), .m_axis_tvalid(m_valid), .m_axis_tready(m_ready),
                    .m_axis_tdata(m_data), .m_axis_tkeep(m_keep), .m_axis_tlast(m_last)
                );
            end
            always @(posedge clk) begin
                dout <= ^{m_data, m_keep, m_last};
                flag <= s_ready ^ m_valid;
            end
        end else begin : g_unit
            reg [6:0] we;
            wire [15:0] out;
            wire busy, valid;
            always @(posedge clk) we <= {we[5:0], strobe_q};
            spec_unit #(
                .TBL_AW(TBL_AW), .INTERP(INTERP), .INTERP_FRAC(INTERP_FRAC), .DELTA_W(DELTA_W),
                .SCALE_W(SCALE_W), .SCALE_FRAC(SCALE_FRAC), .POW(POW), .POW_IDX_W(POW_IDX_W), .ROM9_FILE(ROM9_FILE),
                .ROM12_FILE(ROM12_FILE)
            ) u_core (
                .clk(clk), .init_n(rst_q), .start(we[6]), .c_i(sh[15:0]), .c_we(we[0]),
                .dzeta_i(sh[127:96]), .dzeta_we(we[1]), .zeta0_i(sh[95:64]), .zeta0_we(we[2]),
                .n_i(sh[25:16]), .n_we(we[3]), .len_i(sh[47:32]), .len_load_n(~we[4]),
                .intensity_o(out), .busy_o(busy), .valid_o(valid)
            );
            always @(posedge clk) begin
                dout <= ^out;
                flag <= busy ^ valid;
            end
        end
    endgenerate
endmodule
`default_nettype wire
