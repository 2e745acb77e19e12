// spec_stream_seq - the compact streaming back end: spec_stream's ports, descriptor and AXI4-Stream rules with
// LANES = 1, and the same pixels bit for bit, but one span at a time. For a front end that delivers spans
// slowly (spec_shader's small setup: thousands of clocks a span) it needs a fraction of spec_stream's
// flip-flops: the span's C, ROM 9's scale and the table stay in registers for the whole span, the angle is one
// saturating accumulator (adder 6 / register 8, spec_accum, as spec_unit's), and spec_datapath runs with
// PIPE = 0, its own valid pipeline (CTRL = 1) and no delay lines beside it (SIDE = 0).
//
// Descriptor (s_axis_tdata, DESC_W bits; spec_stream's layout, rom/spec_params.vh; bits outside the fields are
// ignored): C [DESC_C_LSB +: C_W], n [DESC_N_LSB +: N_W], l [DESC_L_LSB +: L_W] (l + 1 pixels),
// zeta0 [DESC_ZETA0_LSB +: ANG_W], dzeta [DESC_DZETA_LSB +: ANG_W]; fields outside DESC_W or overlapping stop
// elaboration (spec_desc_check), as do the datapath's parameter rules (spec_param_check).
// Pixels: m_axis_tdata = the intensity (UQ0.OUT_W), m_axis_tkeep = 1, m_axis_tlast = 1 on a span's last pixel.
// POW = 1 (pow mode, docs/pow.md): the datapath is spec_powpath and the span's n waits in a register where ROM 9's
// word does otherwise.
// Angles: pixel k of a span has register 8 = zeta0 + k * dzeta, saturated step by step at the format's ends
// (spec_accum), as spec_unit and the model (Model::angles); spec_stream's clamp of the exact sum gives the same
// values (spec_saccum), so the pixels are spec_stream's.
//
// Timing: a descriptor accepted in cycle a gives its first pixel (m_axis_tvalid) in cycle a + LAT + 2 (LAT =
// spec_datapath's latency with PIPE = 0: 12, 14 with INTERP = 1; POW = 1: spec_powpath's, 23, 24 with INTERP = 1;
// Format::stream_seq_latency()): the span
// registers and ROM 9 (1), the datapath (LAT), the output register (1). Throughput: one pixel per clock
// within a span while m_axis_tready = 1; a descriptor is taken only when the previous span's last pixel has
// left the datapath (C and the table it reads are the next span's from then on), so spans start at most every
// l + 1 + LAT + 2 clocks (Format::stream_seq_gap() clocks without pixels between two spans).
// Backpressure: the pipeline advances only when the output register's skid buffer is empty, a register
// (spec_stream_out: no combinational path from m_axis_tready); m_axis_tvalid, tdata, tkeep, tlast and
// s_axis_tready are registers; the outputs hold until accepted.
// Reset: rst_n is synchronous, active low. At an edge where it is 0 the span in progress, the datapath's valid
// flags and the output registers are cleared: m_axis_tvalid = 0 (tdata, tkeep, tlast = 0) from the next cycle
// and no pixel of that span appears later; s_axis_tready is 0 in the cycle after a reset edge and 1 from the
// one after. A descriptor handed over in a cycle with rst_n = 0 is dropped.
`timescale 1ns / 1ps
`default_nettype none
`include "spec_params.vh"
module spec_stream_seq #(
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
    parameter DECODER_ROM = `SPEC_DECODER_ROM,  // 1: ROM 9's word carries the table (tuned mode); 0: Fig. 10 gates
    parameter TSEL_W = `SPEC_TSEL_W,            // ROM 12 table index width (2 with DECODER_ROM = 0)
    parameter POW = `SPEC_POW,                  // 1: pow mode (ROM 9 the log table, spec_powpath; docs/pow.md)
    parameter POW_SEG_W = `SPEC_POW_SEG_W,
    parameter POW_IDX_W = `SPEC_POW_IDX_W,
    parameter POW_FRAC = `SPEC_POW_FRAC,
    parameter POW_VAL_W = `SPEC_POW_VAL_W,
    parameter POW_DLT_W = `SPEC_POW_DLT_W,
    parameter POW_SH_W = `SPEC_POW_SH_W,
    parameter POW_XB = `SPEC_POW_XB,
    parameter POW_YF = `SPEC_POW_YF,
    parameter POW_YI = `SPEC_POW_YI,
    parameter POW_K = `SPEC_POW_K,
    parameter ROM9_FILE = `SPEC_ROM9_FILE,
    parameter ROM12_FILE = `SPEC_ROM12_FILE,
    parameter DESC_W = `SPEC_DESC_W,
    parameter DESC_C_LSB = `SPEC_DESC_C_LSB,
    parameter DESC_N_LSB = `SPEC_DESC_N_LSB,
    parameter DESC_L_LSB = `SPEC_DESC_L_LSB,
    parameter DESC_ZETA0_LSB = `SPEC_DESC_ZETA0_LSB,
    parameter DESC_DZETA_LSB = `SPEC_DESC_DZETA_LSB
) (
    input  wire              clk,
    input  wire              rst_n,
    input  wire              s_axis_tvalid,
    output wire              s_axis_tready,
    input  wire [DESC_W-1:0] s_axis_tdata,
    output wire              m_axis_tvalid,
    input  wire              m_axis_tready,
    output wire [OUT_W-1:0]  m_axis_tdata,
    output wire              m_axis_tkeep,
    output wire              m_axis_tlast
);
    wire rst = ~rst_n;

    spec_param_check #(
        .C_W(C_W), .ANG_W(ANG_W), .ANG_FRAC(ANG_FRAC), .N_W(N_W), .L_W(L_W), .OUT_W(OUT_W), .SCALE_W(SCALE_W),
        .SCALE_FRAC(SCALE_FRAC), .TBL_AW(TBL_AW), .TBL_FRAC(TBL_FRAC), .INTERP(INTERP), .INTERP_FRAC(INTERP_FRAC),
        .DELTA_W(DELTA_W), .DECODER_ROM(DECODER_ROM), .TSEL_W(TSEL_W), .POW(POW), .POW_SEG_W(POW_SEG_W),
        .POW_IDX_W(POW_IDX_W), .POW_FRAC(POW_FRAC), .POW_VAL_W(POW_VAL_W), .POW_DLT_W(POW_DLT_W), .POW_SH_W(POW_SH_W),
        .POW_XB(POW_XB), .POW_YF(POW_YF), .POW_YI(POW_YI), .POW_K(POW_K)
    ) u_check ();
    spec_desc_check #(
        .C_W(C_W), .N_W(N_W), .L_W(L_W), .ANG_W(ANG_W), .DESC_W(DESC_W), .DESC_C_LSB(DESC_C_LSB),
        .DESC_N_LSB(DESC_N_LSB), .DESC_L_LSB(DESC_L_LSB), .DESC_ZETA0_LSB(DESC_ZETA0_LSB),
        .DESC_DZETA_LSB(DESC_DZETA_LSB)
    ) u_desc_check ();

    wire ce;             // the pipeline advances (spec_stream_out)

    // ---- the descriptor: registers 1, 2, 4 (as ROM 9's word and decoder 10's table), counter 5 ----------------
    wire [C_W-1:0] d_c = s_axis_tdata[DESC_C_LSB +: C_W];
    wire [N_W-1:0] d_n = s_axis_tdata[DESC_N_LSB +: N_W];
    wire [L_W-1:0] d_l = s_axis_tdata[DESC_L_LSB +: L_W];
    wire [ANG_W-1:0] d_zeta0 = s_axis_tdata[DESC_ZETA0_LSB +: ANG_W];
    wire [ANG_W-1:0] d_dzeta = s_axis_tdata[DESC_DZETA_LSB +: ANG_W];
    wire unused_desc;   // the reserved bits between the fields
    assign unused_desc = &{1'b0, s_axis_tdata};
    reg ready_q;
    assign s_axis_tready = ready_q;
    wire accept = s_axis_tvalid & ready_q;
    wire [1:0] d_gate_tsel;
    wire [3:0] d_lines_unused;   // decoder 10's one-hot lines 30 .. 33
    spec_decoder #(.N_W(N_W)) u_dec10 (
        .n(d_n), .d30(d_lines_unused[0]), .d31(d_lines_unused[1]), .d32(d_lines_unused[2]),
        .d33(d_lines_unused[3]), .table_sel(d_gate_tsel)
    );
    reg [C_W-1:0] c_q;
    reg [ANG_W-1:0] dzeta_q;
    reg [1:0] gate_tsel_q;
    reg [L_W-1:0] cnt;   // pixels left after the presented one
    reg run;             // a pixel of the span is presented to the datapath
    wire last = (cnt == {L_W{1'b0}});
    wire take = run & ce;                 // the datapath takes the presented pixel
    always @(posedge clk) begin
        if (accept) begin
            c_q <= d_c;
            dzeta_q <= d_dzeta;
            gate_tsel_q <= d_gate_tsel;
        end
        if (accept) cnt <= d_l;
        else if (take) cnt <= cnt - {{(L_W - 1) {1'b0}}, 1'b1};
    end
    wire dp_busy;
    always @(posedge clk) begin
        if (rst) begin
            run <= 1'b0;
            ready_q <= 1'b0;
        end else begin
            run <= accept | (run & ~(ce & last));
            // a register: 1 when, a cycle ago, no span ran, the datapath was empty and nothing was taken, so
            // that nothing is in flight now
            ready_q <= ~accept & ~run & ~dp_busy;
        end
    end
    // ---- adder 6 / register 8: zeta0 as the descriptor is accepted, + dzeta (saturating) per pixel taken -------
    wire [ANG_W-1:0] angle8;
    spec_accum #(.W(ANG_W)) u_acc678 (
        .clk(clk), .rst(1'b0), .we(accept | (take & ~last)), .sel(~accept), .start(d_zeta0), .step(dzeta_q),
        .angle(angle8)
    );

    // ---- ROM 9, read as the descriptor is accepted: its word is the span's scale (and, DECODER_ROM = 1, its
    // table). POW = 1: n in a register loaded then (ROM 9 is the log table, read per pixel in the datapath).
    wire [SCALE_W-1:0] scale9;
    wire [TSEL_W-1:0] table_sel;
    wire [N_W-1:0] n_dp;
    generate
        if (POW != 0) begin : g_pow
            reg [N_W-1:0] n_q;
            always @(posedge clk) if (accept) n_q <= d_n;
            assign n_dp = n_q;
            assign scale9 = {SCALE_W{1'b0}};
            assign table_sel = {TSEL_W{1'b0}};
            wire unused_gates;
            assign unused_gates = &{1'b0, gate_tsel_q};
        end else begin : g_rom9
            wire [TSEL_W-1:0] rom_tsel;
            spec_rom9 #(
                .N_W(N_W), .SCALE_W(SCALE_W), .SCALE_FRAC(SCALE_FRAC), .DECODER_ROM(DECODER_ROM), .TSEL_W(TSEL_W),
                .INIT_FILE(ROM9_FILE)
            ) u_rom9 (
                .clk(clk), .en(accept), .n(d_n), .scale(scale9), .table_sel(rom_tsel)
            );
            assign n_dp = {N_W{1'b0}};
            if (DECODER_ROM != 0) begin : g_dec_rom
                assign table_sel = rom_tsel;
                wire unused_gates;
                assign unused_gates = &{1'b0, gate_tsel_q};
            end else begin : g_dec_gates
                assign table_sel = gate_tsel_q;
                wire unused_rom;
                assign unused_rom = &{1'b0, rom_tsel};
            end
        end
    endgenerate

    // ---- multiplier 11, ROM 12, [interpolator], multiplier 13 (pow mode: spec_powpath's value) ---------------
    wire [OUT_W-1:0] dp_out;
    wire dp_valid, dp_valid_next, dp_last;
    spec_datapath #(
        .C_W(C_W), .ANG_W(ANG_W), .ANG_FRAC(ANG_FRAC), .OUT_W(OUT_W), .SCALE_W(SCALE_W),
        .SCALE_FRAC(SCALE_FRAC), .TBL_AW(TBL_AW), .TBL_FRAC(TBL_FRAC), .INTERP(INTERP),
        .INTERP_FRAC(INTERP_FRAC), .DELTA_W(DELTA_W), .TSEL_W(TSEL_W), .PIPE(0), .CTRL(1), .SIDE(0),
        .N_W(N_W), .POW(POW), .POW_SEG_W(POW_SEG_W), .POW_IDX_W(POW_IDX_W), .POW_FRAC(POW_FRAC),
        .POW_VAL_W(POW_VAL_W), .POW_DLT_W(POW_DLT_W), .POW_SH_W(POW_SH_W), .POW_XB(POW_XB), .POW_YF(POW_YF),
        .POW_YI(POW_YI), .POW_K(POW_K), .ROM9_FILE(ROM9_FILE), .ROM12_FILE(ROM12_FILE)
    ) u_dp (
        .clk(clk), .rst(rst), .ce(ce), .in_valid(run), .in_last(last), .angle(angle8), .scale(scale9),
        .table_sel(table_sel), .n(n_dp), .c(c_q), .out(dp_out), .out_valid(dp_valid), .out_valid_next(dp_valid_next),
        .out_last(dp_last), .busy(dp_busy)
    );

    // ---- output register with a skid buffer ---------------------------------------------------------------
    wire ce_next_unused;
    spec_stream_out #(.LANES(1), .OUT_W(OUT_W)) u_out (
        .clk(clk), .rst(rst), .in_valid(dp_valid), .in_valid_next(dp_valid_next), .in_data(dp_out),
        .in_keep(dp_valid), .in_last(dp_last), .ce(ce), .ce_next(ce_next_unused), .m_axis_tvalid(m_axis_tvalid),
        .m_axis_tready(m_axis_tready), .m_axis_tdata(m_axis_tdata), .m_axis_tkeep(m_axis_tkeep),
        .m_axis_tlast(m_axis_tlast)
    );
endmodule
`default_nettype wire
