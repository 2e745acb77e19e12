// board_shader - one shader pass of a sub-span through spec_shader (spec_setup -> spec_stream, issue 13,
// docs/setup.md): the sub-span's end normals as sphere_spans gives them ((dx, dy, z) * 2^5 in half-pixel units:
// spec_setup needs only their directions), one light vector for both ends (H or L, Q1.14), the exponent, the
// strength (UQ1.15), the length; the span's pixels out (AXI4-Stream, tlast on the last). The gamma rule is the
// midpoint one: exact for a constant light vector along a slerp of the normal (docs/host.md), which is this
// case. spec_stream runs its up5k configuration (interpolated 4 x 256 tables) on both boards.
// SMALL = 1: spec_setup_small, the small CORDIC setup (one span at a time; the up5k configuration's, the
// frame-buffer designs'); 0: spec_setup, the multiplier setup (a span every II clocks; the ecp5 configuration's,
// the racing design's). BACKEND: spec_shader's back end, 0 = spec_stream, 1 = spec_stream_seq (one span at a
// time, few flip-flops). SETUP_DIR: the directory of the setups' tables and microcode (rom/).
`timescale 1ns / 1ps
`default_nettype none
`include "setup_params.vh"
module board_shader #(
    parameter SMALL = 1,
    parameter BACKEND = 0,
    parameter ROM9_FILE = "",
    parameter ROM12_FILE = "",
    parameter SETUP_DIR = "rom"
) (
    input  wire        clk,
    input  wire        rst_n,
    input  wire        s_valid,
    output wire        s_ready,
    input  wire [47:0] s_n1,       // {z, y, x}
    input  wire [47:0] s_n2,
    input  wire [47:0] s_light,
    input  wire [9:0]  s_n,
    input  wire [15:0] s_strength,
    input  wire [9:0]  s_l,
    output wire        m_valid,
    input  wire        m_ready,
    output wire [15:0] m_data,
    output wire        m_last
);
    localparam BEAT_W = `SETUP_BEAT_W;
    // the span-ends beat (docs/setup.md): N1, N2, H1, H2 (x, y, z each), strength, n, l, gamma rule
    reg [BEAT_W-1:0] beat;
    always @(*) begin
        beat = {BEAT_W{1'b0}};
        beat[`SETUP_BEAT_VEC_LSB +: 48] = s_n1;
        beat[`SETUP_BEAT_VEC_LSB + 48 +: 48] = s_n2;
        beat[`SETUP_BEAT_VEC_LSB + 96 +: 48] = s_light;
        beat[`SETUP_BEAT_VEC_LSB + 144 +: 48] = s_light;
        beat[`SETUP_BEAT_STR_LSB +: 16] = s_strength;
        beat[`SETUP_BEAT_N_LSB +: 10] = s_n;
        beat[`SETUP_BEAT_L_LSB +: 16] = {6'd0, s_l};
        beat[`SETUP_BEAT_RULE_BIT] = 1'b1;
    end
    wire [6:0] flags_unused;
    spec_shader #(
        .ITERATIVE(SMALL), .BACKEND(BACKEND), .EFU_FILE({SETUP_DIR, "/setup_efu.hex"}),
        .EXP2_FILE({SETUP_DIR, "/setup_exp2.hex"}), .UC_FILE({SETUP_DIR, "/setup_ucode.hex"}),
        .SMALL_LOG2_FILE({SETUP_DIR, "/setup_small_log2.hex"}), .SMALL_EXP2_FILE({SETUP_DIR, "/setup_small_exp2.hex"}),
        .TBL_AW(8), .INTERP(1), .INTERP_FRAC(10), .DELTA_W(10), .SCALE_W(16), .SCALE_FRAC(13),
        .ROM9_FILE(ROM9_FILE), .ROM12_FILE(ROM12_FILE)
    ) u_shader (
        .clk(clk), .rst_n(rst_n), .s_axis_tvalid(s_valid), .s_axis_tready(s_ready), .s_axis_tdata(beat),
        .m_axis_tvalid(m_valid), .m_axis_tready(m_ready), .m_axis_tdata(m_data), .m_axis_tlast(m_last),
        .m_axis_tuser(flags_unused)
    );
    wire unused;
    assign unused = &{1'b0, flags_unused};
endmodule
`default_nettype wire
