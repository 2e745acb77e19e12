// spec_setup - the patent's "external device" (digest section 5) in hardware: a span's end vectors N1, N2, H1,
// H2, its exponent n, intervals l and strength Is*ks in, spec_stream's 128-bit descriptor out (C, n, l,
// zeta0 = -lambda, dzeta = gamma / l; eq. 2-5 and 12-16), with the host's degenerate-case flags on tuser.
// docs/setup.md: ports, formats, arithmetic, latency, accuracy; sim/setup/setup_model.h: the bit-exact model.
//
// Span ends (s_axis_tdata, 256 bits; reserved bits ignored):
//   [16*k +: 16], k = 0..11   N1 x, y, z, N2 x, y, z, H1 x, y, z, H2 x, y, z: two's complement Q1.14, any
//                             length, not zero
//   [207:192]                 Is*ks, UQ1.15          [217:208]  n, 0..1023
//   [239:224]                 l, 0..65535            [240]      gamma rule (1: midpoint; patent's otherwise)
// Descriptor (m_axis_tdata, 128 bits): [15:0] C UQ0.16, [25:16] n, [47:32] l, [95:64] zeta0, [127:96] dzeta
// (angles two's complement radians, 28 fraction bits); other bits 0. Flags (m_axis_tuser): 0 flat,
// 1 opposite normals, 2 C saturated, 3 single pixel, 4 no highlight, 5 gamma fallback, 6 invalid (zero vector).
//
// ITERATIVE = 0: the arithmetic fully pipelined (spec_setup_pipe): a new span every clock, its descriptor
//   LAT clocks later, in order, into a FIFO of 2^FIFO_AW + 2 places; s_axis_tready (a register) gives as many
//   credits, so the pipeline never stops and nothing is lost when the sink stalls.
// ITERATIVE = 1: one span at a time through shared units (spec_setup_engine); s_axis_tready is 1 while it
//   is idle. For the iCE40 UP5K.
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
    parameter EXP2_FILE = `SETUP_EXP2_FILE
) (
    input  wire         clk,
    input  wire         rst_n,
    input  wire         s_axis_tvalid,
    output wire         s_axis_tready,
    input  wire [255:0] s_axis_tdata,
    output wire         m_axis_tvalid,
    input  wire         m_axis_tready,
    output wire [127:0] m_axis_tdata,
    output wire [6:0]   m_axis_tuser
);
    wire rst = ~rst_n;
    localparam C_W = `SPEC_C_W, N_W = `SPEC_N_W, L_W = `SPEC_L_W, ANG_W = `SPEC_ANG_W;
    wire unused_in;
    assign unused_in = &{1'b0, s_axis_tdata[223:218], s_axis_tdata[255:241]};

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
                .clk(clk), .rst(rst), .in_valid(accept), .in_vec(s_axis_tdata[191:0]),
                .in_str(s_axis_tdata[207:192]), .in_n(s_axis_tdata[208 +: N_W]), .in_l(s_axis_tdata[224 +: L_W]),
                .in_rule(s_axis_tdata[240]), .out_valid(o_valid), .out_c(o_c), .out_n(o_n), .out_l(o_l),
                .out_zeta0(o_z0), .out_dzeta(o_dz), .out_flags(o_flags)
            );
            localparam DW = 7 + 2 * ANG_W + L_W + N_W + C_W;
            wire [DW-1:0] f_data;
            spec_setup_fifo #(.W(DW), .AW(FIFO_AW)) u_fifo (
                .clk(clk), .rst(rst), .push(o_valid), .push_data({o_flags, o_dz, o_z0, o_l, o_n, o_c}),
                .m_tvalid(m_axis_tvalid), .m_tready(m_axis_tready), .m_tdata(f_data)
            );
            wire [C_W-1:0] f_c;
            wire [N_W-1:0] f_n;
            wire [L_W-1:0] f_l;
            wire [ANG_W-1:0] f_z0, f_dz;
            assign {m_axis_tuser, f_dz, f_z0, f_l, f_n, f_c} = f_data;
            assign m_axis_tdata = {f_dz, f_z0, {(32 - L_W) {1'b0}}, f_l, {(16 - N_W) {1'b0}}, f_n,
                                   {(16 - C_W) {1'b0}}, f_c};
        end else begin : g_engine
            spec_setup_engine #(.LOG2_FILE(LOG2_FILE), .EXP2_FILE(EXP2_FILE)) u_engine (
                .clk(clk), .rst(rst), .s_tvalid(s_axis_tvalid), .s_tready(s_axis_tready), .s_tdata(s_axis_tdata[240:0]),
                .m_tvalid(m_axis_tvalid), .m_tready(m_axis_tready), .m_tdata(m_axis_tdata), .m_tuser(m_axis_tuser)
            );
        end
    endgenerate
endmodule
`default_nettype wire
