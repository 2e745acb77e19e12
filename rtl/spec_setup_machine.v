// spec_setup_machine - the units of spec_setup running the setup program (rom/gen/setup_program.h) by the modulo
// schedule and microcode that setuprom generates for a configuration (rom/gen/setup_sched.h states the contract,
// setup_params.vh carries the shape). A new span starts every II clocks and several are in flight; the machine
// never stalls (spec_setup keeps room for every span it starts).
//
//   - slot tau counts 0 .. II-1; the span counter S (STAGE_W bits) grows when tau returns to 0, and the span S
//     has its time 0 in that clock (tau0). Its beat is taken then.
//   - the microcode word of slot tau (a ROM, read a clock ahead) says which operation each unit starts, where its
//     operands are (per port: a bank slot and stage, or a constant; negate, magnitude), and where each unit's
//     result goes (per bank: write enable, source unit, slot and stage). A bank address is
//     {slot, (S - stage) mod 2^LMAX_LOG2}.
//   - an operation reads its banks in its issue clock; the operands (read registered) enter the unit one clock
//     later; the unit's result is written LAT clocks after the issue (LAT per unit type: setup_params.vh, checked
//     against the units' pipelines below).
//   - the IDOT units read the beat of span S - stage from a buffer of LIN = 2 beats.
//   - the OUT pseudo-unit (index NU) reads the program's results for the finish stage: fin_field of span
//     fin_span, one a clock.
// Reset (rst, synchronous): tau, S and the microcode register; the banks keep garbage that no span started after
// the reset reads before writing.
`timescale 1ns / 1ps
`default_nettype none
`include "setup_params.vh"
module spec_setup_machine #(
    parameter EFU_FILE = `SETUP_EFU_FILE,
    parameter UC_FILE = `SETUP_UC_FILE,
    parameter N_W = 10,
    parameter L_W = 16
) (
    input  wire                        clk,
    input  wire                        rst,
    output wire                        tau0,
    output wire [`SETUP_STAGE_W-1:0]   span,
    input  wire [15*`SETUP_VEC_W+14:0] beat_vec,       // N1, N2, H1, H2, PN (VEC_W + 1 bits each) of the span starting now
    input  wire                        beat_rule,
    input  wire [`SETUP_STR_W-1:0]     beat_strength,
    input  wire [N_W-1:0]              beat_n,
    input  wire [L_W-1:0]              beat_l,
    output reg                         fin_en,
    output reg  [3:0]                  fin_field,
    output reg  [`SETUP_STAGE_W-1:0]   fin_span,
    output wire [`SETUP_W-1:0]         fin_data
);
    localparam FM = `SETUP_FM, FE = `SETUP_FE, FG = `SETUP_FG, W = `SETUP_W;
    localparam II = `SETUP_II, NU = `SETUP_NU, NB = `SETUP_N_BANK;
    localparam LM = `SETUP_LMAX_LOG2, SW = `SETUP_STAGE_W;
    localparam UCW = `SETUP_UC_W, OPW = `SETUP_OP_W, SCW = `SETUP_SCALE_W, ADW = `SETUP_ADDR_W;
    localparam CSW = `SETUP_CSEL_W, WSW = `SETUP_WSRC_W;
    localparam MAXSRC = `SETUP_MAXSRC, MAXC = `SETUP_MAXC;
    localparam VEC_W = `SETUP_VEC_W, STR_W = `SETUP_STR_W;
    localparam VW = 15 * (VEC_W + 1);
    localparam BEATW = VW + 1 + STR_W + N_W + L_W;
    localparam TAUW = (II > 512) ? 10 : (II > 256) ? 9 : (II > 128) ? 8 : (II > 64) ? 7 : (II > 32) ? 6 : (II > 16) ? 5 : 4;
    localparam [3*(NU+1)-1:0] UNIT_TYPE = `SETUP_UNIT_TYPE;
    localparam [8*3*(NU+1)-1:0] PORT_BANK = `SETUP_PORT_BANK;
    localparam [8*NB-1:0] BANK_UNIT = `SETUP_BANK_UNIT;
    localparam [2*NB-1:0] BANK_PORT = `SETUP_BANK_PORT;
    localparam [8*NB-1:0] BANK_AW = `SETUP_BANK_AW;
    localparam [NB-1:0] BANK_PRED = `SETUP_BANK_PRED;
    localparam [8*NB-1:0] BANK_NSRC = `SETUP_BANK_NSRC;
    localparam [8*NB*MAXSRC-1:0] BANK_SRC = `SETUP_BANK_SRC;
    localparam [8*NB-1:0] BANK_NCONST = `SETUP_BANK_NCONST;
    localparam [W*NB*MAXC-1:0] BANK_CONST = `SETUP_BANK_CONST;
    localparam [16*(NU+1)-1:0] UC_GO = `SETUP_UC_GO, UC_OP = `SETUP_UC_OP, UC_SCALE = `SETUP_UC_SCALE;
    localparam [16*(NU+1)-1:0] UC_ISTAGE = `SETUP_UC_ISTAGE;
    localparam [16*3*(NU+1)-1:0] UC_ADDR = `SETUP_UC_ADDR, UC_STAGE = `SETUP_UC_STAGE, UC_CSEL = `SETUP_UC_CSEL;
    localparam [16*3*(NU+1)-1:0] UC_NEG = `SETUP_UC_NEG, UC_ABS = `SETUP_UC_ABS;
    localparam [16*NB-1:0] UC_WE = `SETUP_UC_WE, UC_WSRC = `SETUP_UC_WSRC, UC_WADDR = `SETUP_UC_WADDR;
    localparam [16*NB-1:0] UC_WSTAGE = `SETUP_UC_WSTAGE;

    // ---- slot, span counter, microcode ---------------------------------------------------------------------------
    reg [TAUW-1:0] tau;
    reg [SW-1:0] s_cnt;
    wire last = tau == II - 1;
    wire [TAUW-1:0] tau_n = (rst | last) ? {TAUW{1'b0}} : tau + 1'b1;
    always @(posedge clk) begin
        tau <= tau_n;
        if (rst) s_cnt <= {SW{1'b0}};
        else if (last) s_cnt <= s_cnt + 1'b1;
    end
    assign tau0 = tau == {TAUW{1'b0}};
    assign span = s_cnt;
    reg [UCW-1:0] ucrom[0:II-1];
    initial $readmemh(UC_FILE, ucrom);
    spec_setup_imgcheck #(.FILE(UC_FILE), .WORDS(II), .DIGITS((UCW + 3) / 4)) u_check ();
    reg [UCW-1:0] uc;   // the word of slot tau
    always @(posedge clk) uc <= ucrom[tau_n];

    // ---- the beat buffer -----------------------------------------------------------------------------------------
    reg [BEATW-1:0] bbuf0, bbuf1;
    always @(posedge clk) begin
        if (tau0 & ~s_cnt[0]) bbuf0 <= {beat_l, beat_n, beat_strength, beat_rule, beat_vec};
        if (tau0 & s_cnt[0]) bbuf1 <= {beat_l, beat_n, beat_strength, beat_rule, beat_vec};
    end

    // ---- units ---------------------------------------------------------------------------------------------------
    wire [W*NU-1:0] uout;          // each unit's result register
    wire [W*3*(NU+1)-1:0] rdat;    // each port's bank read (registered)
    genvar u, j, b, k;
    generate
        for (u = 0; u < NU; u = u + 1) begin : g_unit
            localparam [2:0] TY = UNIT_TYPE[3 * u +: 3];
            localparam integer OOP = {16'd0, UC_OP[16 * u +: 16]};
            localparam integer OSC = {16'd0, UC_SCALE[16 * u +: 16]};
            reg [OPW-1:0] op_q;
            reg [SCW-1:0] sc_q;
            always @(posedge clk) begin
                op_q <= uc[OOP +: OPW];
                sc_q <= uc[OSC +: SCW];
            end
            // the operands: the bank's word or a constant, magnitude, negate (one clock after the issue)
            wire [3*W-1:0] opnd;
            for (j = 0; j < 3; j = j + 1) begin : g_port
                localparam integer BK = {24'd0, PORT_BANK[8 * (3 * u + j) +: 8]};
                if (BK == 255) begin : g_none
                    assign opnd[j*W +: W] = {W{1'b0}};
                end else begin : g_opnd
                    localparam integer NC = {24'd0, BANK_NCONST[8 * BK +: 8]};
                    localparam integer OCS = {16'd0, UC_CSEL[16 * (3 * u + j) +: 16]};
                    localparam integer ONG = {16'd0, UC_NEG[16 * (3 * u + j) +: 16]};
                    localparam integer OAB = {16'd0, UC_ABS[16 * (3 * u + j) +: 16]};
                    reg [CSW-1:0] cs_q;
                    reg ng_q, ab_q;
                    always @(posedge clk) begin
                        cs_q <= uc[OCS +: CSW];
                        ng_q <= uc[ONG];
                        ab_q <= uc[OAB];
                    end
                    // candidates: the bank's word (select 0), then the port's constants (1 .. NC)
                    wire [W*(1<<CSW)-1:0] cand;
                    assign cand[0 +: W] = rdat[(3 * u + j) * W +: W];
                    for (k = 1; k < (1 << CSW); k = k + 1) begin : g_const
                        if (k <= NC) begin : g_c
                            assign cand[k*W +: W] = BANK_CONST[(BK * MAXC + k - 1) * W +: W];
                        end else begin : g_z
                            assign cand[k*W +: W] = {W{1'b0}};
                        end
                    end
                    wire [W-1:0] v = cand[cs_q * W +: W];
                    // magnitude first, then negate; zero keeps sign 0
                    wire sgn = (ab_q ? 1'b0 : v[W-1]) ^ (ng_q & |v[FM-1:0]);
                    assign opnd[j*W +: W] = {sgn, v[W-2:0]};
                end
            end
            if (TY == 3'd0) begin : g_idot
                localparam integer OIS = {16'd0, UC_ISTAGE[16 * u +: 16]};
                reg bsel;
                always @(posedge clk) bsel <= s_cnt[0] ^ uc[OIS];   // the span S - stage's buffer (LIN = 2)
                wire [BEATW-1:0] bt = bsel ? bbuf1 : bbuf0;
                spec_setup_idot #(.FM(FM), .FE(FE), .VEC_W(VEC_W), .STR_W(STR_W), .STR_FRAC(`SETUP_STR_FRAC),
                                  .N_W(N_W), .L_W(L_W)) u_idot (
                    .clk(clk), .vec(bt[0 +: VW]), .rule(bt[VW]), .strength(bt[VW + 1 +: STR_W]),
                    .n(bt[VW + 1 + STR_W +: N_W]), .l(bt[VW + 1 + STR_W + N_W +: L_W]),
                    .mode(op_q[2:0]), .va(op_q[5:3]), .vb(op_q[8:6]), .comp(op_q[10:9]), .r(uout[u*W +: W])
                );
                wire unused_idot;
                assign unused_idot = &{1'b0, sc_q, opnd, op_q};
            end else if (TY == 3'd1) begin : g_mul
                spec_setup_fmul #(.FM(FM), .FE(FE), .SCALE_W(SCW)) u_mul (
                    .clk(clk), .a(opnd[0 +: W]), .b(opnd[W +: W]), .scale(sc_q), .r(uout[u*W +: W])
                );
                wire unused_mul;
                assign unused_mul = &{1'b0, op_q, opnd[2*W +: W]};
            end else if (TY == 3'd2) begin : g_add
                spec_setup_fadd #(.FM(FM), .FE(FE), .FG(FG), .SCALE_W(SCW)) u_add (
                    .clk(clk), .a(opnd[0 +: W]), .b(opnd[W +: W]), .bscale(op_q[2:0]), .scale(sc_q), .r(uout[u*W +: W])
                );
                wire unused_add;
                assign unused_add = &{1'b0, op_q, opnd[2*W +: W]};
            end else if (TY == 3'd3) begin : g_efu
                spec_setup_efu #(.FM(FM), .FE(FE), .TAB_T(`SETUP_TAB_T), .TAB_R(`SETUP_TAB_R), .TAB_F(`SETUP_TAB_F),
                                 .SCALE_W(SCW), .END(`SETUP_EFU_END), .EFU_FILE(EFU_FILE)) u_efu (
                    .clk(clk), .a(opnd[0 +: W]), .op(op_q[1:0]), .scale(sc_q), .r(uout[u*W +: W])
                );
                wire unused_efu;
                assign unused_efu = &{1'b0, op_q, opnd[W +: 2 * W]};
            end else begin : g_misc
                spec_setup_misc #(.FM(FM), .FE(FE), .SCALE_W(SCW)) u_misc (
                    .clk(clk), .a(opnd[0 +: W]), .b(opnd[W +: W]), .c(opnd[2 * W]), .op(op_q[1:0]), .scale(sc_q),
                    .r(uout[u*W +: W])
                );
                wire unused_misc;
                assign unused_misc = &{1'b0, op_q, opnd[2*W+1 +: W-1]};
            end
        end
    endgenerate

    // ---- banks: one per unit port (the last: the OUT pseudo-unit's, the finish's) ---------------------------------
    generate
        for (b = 0; b < NB; b = b + 1) begin : g_bank
            localparam integer U = {24'd0, BANK_UNIT[8 * b +: 8]};
            localparam integer P = {30'd0, BANK_PORT[2 * b +: 2]};
            localparam [7:0] AW = BANK_AW[8 * b +: 8];
            localparam [0:0] PRED = BANK_PRED[b];
            localparam integer DW = (PRED == 1'b1) ? 1 : W;
            localparam [7:0] NS = BANK_NSRC[8 * b +: 8];
            localparam integer ORA = {16'd0, UC_ADDR[16 * (3 * U + P) +: 16]};
            localparam integer ORS = {16'd0, UC_STAGE[16 * (3 * U + P) +: 16]};
            localparam integer OWE = {16'd0, UC_WE[16 * b +: 16]};
            localparam integer OWS = {16'd0, UC_WSRC[16 * b +: 16]};
            localparam integer OWA = {16'd0, UC_WADDR[16 * b +: 16]};
            localparam integer OWT = {16'd0, UC_WSTAGE[16 * b +: 16]};
            // addresses: {slot, (S - stage) mod 2^LM}, AW bits
            wire [SW-1:0] rs = s_cnt - uc[ORS +: SW];
            wire [SW-1:0] ws = s_cnt - uc[OWT +: SW];
            wire [ADW+LM-1:0] ra_full, wa_full;
            if (LM > 0) begin : g_lm
                assign ra_full = {uc[ORA +: ADW], rs[LM-1:0]};
                assign wa_full = {uc[OWA +: ADW], ws[LM-1:0]};
            end else begin : g_nolm
                assign ra_full = uc[ORA +: ADW];
                assign wa_full = uc[OWA +: ADW];
            end
            // the write's source: the bank's source list (setup_params.vh)
            reg [W-1:0] src;
            integer s;
            always @(*) begin
                src = {W{1'b0}};
                for (s = 0; s < MAXSRC; s = s + 1)
                    if (s < NS && {{(32 - WSW) {1'b0}}, uc[OWS +: WSW]} == s)
                        src = uout[BANK_SRC[8 * (b * MAXSRC + s) +: 8] * W +: W];
            end
            wire [DW-1:0] wd;
            if (PRED == 1'b1) begin : g_pred
                assign wd = |src[FM-1:0];
                wire unused_pred;
                assign unused_pred = &{1'b0, src[W-1:FM]};
            end else begin : g_word
                assign wd = src;
            end
            wire [DW-1:0] rd;
            spec_setup_bank #(.AW(AW), .DW(DW)) u_bank (
                .clk(clk), .we(uc[OWE]), .wa(wa_full[AW-1:0]), .wd(wd), .ra(ra_full[AW-1:0]), .rd(rd)
            );
            assign rdat[(3 * U + P) * W +: W] = {{(W - DW) {1'b0}}, rd};
            wire unused_bank;
            assign unused_bank = &{1'b0, rs, ws, ra_full, wa_full};
        end
    endgenerate
    // ports without a bank read zero
    generate
        for (u = 0; u <= NU; u = u + 1) begin : g_noport
            for (j = 0; j < 3; j = j + 1) begin : g_p
                if (PORT_BANK[8 * (3 * u + j) +: 8] == 8'd255) begin : g_z
                    assign rdat[(3 * u + j) * W +: W] = {W{1'b0}};
                end
            end
        end
    endgenerate

    // ---- the finish's reads --------------------------------------------------------------------------------------
    localparam integer OGO = {16'd0, UC_GO[16 * NU +: 16]};
    localparam integer OFF_OUTOP = {16'd0, UC_OP[16 * NU +: 16]};
    localparam integer OFF_OUTST = {16'd0, UC_STAGE[16 * 3 * NU +: 16]};
    always @(posedge clk) begin
        fin_en <= ~rst & uc[OGO];
        fin_field <= uc[OFF_OUTOP +: 4];
        fin_span <= s_cnt - uc[OFF_OUTST +: SW];
    end
    assign fin_data = rdat[3 * NU * W +: W];

    // ---- checks: the schedule was made for these pipelines (an instance of a module that does not exist stops
    // elaboration in every tool, naming the rule; spec_param_check does the same)
    generate
        if (`SETUP_LAT_MUL != 7 || `SETUP_LAT_ADD != 8 || `SETUP_LAT_EFU != 9 || `SETUP_LAT_MISC != 3 ||
            `SETUP_LAT_IDOT != 7) begin : g_lat
            spec_parameter_error_setup_params_vh_unit_latencies_are_not_the_RTLs run_setuprom_of_this_tree ();
        end
        if (`SETUP_LIN != 2) begin : g_lin
            spec_parameter_error_setup_params_vh_LIN_must_be_2 run_setuprom_of_this_tree ();
        end
        if (II < 11) begin : g_ii
            spec_parameter_error_II_must_be_at_least_11 the_finish_reads_nine_fields_a_span ();
        end
    endgenerate
    wire unused;
    assign unused = &{1'b0, rdat};   // the ports without a bank, the condition banks' zero bits
endmodule
`default_nettype wire
