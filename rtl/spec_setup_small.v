// spec_setup_small - the small CORDIC setup of the up5k configuration: spec_setup's ports and beat (a span's end
// vectors N1, N2, H1, H2, its exponent n, intervals l and strength Is*ks in, spec_stream's 128-bit descriptor out,
// the host's degenerate-case flags on tuser), one span at a time through shared units (spec_setup_engine,
// spec_setup_backend), a few thousand clocks a span. Kept because the multiplier setup (spec_setup) does not fit
// the iCE40 UP5K, nor beside the ULX3S's frame buffer (docs/setup.md, "The small CORDIC setup", the rows that
// show it). The gamma rule is always the patent's: a span that asks for the midpoint rule gets flag 5.
// docs/setup.md: ports, formats, arithmetic, latency, accuracy; sim/setup/setup_small_model.h: the bit-exact model.
//
// Span ends (s_axis_tdata, 256 bits; field offsets in rom/setup_params.vh, SETUP_BEAT_*; other bits ignored):
//   [16*k +: 16], k = 0..11   N1 x, y, z, N2 x, y, z, H1 x, y, z, H2 x, y, z: two's complement Q1.14, any
//                             length, not zero
//   [207:192]                 Is*ks, UQ1.15          [217:208]  n, 0..1023
//   [239:224]                 l, 0..65535            [240]      gamma rule (1: midpoint; patent's otherwise)
// Descriptor (m_axis_tdata, spec_stream's: rom/spec_params.vh, SPEC_DESC_*): [15:0] C UQ0.16, [25:16] n,
// [47:32] l, [95:64] zeta0, [127:96] dzeta (angles two's complement radians, 28 fraction bits); other bits 0. Flags (m_axis_tuser): 0 flat,
// 1 opposite normals, 2 C saturated, 3 single pixel, 4 no highlight, 5 gamma fallback, 6 invalid (zero vector).
//
// s_axis_tready is 1 while the setup is idle (the previous descriptor handed over). m_axis_tvalid,
// m_axis_tdata and m_axis_tuser are registers and hold until m_axis_tready. Reset: rst_n synchronous, active low;
// a span in flight is dropped, s_axis_tready is 0 in the cycle after a reset edge.
`timescale 1ns / 1ps
`default_nettype none
`include "setup_params.vh"
`include "setup_small_params.vh"
`include "spec_params.vh"
module spec_setup_small #(
    parameter LOG2_FILE = `SMALL_LOG2_FILE,
    parameter EXP2_FILE = `SMALL_EXP2_FILE,
    parameter BEAT_W = `SETUP_BEAT_W,
    parameter DESC_W = `SPEC_DESC_W
) (
    input  wire              clk,
    input  wire              rst_n,
    input  wire              s_axis_tvalid,
    output wire              s_axis_tready,
    input  wire [BEAT_W-1:0] s_axis_tdata,
    output wire              m_axis_tvalid,
    input  wire              m_axis_tready,
    output wire [DESC_W-1:0] m_axis_tdata,
    output wire [6:0]        m_axis_tuser
);
    wire rst = ~rst_n;
    localparam C_W = `SPEC_C_W, N_W = `SPEC_N_W, L_W = `SPEC_L_W, ANG_W = `SPEC_ANG_W;
    localparam VEC_W = `SMALL_VEC_W, STR_W = `SMALL_STR_W;

    // the span-ends beat's fields (spec_setup's: setup_params.vh, SETUP_BEAT_*); the bits between them are ignored
    wire [12*VEC_W-1:0] in_vec;
    genvar k;
    generate
        for (k = 0; k < 12; k = k + 1) begin : g_vec
            assign in_vec[k*VEC_W +: VEC_W] = s_axis_tdata[`SETUP_BEAT_VEC_LSB + 16 * k +: VEC_W];
        end
    endgenerate
    wire [STR_W-1:0] in_str = s_axis_tdata[`SETUP_BEAT_STR_LSB +: STR_W];
    wire [N_W-1:0] in_n = s_axis_tdata[`SETUP_BEAT_N_LSB +: N_W];
    wire [L_W-1:0] in_l = s_axis_tdata[`SETUP_BEAT_L_LSB +: L_W];
    wire in_rule = s_axis_tdata[`SETUP_BEAT_RULE_BIT];
    wire unused_in;
    assign unused_in = &{1'b0, s_axis_tdata};

    // the descriptor (rom/spec_params.vh: spec_stream's field offsets); the bits between the fields are 0
    wire [C_W-1:0] d_c;
    wire [N_W-1:0] d_n;
    wire [L_W-1:0] d_l;
    wire [ANG_W-1:0] d_z0, d_dz;
    assign m_axis_tdata = ({{(DESC_W - C_W) {1'b0}}, d_c} << `SPEC_DESC_C_LSB) |
                          ({{(DESC_W - N_W) {1'b0}}, d_n} << `SPEC_DESC_N_LSB) |
                          ({{(DESC_W - L_W) {1'b0}}, d_l} << `SPEC_DESC_L_LSB) |
                          ({{(DESC_W - ANG_W) {1'b0}}, d_z0} << `SPEC_DESC_ZETA0_LSB) |
                          ({{(DESC_W - ANG_W) {1'b0}}, d_dz} << `SPEC_DESC_DZETA_LSB);

    spec_setup_engine #(.LOG2_FILE(LOG2_FILE), .EXP2_FILE(EXP2_FILE)) u_engine (
        .clk(clk), .rst(rst), .s_tvalid(s_axis_tvalid), .s_tready(s_axis_tready), .s_vec(in_vec),
        .s_str(in_str), .s_n(in_n), .s_l(in_l), .s_rule(in_rule), .m_tvalid(m_axis_tvalid),
        .m_tready(m_axis_tready), .m_c(d_c), .m_n(d_n), .m_l(d_l), .m_zeta0(d_z0), .m_dzeta(d_dz),
        .m_flags(m_axis_tuser)
    );
endmodule
`default_nettype wire
