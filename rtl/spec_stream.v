// spec_stream - the UA 71489 datapath as a streaming core: one pixel per clock, span descriptors in through
// an AXI4-Stream sink, pixels out through an AXI4-Stream source. Same datapath modules as spec_unit
// (ROM 9, decoder 10, adder 6 / register 8, multiplier 11, ROM 12, multiplier 13), same pixels bit for bit.
//
// Descriptor (s_axis_tdata, DESC_W = 128 bits; unused bits are ignored):
//   [C_W-1:0]            C       UQ0.C_W                     (register 1)
//   [16 +: N_W]          n       0 .. 2^N_W - 1              (register 4)
//   [32 +: L_W]          l       intervals, l + 1 pixels     (counter 5)
//   [64 +: ANG_W]        zeta0   start angle, two's complement, ANG_FRAC fraction bits (register 3)
//   [96 +: ANG_W]        dzeta   angle step, same format     (register 2)
// Pixels (m_axis_tdata, OUT_W bits): intensity UQ0.OUT_W; m_axis_tlast = 1 on a span's last pixel.
//
// Throughput: one pixel per clock while m_axis_tready = 1 and descriptors arrive in time, also across
// span boundaries: the next descriptor waits in a one-entry buffer (and has its ROM 9 word read) while the
// current span runs. Latency: a descriptor accepted in cycle a (core idle) gives its first pixel in cycle
// a + 2 + LAT, LAT = 4 (5 with INTERP = 1). Backpressure: every pipeline stage advances only when the output
// register is empty or being read (ce = !m_axis_tvalid | m_axis_tready); m_axis_tvalid and m_axis_tdata
// hold until accepted. s_axis_tready = 1 when the descriptor buffer is empty or moving into the span
// generator in this cycle (it depends combinationally on m_axis_tready).
// Reset: rst_n is synchronous, active low. At an edge where it is 0 the buffer, the span generator and the
// pipeline's valid flags are cleared: from the next cycle s_axis_tready = 1, m_axis_tvalid = 0, and no pixel
// of a span in progress appears later. s_axis_tready is 0 while rst_n is 0.
`timescale 1ns / 1ps
`default_nettype none
`include "spec_params.vh"
module spec_stream #(
    parameter C_W = `SPEC_C_W,
    parameter ANG_W = `SPEC_ANG_W,
    parameter ANG_FRAC = `SPEC_ANG_FRAC,
    parameter N_W = `SPEC_N_W,
    parameter L_W = `SPEC_L_W,
    parameter OUT_W = `SPEC_OUT_W,
    parameter SCALE_W = `SPEC_SCALE_W,
    parameter SCALE_FRAC = `SPEC_SCALE_FRAC,
    parameter TBL_AW = `SPEC_TBL_AW,
    parameter TBL_FRAC = `SPEC_TBL_FRAC,
    parameter INTERP = `SPEC_INTERP,
    parameter INTERP_FRAC = `SPEC_INTERP_FRAC,
    parameter DELTA_W = `SPEC_DELTA_W,
    parameter ROM9_FILE = `SPEC_ROM9_FILE,
    parameter ROM12_FILE = `SPEC_ROM12_FILE,
    parameter DESC_W = 128
) (
    input  wire              clk,
    input  wire              rst_n,
    input  wire              s_axis_tvalid,
    output wire              s_axis_tready,
    input  wire [DESC_W-1:0] s_axis_tdata,
    output wire              m_axis_tvalid,
    input  wire              m_axis_tready,
    output wire [OUT_W-1:0]  m_axis_tdata,
    output wire              m_axis_tlast
);
    wire rst = ~rst_n;

    // descriptor fields
    wire [C_W-1:0] d_c = s_axis_tdata[C_W-1:0];
    wire [N_W-1:0] d_n = s_axis_tdata[16 +: N_W];
    wire [L_W-1:0] d_l = s_axis_tdata[32 +: L_W];
    wire [ANG_W-1:0] d_zeta0 = s_axis_tdata[64 +: ANG_W];
    wire [ANG_W-1:0] d_dzeta = s_axis_tdata[96 +: ANG_W];
    wire unused_desc;   // the reserved bits between the fields
    assign unused_desc = &{1'b0, s_axis_tdata};

    wire ce;             // the pipeline advances
    wire out_valid;

    // ---- descriptor buffer ("registers 1-4 and counter 5" of the next span) -------------------------------
    reg pend_v;
    reg [C_W-1:0] pend_c;
    reg [N_W-1:0] pend_n;
    reg [L_W-1:0] pend_l;
    reg [ANG_W-1:0] pend_zeta0, pend_dzeta;
    wire take;           // the span generator takes the buffered descriptor in this cycle
    assign s_axis_tready = rst_n & (~pend_v | take);
    wire accept = s_axis_tvalid & s_axis_tready;
    always @(posedge clk) begin
        if (rst) pend_v <= 1'b0;
        else if (accept) pend_v <= 1'b1;
        else if (take) pend_v <= 1'b0;
        if (accept) begin
            pend_c <= d_c;
            pend_n <= d_n;
            pend_l <= d_l;
            pend_zeta0 <= d_zeta0;
            pend_dzeta <= d_dzeta;
        end
    end

    // ROM 9, read as the descriptor is accepted: its word waits beside the buffer
    wire [SCALE_W-1:0] pend_scale;
    spec_rom #(.AW(N_W), .DW(SCALE_W), .INIT_FILE(ROM9_FILE)) u_rom9 (
        .clk(clk), .en(accept), .addr(d_n), .data(pend_scale)
    );
    // decoder 10 on the buffered n
    wire [1:0] pend_tsel;
    wire d30_unused, d31_unused, d32_unused, d33_unused;
    spec_decoder #(.N_W(N_W)) u_dec10 (
        .n(pend_n), .d30(d30_unused), .d31(d31_unused), .d32(d32_unused), .d33(d33_unused),
        .table_sel(pend_tsel)
    );

    // ---- span generator: register 8 with adder 6 / multiplexer 7, the counter, the span's C and scale ----
    reg cur_v;
    reg [L_W-1:0] cur_cnt;        // intervals left after the pixel in register 8
    reg [C_W-1:0] cur_c;
    reg [SCALE_W-1:0] cur_scale;
    reg [1:0] cur_tsel;
    reg [ANG_W-1:0] cur_dzeta;
    wire cur_last = (cur_cnt == {L_W{1'b0}});
    wire cur_done = ~cur_v | cur_last;     // register 8's pixel is the span's last (or there is none)
    assign take = ce & cur_done & pend_v;
    wire step = ce & cur_v & ~cur_last;

    wire [ANG_W-1:0] angle8;
    spec_accum #(.W(ANG_W)) u_acc678 (
        .clk(clk), .rst(rst), .we(take | step), .sel(~take), .start(pend_zeta0), .step(cur_dzeta),
        .angle(angle8)
    );
    always @(posedge clk) begin
        if (rst) cur_v <= 1'b0;
        else if (ce & cur_done) cur_v <= pend_v;
        if (take) begin
            cur_cnt <= pend_l;
            cur_c <= pend_c;
            cur_scale <= pend_scale;
            cur_tsel <= pend_tsel;
            cur_dzeta <= pend_dzeta;
        end else if (step) begin
            cur_cnt <= cur_cnt - {{(L_W - 1) {1'b0}}, 1'b1};
        end
    end

    // ---- datapath: multiplier 11, ROM 12, [interpolator], multiplier 13 -------------------------------------
    wire dp_busy_unused;
    spec_datapath #(
        .C_W(C_W), .ANG_W(ANG_W), .ANG_FRAC(ANG_FRAC), .OUT_W(OUT_W), .SCALE_W(SCALE_W),
        .SCALE_FRAC(SCALE_FRAC), .TBL_AW(TBL_AW), .TBL_FRAC(TBL_FRAC), .INTERP(INTERP),
        .INTERP_FRAC(INTERP_FRAC), .DELTA_W(DELTA_W), .ROM12_FILE(ROM12_FILE)
    ) u_dp (
        .clk(clk), .rst(rst), .ce(ce), .in_valid(cur_v), .in_last(cur_last), .angle(angle8),
        .scale(cur_scale), .table_sel(cur_tsel), .c(cur_c), .out(m_axis_tdata), .out_valid(out_valid),
        .out_last(m_axis_tlast), .busy(dp_busy_unused)
    );
    assign ce = ~out_valid | m_axis_tready;
    assign m_axis_tvalid = out_valid;
endmodule
`default_nettype wire
