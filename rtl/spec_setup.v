// spec_setup - the patent's "external device" (digest section 5) in hardware: a span's end vectors N1, N2, H1,
// H2, its exponent n, intervals l and strength Is*ks in, spec_stream's 128-bit descriptor out (C, n, l,
// zeta0 = -lambda, dzeta = gamma / l; eq. 2-5 and 12-16), with the host's degenerate-case flags on tuser.
// docs/setup.md: ports, formats, arithmetic, latency, accuracy; sim/setup/setup_model.h: the bit-exact model.
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
// ITERATIVE = 0: the arithmetic fully pipelined (spec_setup_pipe): a new span every clock, its descriptor
//   LAT clocks later, in order, into a FIFO of 2^FIFO_AW + 2 places; s_axis_tready (a register) gives as many
//   credits, so the pipeline never stops and nothing is lost when the sink stalls.
// ITERATIVE = 1: one span at a time through shared units (spec_setup_engine, spec_setup_backend);
//   s_axis_tready is 1 while it is idle (the previous descriptor handed over). For the iCE40 UP5K.
// Both give the same descriptors and flags bit for bit. m_axis_tvalid, m_axis_tdata and m_axis_tuser are
// registers and hold until m_axis_tready. Reset: rst_n synchronous, active low; spans in flight are dropped,
// s_axis_tready is 0 in the cycle after a reset edge.
`timescale 1ns / 1ps
`default_nettype none
`include "setup_params.vh"
`include "spec_params.vh"
module spec_setup #(
    parameter ITERATIVE = 0,
    parameter FIFO_AW = 9,
    parameter LOG2_FILE = `SETUP_LOG2_FILE,
    parameter EXP2_FILE = `SETUP_EXP2_FILE,
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
    localparam VEC_W = `SETUP_VEC_W, STR_W = `SETUP_STR_W;

    // the span-ends beat's fields (rom/setup_params.vh); the bits between them are ignored
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

    generate
        if (ITERATIVE == 0) begin : g_pipe
            localparam [FIFO_AW+1:0] DEPTH = (1 << FIFO_AW) + 2;
            reg ready_q;
            reg [FIFO_AW+1:0] cnt;                     // spans accepted and not yet handed over
            wire accept = s_axis_tvalid & ready_q;
            wire handover = m_axis_tvalid & m_axis_tready;
            wire [FIFO_AW+1:0] cnt_n = cnt + {{(FIFO_AW + 1) {1'b0}}, accept} - {{(FIFO_AW + 1) {1'b0}}, handover};
            always @(posedge clk) begin
                if (rst) begin
                    cnt <= {(FIFO_AW + 2) {1'b0}};
                    ready_q <= 1'b0;
                end else begin
                    cnt <= cnt_n;
                    ready_q <= cnt_n < DEPTH;
                end
            end
            assign s_axis_tready = ready_q;

            wire o_valid;
            wire [C_W-1:0] o_c;
            wire [N_W-1:0] o_n;
            wire [L_W-1:0] o_l;
            wire [ANG_W-1:0] o_z0, o_dz;
            wire [6:0] o_flags;
            spec_setup_pipe #(.LOG2_FILE(LOG2_FILE), .EXP2_FILE(EXP2_FILE)) u_pipe (
                .clk(clk), .rst(rst), .in_valid(accept), .in_vec(in_vec), .in_str(in_str), .in_n(in_n), .in_l(in_l),
                .in_rule(in_rule), .out_valid(o_valid), .out_c(o_c), .out_n(o_n), .out_l(o_l), .out_zeta0(o_z0),
                .out_dzeta(o_dz), .out_flags(o_flags)
            );
            localparam DW = 7 + 2 * ANG_W + L_W + N_W + C_W;
            spec_setup_fifo #(.W(DW), .AW(FIFO_AW)) u_fifo (
                .clk(clk), .rst(rst), .push(o_valid), .push_data({o_flags, o_dz, o_z0, o_l, o_n, o_c}),
                .m_tvalid(m_axis_tvalid), .m_tready(m_axis_tready), .m_tdata({m_axis_tuser, d_dz, d_z0, d_l, d_n, d_c})
            );
        end else begin : g_engine
            spec_setup_engine #(.LOG2_FILE(LOG2_FILE), .EXP2_FILE(EXP2_FILE)) u_engine (
                .clk(clk), .rst(rst), .s_tvalid(s_axis_tvalid), .s_tready(s_axis_tready), .s_vec(in_vec),
                .s_str(in_str), .s_n(in_n), .s_l(in_l), .s_rule(in_rule), .m_tvalid(m_axis_tvalid),
                .m_tready(m_axis_tready), .m_c(d_c), .m_n(d_n), .m_l(d_l), .m_zeta0(d_z0), .m_dzeta(d_dz),
                .m_flags(m_axis_tuser)
            );
        end
    endgenerate
endmodule
`default_nettype wire
