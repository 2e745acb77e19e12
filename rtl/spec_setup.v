// spec_setup - the patent's "external device" (digest section 5) in hardware: a span's end vectors N1, N2, H1,
// H2, its exponent n, intervals l and strength Is*ks in, spec_stream's 128-bit descriptor out (C, n, l,
// zeta0 = -lambda, dzeta = gamma / l; eq. 2-5 and 12-16), with the host's degenerate-case flags on tuser.
// docs/setup.md: ports, formats, arithmetic, schedule, accuracy; sim/setup/setup_model.h: the bit-exact model.
//
// Span ends (s_axis_tdata, 256 bits; field offsets in setup_params.vh, SETUP_BEAT_*; other bits ignored):
//   [16*k +: 16], k = 0..11   N1 x, y, z, N2 x, y, z, H1 x, y, z, H2 x, y, z: two's complement Q1.14, any
//                             length; a zero vector makes the span invalid
//   [207:192]                 Is*ks, UQ1.15          [217:208]  n, 0..1023
//   [239:224]                 l, 0..65535            [240]      gamma rule (1: midpoint; patent's otherwise)
// Descriptor (m_axis_tdata, spec_stream's: rom/spec_params.vh, SPEC_DESC_*): [15:0] C UQ0.16, [25:16] n,
// [47:32] l, [95:64] zeta0, [127:96] dzeta (angles two's complement radians, 28 fraction bits); other bits 0.
// Flags (m_axis_tuser): 0 flat, 1 opposite normals, 2 C saturated, 3 single pixel, 4 no highlight, 5 gamma
// fallback, 6 invalid (zero vector).
//
// The arithmetic runs on spec_setup_machine by the schedule setuprom made for the configuration whose
// setup_params.vh is on the include path (rom/: the ecp5 configuration's): a span starts every II
// clocks, several in flight, its descriptor LATENCY clocks later, in order, into a FIFO; s_axis_tready (a
// register) follows a one-beat holding register, and a span starts only with a credit for its place in the FIFO,
// so the machine never stalls and nothing is lost when the sink stalls. Sustained: one span every II clocks.
// m_axis_tvalid, m_axis_tdata and m_axis_tuser are registers and hold until m_axis_tready. Reset: rst_n
// synchronous, active low; spans in flight are dropped, s_axis_tready is 0 in the cycle after a reset edge.
`timescale 1ns / 1ps
`default_nettype none
`include "setup_params.vh"
`include "spec_params.vh"
module spec_setup #(
    parameter EFU_FILE = `SETUP_EFU_FILE,
    parameter EXP2_FILE = `SETUP_EXP2_FILE,
    parameter UC_FILE = `SETUP_UC_FILE,
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
    localparam VEC_W = `SETUP_VEC_W, STR_W = `SETUP_STR_W, SW = `SETUP_STAGE_W;
    localparam CW = VEC_W + 1;
    // spans in flight: LATENCY / II + 2; the FIFO holds 2^FIFO_AW + 2 (spec_setup_fifo) and that many credits
    localparam FLY = `SETUP_LATENCY / `SETUP_II + 3;
    localparam FIFO_AW = (FLY > 64) ? 7 : (FLY > 32) ? 6 : (FLY > 16) ? 5 : (FLY > 8) ? 4 : (FLY > 4) ? 3 : 2;
    localparam [FIFO_AW+1:0] DEPTH = (1 << FIFO_AW) + 2;

    // ---- the span-ends beat and the pre-stage: PN = N1 x e_k (e_k the axis of N1's smallest component, the
    // first of x, y, z: the host's perpendicular(N1)); a zero vector: invalid
    wire [12*VEC_W-1:0] iv;
    genvar k;
    generate
        for (k = 0; k < 12; k = k + 1) begin : g_vec
            assign iv[k*VEC_W +: VEC_W] = s_axis_tdata[`SETUP_BEAT_VEC_LSB + 16 * k +: VEC_W];
        end
    endgenerate
    function [CW-1:0] ext(input [VEC_W-1:0] v);
        ext = {v[VEC_W-1], v};
    endfunction
    function [CW-1:0] mag(input [VEC_W-1:0] v);
        mag = v[VEC_W-1] ? -{v[VEC_W-1], v} : {1'b0, v};
    endfunction
    wire [CW-1:0] nx = ext(iv[0 +: VEC_W]), ny = ext(iv[VEC_W +: VEC_W]), nz = ext(iv[2*VEC_W +: VEC_W]);
    wire [CW-1:0] ax = mag(iv[0 +: VEC_W]), ay = mag(iv[VEC_W +: VEC_W]), az = mag(iv[2*VEC_W +: VEC_W]);
    localparam [CW-1:0] Z = 0;
    wire [3*CW-1:0] pn = (ax <= ay && ax <= az) ? {-ny, nz, Z} : (ay <= az ? {nx, Z, -nz} : {Z, -nx, ny});
    wire [15*CW-1:0] vec;
    generate
        for (k = 0; k < 12; k = k + 1) begin : g_ext
            assign vec[k*CW +: CW] = ext(iv[k*VEC_W +: VEC_W]);
        end
    endgenerate
    assign vec[12*CW +: 3*CW] = pn;
    wire inv = ~|iv[0 +: 3*VEC_W] | ~|iv[3*VEC_W +: 3*VEC_W] | ~|iv[6*VEC_W +: 3*VEC_W] | ~|iv[9*VEC_W +: 3*VEC_W];

    // ---- the holding register, credits, span starts
    reg held, ready_q;
    reg [15*CW-1:0] h_vec;
    reg h_rule, h_inv;
    reg [STR_W-1:0] h_str;
    reg [N_W-1:0] h_n;
    reg [L_W-1:0] h_l;
    reg [FIFO_AW+1:0] credit;
    wire tau0;
    wire [SW-1:0] span;
    wire take = s_axis_tvalid & ready_q;
    wire start = tau0 & held & (credit != {(FIFO_AW + 2) {1'b0}});
    wire handover = m_axis_tvalid & m_axis_tready;
    always @(posedge clk) begin
        if (take) begin
            h_vec <= vec;
            h_rule <= s_axis_tdata[`SETUP_BEAT_RULE_BIT];
            h_inv <= inv;
            h_str <= s_axis_tdata[`SETUP_BEAT_STR_LSB +: STR_W];
            h_n <= s_axis_tdata[`SETUP_BEAT_N_LSB +: N_W];
            h_l <= s_axis_tdata[`SETUP_BEAT_L_LSB +: L_W];
        end
        if (rst) begin
            held <= 1'b0;
            ready_q <= 1'b0;
            credit <= DEPTH;
        end else begin
            held <= take | (held & ~start);
            ready_q <= ~(take | (held & ~start));
            credit <= credit - {{(FIFO_AW + 1) {1'b0}}, start} + {{(FIFO_AW + 1) {1'b0}}, handover};
        end
    end
    assign s_axis_tready = ready_q;
    wire unused_in;
    assign unused_in = &{1'b0, s_axis_tdata};

    // ---- the machine and the finish
    wire fin_en;
    wire [3:0] fin_field;
    wire [SW-1:0] fin_span;
    wire [`SETUP_W-1:0] fin_data;
    spec_setup_machine #(.EFU_FILE(EFU_FILE), .UC_FILE(UC_FILE), .N_W(N_W), .L_W(L_W)) u_mach (
        .clk(clk), .rst(rst), .tau0(tau0), .span(span), .beat_vec(h_vec), .beat_rule(h_rule), .beat_strength(h_str),
        .beat_n(h_n), .beat_l(h_l), .fin_en(fin_en), .fin_field(fin_field), .fin_span(fin_span), .fin_data(fin_data)
    );
    wire d_valid;
    wire [C_W-1:0] d_c;
    wire [N_W-1:0] d_n;
    wire [L_W-1:0] d_l;
    wire [ANG_W-1:0] d_z0, d_dz;
    wire [6:0] d_flags;
    spec_setup_finish #(.EXP2_FILE(EXP2_FILE)) u_fin (
        .clk(clk), .rst(rst), .side_we(tau0), .side_span(span), .side_valid(start), .side_invalid(h_inv),
        .side_rule(h_rule), .side_n(h_n), .side_l(h_l), .fin_en(fin_en), .fin_field(fin_field), .fin_span(fin_span),
        .fin_data(fin_data), .d_valid(d_valid), .d_c(d_c), .d_n(d_n), .d_l(d_l), .d_zeta0(d_z0), .d_dzeta(d_dz),
        .d_flags(d_flags)
    );

    // ---- the descriptor FIFO
    localparam DW = 7 + 2 * ANG_W + L_W + N_W + C_W;
    wire [C_W-1:0] o_c;
    wire [N_W-1:0] o_n;
    wire [L_W-1:0] o_l;
    wire [ANG_W-1:0] o_z0, o_dz;
    spec_setup_fifo #(.W(DW), .AW(FIFO_AW)) u_fifo (
        .clk(clk), .rst(rst), .push(d_valid), .push_data({d_flags, d_dz, d_z0, d_l, d_n, d_c}),
        .m_tvalid(m_axis_tvalid), .m_tready(m_axis_tready), .m_tdata({m_axis_tuser, o_dz, o_z0, o_l, o_n, o_c})
    );
    assign m_axis_tdata = ({{(DESC_W - C_W) {1'b0}}, o_c} << `SPEC_DESC_C_LSB) |
                          ({{(DESC_W - N_W) {1'b0}}, o_n} << `SPEC_DESC_N_LSB) |
                          ({{(DESC_W - L_W) {1'b0}}, o_l} << `SPEC_DESC_L_LSB) |
                          ({{(DESC_W - ANG_W) {1'b0}}, o_z0} << `SPEC_DESC_ZETA0_LSB) |
                          ({{(DESC_W - ANG_W) {1'b0}}, o_dz} << `SPEC_DESC_DZETA_LSB);
endmodule
`default_nettype wire
