// spec_datapath - the pixel datapath after register 8, shared by spec_unit, spec_stream and spec_stream_seq:
// multiplier 11 -> ROM 12 (table chosen by decoder 10) -> [interpolator, INTERP = 1] -> multiplier 13; with POW = 1
// (pow mode, docs/pow.md) the value multiplier 13 takes comes from spec_powpath instead (ROM 9 the log table read
// per pixel, multiplier 11 by n, ROM 12 exp2, the shift): the valid pipeline, C's delay and multiplier 13 are
// the same in both modes.
// Every stage is registered and advances when `ce` is 1 (a stall holds everything, including the ROMs' read
// registers). Each pixel carries its own C, scale (pow mode: n), table and `last` flag, so consecutive pixels may
// belong to different spans (SIDE = 1, the default); SIDE = 0: C, n and the table are the span's, held by the
// caller. Latency from the input to `out`: LAT = 12 clocks (14 with INTERP = 1) of `ce`; pow mode 23 (24); no
// stage holds more than one DSP multiply or one carry chain.
`timescale 1ns / 1ps
`default_nettype none
module spec_datapath #(
    parameter C_W = 16,
    parameter ANG_W = 32,
    parameter ANG_FRAC = 28,
    parameter OUT_W = 16,
    parameter SCALE_W = 18,
    parameter SCALE_FRAC = 15,
    parameter TBL_AW = 12,
    parameter TBL_FRAC = 16,
    parameter INTERP = 0,
    parameter INTERP_FRAC = 10,
    parameter DELTA_W = 10,
    parameter TSEL_W = 2,
    parameter PIPE = 0,    // 1: a register stage after each DSP block's output (spec_stream; 2 more clocks,
                           //    4 with INTERP = 1: also a second register on ROM 12's word)
    parameter CTRL = 1,    // 0: no valid/last pipeline (out_valid, out_last, busy = 0; the output register
                           //    loads with every ce): the caller tracks its pixels (spec_stream)
    parameter DELAY_RAM = 0,   // 1: C's delay beside multiplier 11 and ROM 12 in block RAM (spec_delay RAM)
    parameter SIDE = 1,    // 1: C and the table travel beside each pixel (delay lines); 0: the caller holds them
                           //    for a whole span and changes them only while no pixel is in the pipeline
                           //    (busy = 0): ROM 12 and multiplier 13 read them as they are (spec_stream_seq)
    parameter N_W = 10,
    parameter POW = 0,     // 1: pow mode: the value from spec_powpath (scale, table_sel unused; n used)
    parameter POW_SEG_W = 3,
    parameter POW_IDX_W = 6,
    parameter POW_FRAC = 10,
    parameter POW_VAL_W = 16,
    parameter POW_DLT_W = 14,
    parameter POW_SH_W = 5,
    parameter POW_XB = 12,
    parameter POW_YF = 18,
    parameter POW_YI = 5,
    parameter POW_K = 421657428,
    parameter ROM9_FILE = "",   // pow mode's ROM 9 (the log table)
    parameter ROM12_FILE = ""
) (
    input  wire               clk,
    input  wire               rst,        // synchronous: clears the valid flags and the output
    input  wire               ce,
    input  wire               in_valid,
    input  wire               in_last,
    input  wire [ANG_W-1:0]   angle,      // register 8
    input  wire [SCALE_W-1:0] scale,      // ROM 9 (patent and tuned mode)
    input  wire [TSEL_W-1:0]  table_sel,  // decoder 10 (patent and tuned mode)
    input  wire [N_W-1:0]     n,          // register 4 (pow mode)
    input  wire [C_W-1:0]     c,          // register 1
    output wire [OUT_W-1:0]   out,        // output 27
    output wire               out_valid,
    output wire               out_valid_next,   // out_valid in the next cycle (CTRL = 1; 0 otherwise)
    output wire               out_last,
    output wire               busy        // a pixel is somewhere in the pipeline
);
    localparam TBL_DW = TBL_FRAC + 1;
    localparam WORD_W = TBL_DW + ((INTERP != 0) ? DELTA_W : 0);
    localparam FRAC_W = (INTERP != 0) ? INTERP_FRAC : 1;
    localparam P = (PIPE != 0) ? 1 : 0;
    localparam M11 = 7 + P;                       // multiplier 11's stages
    // registers on ROM 12's word after the block RAM: two with INTERP = 1 and PIPE = 1, so that the block
    // RAM's output register and the interpolator's DSP input register each have one of their own
    localparam WR = ((INTERP != 0) && (PIPE != 0)) ? 2 : 1;
    // the stage where the table value is ready (spec_powpath's VS in pow mode: Format::pow_latency - 3 - P)
    localparam VS_COSK = M11 + 1 + WR + ((INTERP != 0) ? 2 + P : 0);
    localparam VS_POW = 3 + POW_SEG_W + 3 * (2 + P) + (POW_SH_W + 1) / 2 + ((INTERP != 0) ? 0 : 1) + 2 +
                        ((INTERP != 0) ? 2 + 2 * P : 0) + POW_YI / 2;
    localparam VS = (POW != 0) ? VS_POW : VS_COSK;
    localparam LAT = VS + 3 + P;                  // multiplier 13's stages

    // valid flags of every stage (stage s holds what entered s clocks of `ce` ago)
    wire [LAT:1] vs;
    wire out_en;   // multiplier 13's output register loads
    generate
        if (CTRL != 0) begin : g_ctrl
            reg [LAT:1] vs_q;
            always @(posedge clk) begin
                if (rst) vs_q <= {LAT{1'b0}};
                else if (ce) vs_q <= {vs_q[LAT-1:1], in_valid};
            end
            assign vs = vs_q;
            assign out_en = ce & vs_q[LAT-1];
            assign out_valid_next = ce ? vs_q[LAT-1] : vs_q[LAT];
            // `last` beside the valid flags (stage s at bit s)
            reg [LAT:1] ls_q;
            always @(posedge clk) if (ce) ls_q <= {ls_q[LAT-1:1], in_last};
            assign out_last = ls_q[LAT];
        end else begin : g_noctrl
            assign vs = {LAT{1'b0}};
            assign out_en = ce;
            assign out_valid_next = 1'b0;
            assign out_last = 1'b0;
            wire unused_ctrl;
            assign unused_ctrl = &{1'b0, in_valid, in_last};
        end
    endgenerate

    // the value multiplier 13 takes (stage VS), and whether the pixel is 0
    wire [TBL_DW-1:0] value_m;
    wire zero_m;
    generate
        if (POW != 0) begin : g_pow
            spec_powpath #(
                .ANG_W(ANG_W), .ANG_FRAC(ANG_FRAC), .N_W(N_W), .TBL_AW(TBL_AW), .TBL_FRAC(TBL_FRAC), .INTERP(INTERP),
                .INTERP_FRAC(INTERP_FRAC), .DELTA_W(DELTA_W), .POW_SEG_W(POW_SEG_W), .POW_IDX_W(POW_IDX_W),
                .POW_FRAC(POW_FRAC), .POW_VAL_W(POW_VAL_W), .POW_DLT_W(POW_DLT_W), .POW_SH_W(POW_SH_W),
                .POW_XB(POW_XB), .POW_YF(POW_YF), .POW_YI(POW_YI), .POW_K(POW_K), .PIPE(PIPE), .SIDE(SIDE),
                .VS(VS), .ROM9_FILE(ROM9_FILE), .ROM12_FILE(ROM12_FILE)
            ) u_pow (
                .clk(clk), .ce(ce), .angle(angle), .n(n), .value(value_m), .zero(zero_m)
            );
            wire unused_cosk;
            assign unused_cosk = &{1'b0, scale, table_sel};
        end else begin : g_cosk
            // multiplier 11 (stages 1..7)
            wire [TBL_AW-1:0] index11;
            wire [FRAC_W-1:0] frac11;
            wire zero11;
            spec_mul11 #(
                .ANG_W(ANG_W), .SCALE_W(SCALE_W), .PROD_FRAC(ANG_FRAC + SCALE_FRAC), .TBL_AW(TBL_AW),
                .INTERP(INTERP), .INTERP_FRAC(INTERP_FRAC), .DSP_FF(P)
            ) u_mul11 (
                .clk(clk), .ce(ce), .angle(angle), .scale(scale), .index(index11), .frac(frac11), .zero(zero11)
            );

            // ROM 12 (stage 8), addressed by decoder 10's table (delayed to stage 7) and multiplier 11's position
            wire [TSEL_W-1:0] tsel_rom;   // the table, delayed to meet multiplier 11's position
            spec_delay #(.W(TSEL_W), .N((SIDE != 0) ? M11 : 0)) u_tsel (
                .clk(clk), .ce(ce), .d(table_sel), .q(tsel_rom)
            );
            wire [WORD_W-1:0] word12;
            spec_rom12 #(
                .TBL_AW(TBL_AW), .TSEL_W(TSEL_W), .TBL_FRAC(TBL_FRAC), .INTERP(INTERP), .DELTA_W(DELTA_W),
                .WORD_W(WORD_W), .INIT_FILE(ROM12_FILE)
            ) u_rom12 (
                .clk(clk), .en(ce), .table_sel(tsel_rom), .index(index11), .value(word12)
            );
            // a plain register after the block RAM (stage 9): the block RAM's clock-to-output time is long (5.6 ns
            // on the ECP5 without its output register), so nothing but a register comes after it; syn/dsp_pack.py
            // moves it into the DP16KD's output register (REGMODE OUTREG). With INTERP = 1 and PIPE = 1 a second
            // register (stage 10) feeds the interpolator's DSP block alone, which takes it as its input register.
            // The table value and the interpolation step get registers of their own.
            wire [TBL_DW-1:0] word_v;
            spec_delay #(.W(TBL_DW), .N(WR)) u_word (.clk(clk), .ce(ce), .d(word12[TBL_DW-1:0]), .q(word_v));
            wire [FRAC_W-1:0] frac_interp;   // the position's fraction, delayed to meet the table word
            spec_delay #(.W(FRAC_W), .N(1 + WR)) u_frac (.clk(clk), .ce(ce), .d(frac11), .q(frac_interp));
            spec_delay #(.W(1), .N(VS - M11)) u_zero (.clk(clk), .ce(ce), .d(zero11), .q(zero_m));

            // interpolator (INTERP = 1, stages 10..11) or the plain table value
            if (INTERP != 0) begin : g_interp
                wire [DELTA_W-1:0] word_d;
                spec_delay #(.W(DELTA_W), .N(WR)) u_word_d (
                    .clk(clk), .ce(ce), .d(word12[WORD_W-1:TBL_DW]), .q(word_d)
                );
                spec_interp #(.TBL_DW(TBL_DW), .DELTA_W(DELTA_W), .INTERP_FRAC(INTERP_FRAC), .DSP_FF(P)) u_interp (
                    .clk(clk), .ce(ce), .v(word_v), .delta(word_d), .frac(frac_interp), .value(value_m)
                );
            end else begin : g_plain
                wire unused_frac;
                assign unused_frac = &{1'b0, frac_interp};
                assign value_m = word_v;
            end
            wire unused_n;
            assign unused_n = &{1'b0, n};
        end
    endgenerate

    // multiplier 13 (three stages) -> output 27
    wire [C_W-1:0] c_m;
    spec_delay #(.W(C_W), .N((SIDE != 0) ? VS : 0), .RAM(DELAY_RAM)) u_c (.clk(clk), .ce(ce), .d(c), .q(c_m));
    spec_mul13 #(.C_W(C_W), .TBL_DW(TBL_DW), .OUT_W(OUT_W), .SHIFT(C_W + TBL_FRAC - OUT_W), .DSP_FF(P)) u_mul13 (
        .clk(clk), .rst(rst), .ce(ce), .en(out_en), .c(c_m), .value(value_m), .zero(zero_m),
        .out(out)
    );
    assign out_valid = vs[LAT];
    assign busy = |vs;
endmodule
`default_nettype wire
