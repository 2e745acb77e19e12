// spec_unit - the device of UA 71489 (Romanyuk & Chornyi, 2004), Fig. 1: intensity of the specular
// component C * cos^k(sqrt(n/k) * angle) along a scanline, one pixel per two clocks (POW = 1: C * cos^n(angle)
// as exp2(n log2 cos), spec_powpath, docs/pow.md).
// (spec_stream is the one-pixel-per-clock variant on the same datapath.)
//
// Reference numerals in comments are the patent's. Formats (defaults from rom/spec_params.vh):
//   C      UQ0.C_W                         register 1 (inputs 15, 16)
//   dzeta  two's complement, ANG_FRAC bits  register 2 (inputs 17, 18), angle step in radians
//   zeta0  same format                      register 3 (inputs 19, 20), start angle (unscaled: -lambda)
//   n      0 .. 2^N_W - 1                   register 4 (inputs 21, 22)
//   l      0 .. 2^L_W - 1 intervals         counter 5 (inputs 23, 24): l + 1 pixels
//   out    UQ0.OUT_W                        output 27
// Start (26) acts on its rising edge, as the patent's flip-flop 39 is clocked by it: Start held high begins
// one span. A span runs the registers as they are: a Start without a new load of counter 5 runs the last
// loaded l again (a length register keeps it), never the 2^L_W pixels of a counter left at its maximum.
// Timing (see docs/interface.md): with Start rising in cycle t, busy_o is 1 from t+1; pixel i's valid_o pulse
// is in cycle t + `SPEC_UNIT_FIRST_PIXEL + 2i (15 + 2i; 17 + 2i with INTERP = 1; pow mode 26 + 2i, 27 + 2i);
// busy_o falls in the cycle after the last valid_o. Start, register writes and counter loads are ignored while
// busy_o is 1; init_n = 0 at a clock edge returns to idle (busy_o = 0, valid_o = 0 from the next cycle) and clears
// every register.
`timescale 1ns / 1ps
`default_nettype none
`include "spec_params.vh"
module spec_unit #(
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
    parameter ROM12_FILE = `SPEC_ROM12_FILE
) (
    input  wire             clk,
    input  wire             init_n,      // 25  initial set, active low (synchronous)
    input  wire             start,       // 26  "Start" (its rising edge)
    input  wire [C_W-1:0]   c_i,         // 15  C
    input  wire             c_we,        // 16
    input  wire [ANG_W-1:0] dzeta_i,     // 17  angle step
    input  wire             dzeta_we,    // 18
    input  wire [ANG_W-1:0] zeta0_i,     // 19  start angle
    input  wire             zeta0_we,    // 20
    input  wire [N_W-1:0]   n_i,         // 21  exponent n
    input  wire             n_we,        // 22
    input  wire [L_W-1:0]   len_i,       // 23  intervals l
    input  wire             len_load_n,  // 24  load counter 5, active low
    output wire [OUT_W-1:0] intensity_o, // 27  intensity
    output wire             busy_o,      // 28  "End": 1 while the span is computed
    output wire             valid_o      // 29  data valid
);
    wire rst = ~init_n;
    wire idle = ~busy_o;

    spec_param_check #(
        .C_W(C_W), .ANG_W(ANG_W), .ANG_FRAC(ANG_FRAC), .N_W(N_W), .L_W(L_W), .OUT_W(OUT_W), .SCALE_W(SCALE_W),
        .SCALE_FRAC(SCALE_FRAC), .TBL_AW(TBL_AW), .TBL_FRAC(TBL_FRAC), .INTERP(INTERP), .INTERP_FRAC(INTERP_FRAC),
        .DELTA_W(DELTA_W), .DECODER_ROM(DECODER_ROM), .TSEL_W(TSEL_W), .POW(POW), .POW_SEG_W(POW_SEG_W),
        .POW_IDX_W(POW_IDX_W), .POW_FRAC(POW_FRAC), .POW_VAL_W(POW_VAL_W), .POW_DLT_W(POW_DLT_W), .POW_SH_W(POW_SH_W),
        .POW_XB(POW_XB), .POW_YF(POW_YF), .POW_YI(POW_YI), .POW_K(POW_K)
    ) u_check ();

    // Start (26) on its rising edge: flip-flop 39 is clocked by Start in the patent. start_q is Start one clock
    // ago (not reset: after init_n, Start must rise again to begin a span).
    reg start_q;
    always @(posedge clk) start_q <= start;
    wire start_go = start & ~start_q & idle;

    // Control block 14 and its signals (public for the Fig. 11 trace of the Verilator harness).
    wire sig28 /*verilator public_flat_rd*/;
    wire sig34 /*verilator public_flat_rd*/;
    wire sig35 /*verilator public_flat_rd*/;   // borrow, active low
    wire sig36 /*verilator public_flat_rd*/;
    wire sig37 /*verilator public_flat_rd*/;
    wire d30 /*verilator public_flat_rd*/;
    wire d31 /*verilator public_flat_rd*/;
    wire d32 /*verilator public_flat_rd*/;
    wire d33 /*verilator public_flat_rd*/;

    // Register 8 holds a fresh pixel angle in the cycle after strobe 37; the datapath (multiplier 11 ->
    // ROM 12 -> multiplier 13) carries it to output 27 and raises data valid 29 with it.
    reg fresh8;
    always @(posedge clk) begin
        if (rst) fresh8 <= 1'b0;
        else fresh8 <= sig37;
    end
    wire dp_busy;
    assign busy_o = sig28 | fresh8 | dp_busy;

    // Registers 1..4
    wire [C_W-1:0] c_q;
    wire [ANG_W-1:0] dzeta_q, zeta0_q;
    wire [N_W-1:0] n_q;
    spec_reg #(.W(C_W))   u_reg1 (.clk(clk), .rst(rst), .we(c_we & idle),     .d(c_i),     .q(c_q));
    spec_reg #(.W(ANG_W)) u_reg2 (.clk(clk), .rst(rst), .we(dzeta_we & idle), .d(dzeta_i), .q(dzeta_q));
    spec_reg #(.W(ANG_W)) u_reg3 (.clk(clk), .rst(rst), .we(zeta0_we & idle), .d(zeta0_i), .q(zeta0_q));
    spec_reg #(.W(N_W))   u_reg4 (.clk(clk), .rst(rst), .we(n_we & idle),     .d(n_i),     .q(n_q));

    // Down-counter 5, loaded by strobe 24 (active low) with l from input 23, and again from the length
    // register when a span starts: a Start without a new load runs the last loaded l, not the 2^L_W pixels of
    // the counter's maximum, where the patent's counter is left after a span (docs/decisions.md).
    wire len_we = ~len_load_n & idle;
    wire [L_W-1:0] len_q;
    spec_reg #(.W(L_W)) u_len (.clk(clk), .rst(rst), .we(len_we), .d(len_i), .q(len_q));
    wire [L_W-1:0] count_q;
    spec_counter #(.W(L_W)) u_cnt5 (
        .clk(clk), .rst(rst), .load_n(~(len_we | start_go)), .d(len_we ? len_i : len_q),
        .count(sig34), .q(count_q), .borrow_n(sig35)
    );
    wire unused_count;
    assign unused_count = &{1'b0, count_q};

    // Control block 14
    spec_ctrl u_ctrl14 (
        .clk(clk), .init_n(init_n), .start(start_go), .borrow_n(sig35),
        .sig28(sig28), .sig34(sig34), .sig36(sig36), .sig37(sig37)
    );

    // Accumulating adder: adder 6, multiplexer 7, register 8
    wire [ANG_W-1:0] angle8;
    spec_accum #(.W(ANG_W)) u_acc678 (
        .clk(clk), .rst(rst), .we(sig37), .sel(sig36), .start(zeta0_q), .step(dzeta_q), .angle(angle8)
    );

    // ROM 9 and decoder 10 (both follow register 4; ROM 9 one clock later, ready long before the first pixel).
    // DECODER_ROM = 1: the table comes from ROM 9's word (decoder 10 as a ROM), the gates' one-hot lines
    // 30..33 stay observable. POW = 1: ROM 9 is the log table inside the datapath (spec_powpath), read every pixel
    // at register 8's angle, and multiplier 11 there takes register 4's n; the gates' lines stay observable.
    wire [1:0] gate_tsel;
    spec_decoder #(.N_W(N_W)) u_dec10 (
        .n(n_q), .d30(d30), .d31(d31), .d32(d32), .d33(d33), .table_sel(gate_tsel)
    );
    wire [SCALE_W-1:0] scale9;
    wire [TSEL_W-1:0] table_sel;
    generate
        if (POW != 0) begin : g_pow
            assign scale9 = {SCALE_W{1'b0}};
            assign table_sel = {TSEL_W{1'b0}};
            wire unused_gates;
            assign unused_gates = &{1'b0, gate_tsel};
        end else begin : g_rom9
            wire [TSEL_W-1:0] rom_tsel;
            spec_rom9 #(
                .N_W(N_W), .SCALE_W(SCALE_W), .SCALE_FRAC(SCALE_FRAC), .DECODER_ROM(DECODER_ROM), .TSEL_W(TSEL_W),
                .INIT_FILE(ROM9_FILE)
            ) u_rom9 (
                .clk(clk), .en(1'b1), .n(n_q), .scale(scale9), .table_sel(rom_tsel)
            );
            if (DECODER_ROM != 0) begin : g_dec_rom
                assign table_sel = rom_tsel;
                wire unused_gates;
                assign unused_gates = &{1'b0, gate_tsel};
            end else begin : g_dec_gates
                assign table_sel = gate_tsel;
                wire unused_rom;
                assign unused_rom = &{1'b0, rom_tsel};
            end
        end
    endgenerate

    // Multiplier 11, ROM 12, [interpolator], multiplier 13 (pow mode: the log table, multiplier 11 by n, ROM 12
    // exp2, the shift, multiplier 13)
    wire out_last_unused, out_next_unused;
    spec_datapath #(
        .C_W(C_W), .ANG_W(ANG_W), .ANG_FRAC(ANG_FRAC), .OUT_W(OUT_W), .SCALE_W(SCALE_W),
        .SCALE_FRAC(SCALE_FRAC), .TBL_AW(TBL_AW), .TBL_FRAC(TBL_FRAC), .INTERP(INTERP),
        .INTERP_FRAC(INTERP_FRAC), .DELTA_W(DELTA_W), .TSEL_W(TSEL_W), .N_W(N_W), .POW(POW), .POW_SEG_W(POW_SEG_W), .POW_IDX_W(POW_IDX_W), .POW_FRAC(POW_FRAC),
        .POW_VAL_W(POW_VAL_W), .POW_DLT_W(POW_DLT_W), .POW_SH_W(POW_SH_W), .POW_XB(POW_XB), .POW_YF(POW_YF),
        .POW_YI(POW_YI), .POW_K(POW_K), .ROM9_FILE(ROM9_FILE), .ROM12_FILE(ROM12_FILE)
    ) u_dp (
        .clk(clk), .rst(rst), .ce(1'b1), .in_valid(fresh8), .in_last(1'b0), .angle(angle8), .scale(scale9),
        .table_sel(table_sel), .n(n_q), .c(c_q), .out(intensity_o), .out_valid(valid_o),
        .out_valid_next(out_next_unused), .out_last(out_last_unused), .busy(dp_busy)
    );
endmodule
`default_nettype wire
