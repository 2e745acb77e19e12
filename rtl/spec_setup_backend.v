// spec_setup_backend - the small setup's back end (SetupModel::run after the angles): from gamma, lambda, A * 2^F
// and cos(theta1) * 2^F / G to the descriptor (C, zeta0, dzeta) and the flags, one operation a clock through ONE
// adder (the ALU below) driven by a micro-program (the table `ctl` below, in LUTs: a function of the program
// counter). The same integer operations as spec_setup_pipe in the same order, so bit for bit SetupModel::run.
//
// Datapath: ACC (PW bits, two's complement) <= A + B + cin, A one of {ACC, 0, ACC << 1, ACC >>> 1} (optionally
// inverted), B one of {register file word, 0, gamma, lambda, table word, first table word, interpolation
// product, exponent, l << (S-1)} (optionally inverted); a step may instead only test the sign of A + B + cin
// into a flag, and may write ACC (its value before the step) into the register file. The register file
// (block RAM, registered read, its address one step ahead) holds the constants (initial values, never
// written) and the values kept between steps. A comparison is the sign of a sum: x > y is x + ~y >= 0.
// Beside the ALU: a log2 normalizer (a shift left a clock), the log2 / exp2 tables, a multiplier (a DSP) for
// their interpolation, a restoring divider for dzeta (one subtractor, running beside the program).
//
// Timing (issue 13, docs/setup.md): the step's control word is a register loaded from the table one step
// ahead; an ALU step takes three clocks (operands into registers, low half, high half with the registered
// carry), the steps without the ALU one; the hold conditions, the divider's state and the output words are
// registers.
//
// Handshake: start (one clock, while idle) begins a span; the inputs hold until done. The outputs m_* are
// registers (m_n and m_l are the caller's, m_c and m_flags the registers c_out and f_out, m_dzeta is the
// divider's quotient, m_zeta0 the register file's read register holding word R_ZETA): m_tvalid rises when the
// span is finished and holds until m_tready; done is 1 in the clock after that handover, and only then may the
// caller start the next span. rst: idle, output empty.
`timescale 1ns / 1ps
`default_nettype none
`include "setup_small_params.vh"
`include "spec_params.vh"
module spec_setup_backend #(
    parameter F = `SMALL_F,
    parameter W = `SMALL_W,
    parameter ZW = `SMALL_ZW,
    parameter ZF = `SMALL_ZF,
    parameter LF = `SMALL_LF,
    parameter EF = `SMALL_EF,
    parameter TB = `SMALL_TB,
    parameter RB = `SMALL_RB,
    parameter STR_W = `SMALL_STR_W,
    parameter STR_FRAC = `SMALL_STR_FRAC,
    parameter C_W = `SPEC_C_W,
    parameter N_W = `SPEC_N_W,
    parameter L_W = `SPEC_L_W,
    parameter ANG_W = `SPEC_ANG_W,
    parameter ANG_FRAC = `SPEC_ANG_FRAC,
    parameter LOG2_FILE = `SMALL_LOG2_FILE,
    parameter EXP2_FILE = `SMALL_EXP2_FILE
) (
    input  wire                 clk,
    input  wire                 rst,
    input  wire                 start,   // gamma is in lz
    input  wire                 lam_ok,  // lambda is in lz, A * 2^F in mag (until done)
    output reg                  done,
    input  wire signed [ZW-1:0] lz,      // the angle lane: gamma, then lambda (ZF fraction bits)
    input  wire signed [W-1:0]  mag,     // A * 2^F
    input  wire signed [W-1:0]  c1,      // cos(theta1) * 2^F / G (valid from step P_LOG_X on)
    input  wire [STR_W-1:0]     s_str,
    input  wire [N_W-1:0]       s_n,
    input  wire [L_W-1:0]       s_l,
    input  wire                 s_rule,
    input  wire                 s_bad,   // a zero end vector
    input  wire                 s_opp,   // opposite normals
    output reg                  m_tvalid,
    input  wire                 m_tready,
    output wire [C_W-1:0]       m_c,
    output wire [N_W-1:0]       m_n,
    output wire [L_W-1:0]       m_l,
    output wire [ANG_W-1:0]     m_zeta0,
    output wire [ANG_W-1:0]     m_dzeta,
    output wire [6:0]           m_flags
);
    localparam S = ZF - ANG_FRAC;
    localparam PW = LF + N_W + 8;           // ACC: the widest value, p = n * (-log2 A) - log2 Is
    localparam signed [ZW-1:0] HALF_PI = `SMALL_HALF_PI;
    localparam signed [ZW-1:0] PI_Z = `SMALL_PI;
    localparam signed [ZW-1:0] TWO_PI = `SMALL_TWO_PI;
    localparam signed [ZW-1:0] FLAT_Z = `SMALL_FLAT_Z;

    // ---- register file: constants and kept values ---------------------------------------------------------------
    localparam [3:0] R_Z0 = 4'd0, R_LAV = 4'd1, R_LIS = 4'd2, R_GAM = 4'd3, R_ZETA = 4'd13, R_PI = 4'd4, R_2PI = 4'd5, R_HPI = 4'd6,
                     R_HPIM1 = 4'd7, R_S2 = 4'd8, R_OFF = 4'd9, R_OFFF = 4'd10, R_LAMAX = 4'd11, R_STRF = 4'd12;
    (* no_rw_check *) reg [PW-1:0] rf[0:15];   // no read-during-write relation: see the read below
    wire [3:0] rf_ra;                       // the word the next step reads
    reg [PW-1:0] rd;
    reg signed [PW-1:0] acc;
    initial begin
        rf[R_PI] = {{(PW - ZW) {PI_Z[ZW-1]}}, PI_Z};
        rf[R_2PI] = {{(PW - ZW) {TWO_PI[ZW-1]}}, TWO_PI};
        rf[R_HPI] = {{(PW - ZW) {HALF_PI[ZW-1]}}, HALF_PI};
        rf[R_HPIM1] = {{(PW - ZW) {HALF_PI[ZW-1]}}, HALF_PI} - 1'b1;
        rf[R_S2] = 1 << (S - 1);
        rf[R_OFF] = F << LF;
        rf[R_OFFF] = (F << LF) - `SMALL_LOG2_GAIN;
        rf[R_LAMAX] = 31 << LF;
        rf[R_STRF] = STR_FRAC << LF;
    end

    // ---- the micro-program ----------------------------------------------------------------------------------------
    // A step: a (A operand), ia / ib (invert A / B), ci (carry in), b (B operand), g (B gated by the exponent bit of
    // the multiplication step), we (ACC <= sum) under condition cd, fl (a flag from the sum's sign), rw / wa
    // (register file write of ACC), ra (register file word for B), act (the other units).
    localparam [1:0] A_ACC = 2'd0, A_ZERO = 2'd1, A_SHL = 2'd2, A_SHR = 2'd3;
    localparam [3:0] B_RF = 4'd0, B_ZERO = 4'd1, B_LZ = 4'd3, B_TABW = 4'd4, B_W0 = 4'd5,
                     B_TPH = 4'd6, B_ELF = 4'd7, B_LSH = 4'd8;
    localparam [2:0] C_NO = 3'd0, C_ALL = 3'd1, C_HI = 3'd2, C_LO = 3'd3, C_BIG = 3'd4, C_ZLA = 3'd5, C_ZETA = 3'd6;
    localparam [2:0] FL_NO = 3'd0, FL_HI = 3'd1, FL_LO = 3'd2, FL_A = 3'd3, FL_B = 3'd4, FL_NEG = 3'd5, FL_BIG = 3'd6,
                     FL_SAT = 3'd7;
    localparam [3:0] X_NONE = 4'd0, X_DIV = 4'd1, X_LGX = 4'd2, X_LGS = 4'd3, X_NORM = 4'd4, X_TABL = 4'd5,
                     X_TABE = 4'd6, X_TAB1 = 4'd7, X_W0 = 4'd8, X_SHIFT = 4'd9, X_OUT = 4'd10, X_IDLE = 4'd11,
                     X_FLAT = 4'd12;
    // program counters of the steps that the logic below refers to
    localparam [6:0] P_LOG_X = 7'd17, P_LOG_S = 7'd33, P_HORNER = 7'd46, P_EXP = 7'd57, P_OUT = 7'd68;
    // The step's control word c_* is a register, loaded from the table at pc1 (the program counter plus one, the
    // only program counter kept) when the program advances, so no adder sees counter -> table -> select.
    reg [6:0] pc1;
    reg [1:0] c_a;
    reg c_ia, c_ib, c_ci, c_g, c_rw;
    reg [3:0] c_b, c_wa, c_act;
    reg [2:0] c_cd, c_fl;
    reg [1:0] t_a;
    reg t_ia, t_ib, t_ci, t_g, t_rw;
    reg [3:0] t_b, t_wa, t_act;
    reg [2:0] t_cd, t_fl;
    always @* begin
        t_a = A_ACC;
        t_ia = 1'b0;
        t_ib = 1'b0;
        t_ci = 1'b0;
        t_b = B_ZERO;
        t_g = 1'b0;
        t_cd = C_NO;
        t_fl = FL_NO;
        t_rw = 1'b0;
        t_wa = R_Z0;
        t_act = X_NONE;
        // one case over the program counter (a ROM): the two log2 lookups (ten steps after P_LOG_X and after
        // P_LOG_S, alike but for zeta0's zeroing in the second), the multiplication n * la_v (N_W steps from
        // P_HORNER, from n's top bit), the other steps
        case (pc1)
            7'd0: t_act = X_IDLE;
            7'd1: begin t_a = A_ZERO; t_b = B_LZ; t_cd = C_ALL; t_act = X_FLAT; end          // gamma; flat
            7'd2: begin t_b = B_LSH; t_cd = C_ALL; t_rw = 1'b1; t_wa = R_GAM; end            // + l 2^(S-1)
            7'd3: begin t_a = A_ZERO; t_b = B_LZ; t_ib = 1'b1; t_ci = 1'b1; t_cd = C_ALL; t_act = X_DIV; end  // -lambda
            7'd4: begin t_a = A_ZERO; t_b = B_RF; t_cd = C_ALL; t_rw = 1'b1; t_wa = R_Z0; end  // gamma
            7'd5: begin t_a = A_SHR; t_cd = C_ALL; end                                       // gamma >>> 1
            7'd6: begin t_b = B_RF; t_cd = C_ALL; end                                        // mid = z0 + gamma/2
            7'd7: begin t_b = B_RF; t_ib = 1'b1; t_fl = FL_HI; end                           // mid > pi
            7'd8: begin t_b = B_RF; t_fl = FL_LO; end                                        // mid < -pi
            7'd9: begin t_a = A_ZERO; t_b = B_RF; t_cd = C_ALL; end                          // z0
            7'd10: begin t_b = B_RF; t_ib = 1'b1; t_ci = 1'b1; t_cd = C_HI; end              // - 2 pi
            7'd11: begin t_b = B_RF; t_cd = C_LO; end                                        // + 2 pi
            7'd12: begin t_b = B_RF; t_ib = 1'b1; t_ci = 1'b1; t_fl = FL_A; end              // z0 >= pi/2
            7'd13: begin t_b = B_RF; t_cd = C_ALL; t_rw = 1'b1; t_wa = R_Z0; end             // z0 + gamma
            7'd14: begin t_b = B_RF; t_fl = FL_B; end                                        // <= -pi/2
            7'd15: begin t_a = A_ZERO; t_b = B_RF; t_cd = C_ALL; end                         // z0
            7'd16: begin t_b = B_RF; t_cd = C_ALL; end                                       // + 2^(S-1)
            P_LOG_X: begin t_rw = 1'b1; t_wa = R_ZETA; t_act = X_LGX; end                    // log2 x
            P_LOG_X + 7'd1, P_LOG_S + 7'd1: t_act = X_NORM;                                  // normalize
            P_LOG_X + 7'd2: t_act = X_TABL;                                                  // word j
            P_LOG_S + 7'd2: begin t_act = X_TABL; t_a = A_ZERO; t_cd = C_ALL; end            // (zeta0: 0
            P_LOG_X + 7'd3: t_act = X_TAB1;                                                  // word j + 1
            P_LOG_S + 7'd3: begin t_act = X_TAB1; t_a = A_ZERO; t_b = B_RF; t_cd = C_ZETA; end   // or kept)
            P_LOG_X + 7'd4: t_act = X_W0;                                                    // w0 = word j
            P_LOG_S + 7'd4: begin t_act = X_W0; t_rw = 1'b1; t_wa = R_ZETA; end
            P_LOG_X + 7'd5, P_LOG_S + 7'd5: begin t_a = A_ZERO; t_b = B_TABW; t_cd = C_ALL; end   // word j + 1
            P_LOG_X + 7'd6, P_LOG_S + 7'd6: begin t_b = B_W0; t_ib = 1'b1; t_ci = 1'b1; t_cd = C_ALL; end  // tdiff
            P_LOG_X + 7'd8, P_LOG_S + 7'd8: begin t_a = A_ZERO; t_b = B_TPH; t_ci = 1'b1; t_cd = C_ALL; end  // (p >> RB-1) + 1
            P_LOG_X + 7'd9, P_LOG_S + 7'd9: begin t_a = A_SHR; t_b = B_W0; t_cd = C_ALL; end  // w0 + round(p / 2^RB)
            P_LOG_X + 7'd10, P_LOG_S + 7'd10: begin t_b = B_ELF; t_cd = C_ALL; end            // + e 2^LF: log2
            7'd28: begin t_ia = 1'b1; t_b = B_RF; t_ci = 1'b1; t_cd = C_ALL; end             // la = off - log2 x
            7'd29: t_fl = FL_NEG;                                                            // la < 0
            7'd30: begin t_ia = 1'b1; t_b = B_RF; t_ci = 1'b1; t_fl = FL_BIG; end            // la > LA_MAX
            7'd31: begin t_a = A_ZERO; t_b = B_RF; t_cd = C_BIG; end
            7'd32: begin t_a = A_ZERO; t_cd = C_ZLA; end
            P_LOG_S: begin t_rw = 1'b1; t_wa = R_LAV; t_act = X_LGS; end                     // log2 Is
            7'd44: begin t_b = B_RF; t_ib = 1'b1; t_ci = 1'b1; t_cd = C_ALL; end             // lis = log2 Is - frac
            7'd45: begin t_a = A_ZERO; t_cd = C_ALL; t_rw = 1'b1; t_wa = R_LIS; end
            P_HORNER, P_HORNER + 7'd1, P_HORNER + 7'd2, P_HORNER + 7'd3, P_HORNER + 7'd4, P_HORNER + 7'd5,
            P_HORNER + 7'd6, P_HORNER + 7'd7, P_HORNER + 7'd8, P_HORNER + 7'd9:
                begin t_a = A_SHL; t_b = B_RF; t_g = 1'b1; t_cd = C_ALL; end                  // 2 ACC + n_k la_v
            7'd56: begin t_b = B_RF; t_ib = 1'b1; t_ci = 1'b1; t_cd = C_ALL; end             // p = n la - lis
            P_EXP: begin t_ib = 1'b1; t_fl = FL_SAT; t_act = X_TABE; end                     // p <= 0; word j
            7'd58: t_act = X_TAB1;
            7'd59: t_act = X_W0;
            7'd60: begin t_a = A_ZERO; t_b = B_W0; t_cd = C_ALL; end
            7'd61: begin t_b = B_TABW; t_ib = 1'b1; t_ci = 1'b1; t_cd = C_ALL; end           // tdiff
            7'd63: begin t_a = A_ZERO; t_b = B_TPH; t_ci = 1'b1; t_cd = C_ALL; end
            7'd64: begin t_a = A_SHR; t_ia = 1'b1; t_b = B_W0; t_ci = 1'b1; t_cd = C_ALL; end   // 2^-f
            7'd65: begin t_a = A_SHR; t_act = X_SHIFT; end                                   // >> (shift - 1)
            7'd66: begin t_ci = 1'b1; t_cd = C_ALL; end                                      // + 1
            7'd67: begin t_a = A_SHR; t_cd = C_ALL; end                                      // >> 1
            P_OUT: t_act = X_OUT;
            default: ;                                                                       // products (24, 40, 62)
        endcase
    end
    generate
        if (N_W != 10) begin : g_n_w   // the program has ten multiplication steps (P_HORNER .. 55)
            spec_parameter_error_setup_backend_needs_N_W_10 program_has_ten_multiplication_steps ();
        end
    endgenerate
    // the register file word each step reads (addressed one step ahead)
    function [3:0] ra_of(input [6:0] p, input fl);
        begin
            case (p)
                7'd4, 7'd13: ra_of = R_GAM;
                7'd6, 7'd9, 7'd15: ra_of = R_Z0;
                7'd7, 7'd8: ra_of = R_PI;
                7'd10, 7'd11: ra_of = R_2PI;
                7'd12: ra_of = R_HPI;
                7'd14: ra_of = R_HPIM1;
                7'd16: ra_of = R_S2;
                7'd28: ra_of = fl ? R_OFFF : R_OFF;
                7'd30, 7'd31: ra_of = R_LAMAX;
                7'd44: ra_of = R_STRF;
                P_LOG_S + 7'd3, P_OUT: ra_of = R_ZETA;
                7'd56: ra_of = R_LIS;
                default: ra_of = R_LAV;                                                      // the products
            endcase
        end
    endfunction

    // ---- the table lookups: log2 operand normalized a bit a clock, tables, interpolation product ------------------
    reg [F+1:0] lgx;
    reg [5:0] lg_e;
    wire [TB-1:0] lg_j = lgx[F -: TB];
    wire [RB-1:0] lg_r = lgx[F-TB -: RB];
    wire unused_lgx;
    assign unused_lgx = &{1'b0, lgx[F-TB-RB:0]};
    reg [TB-1:0] tab_a;
    reg [RB-1:0] tr;
    reg last;                               // word j + 1 is past the table: a constant
    reg [EF:0] w0;
    wire [LF-1:0] lg_w;
    wire [EF:0] ex_w;
    spec_rom #(.AW(TB), .DW(LF), .INIT_FILE(LOG2_FILE)) u_log2 (.clk(clk), .en(1'b1), .addr(tab_a), .data(lg_w));
    spec_rom #(.AW(TB), .DW(EF + 1), .INIT_FILE(EXP2_FILE)) u_exp2 (.clk(clk), .en(1'b1), .addr(tab_a), .data(ex_w));
    reg tsel_exp;                           // pc >= P_EXP (a register, loaded with pc)
    // the table word for B (a register: read two steps after its address, so one clock later is in time)
    reg [EF:0] tabw;
    always @(posedge clk)
        tabw <= tsel_exp ? (last ? (1 << (EF - 1)) : ex_w) : (last ? (1 << LF) : {{(EF + 1 - LF) {1'b0}}, lg_w});
    reg [EF+RB:0] tprod;
    always @(posedge clk) tprod <= acc[EF:0] * tr;   // a DSP with its output register

    // ---- the ALU -------------------------------------------------------------------------------------------------
    reg flat, f_hi, f_lo, f_a, f_b, f_neg, f_big, sat, xpos, big;
    reg [5:0] sc;                           // the rounding shift of the C code, less one
    wire [6:0] hidx = P_HORNER + N_W[6:0] - 7'd1 - pc1;  // the exponent bit of the next multiplication step
    reg nb;                                 // the exponent bit of this one (a register, loaded with pc)
    reg signed [PW-1:0] opa, opb;
    always @* begin
        case (c_a)
            A_ACC: opa = acc;
            A_ZERO: opa = {PW{1'b0}};
            A_SHL: opa = acc <<< 1;
            default: opa = acc >>> 1;
        endcase
        case (c_b)
            B_RF: opb = (c_g && !nb) ? {PW{1'b0}} : rd;
            B_LZ: opb = {{(PW - ZW) {lz[ZW-1]}}, lz};
            B_TABW: opb = {{(PW - EF - 1) {1'b0}}, tabw};
            B_W0: opb = {{(PW - EF - 1) {1'b0}}, w0};
            B_TPH: opb = {{(PW - EF - 2) {1'b0}}, tprod[EF+RB:RB-1]};
            B_ELF: opb = {{(PW - LF - 6) {1'b0}}, lg_e, {LF{1'b0}}};
            B_LSH: opb = {{(PW - L_W - S + 1) {1'b0}}, s_l, {(S - 1) {1'b0}}};
            default: opb = {PW{1'b0}};
        endcase
    end
    // A step of the ALU takes three clocks (bph 0, 1, 2): the operands (selected, inverted) into registers, their
    // low halves added (the carry registered), the high halves added; the step acts in its last clock (stp). The
    // steps that do not use the ALU (idle, normalize, shift, output) take one clock each. The operand and
    // low-half registers run free: a step's inputs hold through its clocks.
    localparam PL = PW / 2;
    reg [PW-1:0] oa, ob;
    reg [PL-1:0] sum_lo;
    reg sum_cy;
    reg [1:0] bph;
    always @(posedge clk) begin
        oa <= opa ^ {PW{c_ia}};
        ob <= opb ^ {PW{c_ib}};
        {sum_cy, sum_lo} <= {1'b0, oa[PL-1:0]} + {1'b0, ob[PL-1:0]} + {{PL{1'b0}}, c_ci};
    end
    wire [PW-PL-1:0] sum_hi = oa[PW-1:PL] + ob[PW-1:PL] + {{(PW - PL - 1) {1'b0}}, sum_cy};
    wire [PW-1:0] sum = {sum_hi, sum_lo};
    wire neg = sum[PW-1];
    // the step's kind, registers loaded with c_act (one-clock steps; the actions that may hold the program),
    // and the ALU step's last clock (ph2 = bph is 2)
    reg a_fast, a_idle, a_div, a_norm, a_shift, a_out, ph2;
    wire stp = a_fast || ph2;
    reg cond;
    always @* begin
        case (c_cd)
            C_ALL: cond = 1'b1;
            C_HI: cond = f_hi;
            C_LO: cond = f_lo;
            C_BIG: cond = f_big;
            C_ZLA: cond = !xpos || f_neg;
            C_ZETA: cond = !s_bad && !flat;
            default: cond = 1'b0;
        endcase
    end
    // ACC's write enables without the program's hold logic in front: only an ALU step with a condition (c_cd not
    // C_NO; never a one-clock step) writes the sum, in its last clock, and of the holds only the divider's can
    // stop it; the control word and the flags and tests the condition reads change only in a step's last clock,
    // so the enable is a register loaded in the clock before (acc_en_pre). The shift step writes ACC >>> 1
    // (a_shift: c_act is X_SHIFT; sc_nz: sc is not 0).
    reg acc_en_pre;

    // ---- divider: dzeta = floor((gamma + l 2^(S-1)) / (l 2^S)), a quotient bit a clock (SetupModel::divide) --------
    localparam DW = L_W + S;
    reg [DW-1:0] drem;
    reg [ZW-1:0] dnq;                       // numerator bits left above the quotient bits made
    reg [5:0] dcnt;
    wire [DW:0] dsh = {drem, dnq[ZW-1]};
    wire [DW+1:0] ddif = {1'b0, dsh} - {2'b00, s_l, {S{1'b0}}};
    wire dge = !ddif[DW+1];
    reg div_done;                           // dcnt == ZW (a register kept with dcnt)

    // ---- control -------------------------------------------------------------------------------------------------
    // registers (free-running) of the inputs' tests and of the output words: c1 and mag hold from the angles on,
    // the output words' inputs from the output step on, which waits a clock for them (out_rdy)
    reg c1_pos, mag_pos, out_rdy;
    reg flat_q;                             // the flat test of lz and s_l (step 1 takes it into flat)
    // lz < FLAT_Z: for FLAT_Z = 2^FK (the generator's 2^FLAT_LOG2 in angle-lane units) "negative, or no bit at
    // FK or above", no carry chain; any other FLAT_Z, the comparison
    localparam integer FK = $clog2(FLAT_Z);
    wire lz_small;
    generate
        if (FLAT_Z > 1 && FLAT_Z < (1 << (ZW - 2)) && FLAT_Z == (1 << FK)) begin : g_flat_pow2
            assign lz_small = lz[ZW-1] || (lz[ZW-2:FK] == {(ZW - 1 - FK) {1'b0}});
        end else begin : g_flat_cmp
            assign lz_small = lz < FLAT_Z;
        end
    endgenerate
    reg [C_W-1:0] c_out;
    reg [6:0] f_out;
    wire nohl = (s_n != {N_W{1'b0}}) && (flat ? !c1_pos : (f_a || f_b));
    wire zero_c = s_bad || nohl || (s_str == {STR_W{1'b0}}) || ((s_n != {N_W{1'b0}}) && !xpos);
    reg lge_nz, sc_nz, lam_q;               // lg_e != 0, sc != 0 (registers kept with them); lam_ok a clock later
    wire norm_more = !lgx[F+1] && lge_nz;
    wire hold = (a_idle && !start) || (a_div && !lam_q) || (a_norm && norm_more) || (a_shift && sc_nz) ||
                (a_out && !(m_tvalid && m_tready));
    wire adv = stp && !hold;                // the program moves on (to pc1, or to 0 after the output step)
    wire wrap = a_out;
    function [5:0] kind_of(input [3:0] act);   // {fast, idle, div, norm, shift, out}
        kind_of = {act == X_IDLE || act == X_NORM || act == X_SHIFT || act == X_OUT, act == X_IDLE, act == X_DIV,
                   act == X_NORM, act == X_SHIFT, act == X_OUT};
    endfunction
    wire [6:0] pc_next = wrap ? 7'd0 : pc1;
    wire [PW-LF-1:0] p_i = acc[PW-1:LF];
    wire [5:0] sc_init = EF - C_W - 1 + {1'b0, p_i[4:0]};
    wire [C_W-1:0] ccode = big ? {C_W{1'b0}} : (|acc[PW-1:C_W]) ? {C_W{1'b1}} : acc[C_W-1:0];
    always @(posedge clk) begin
        c1_pos <= !c1[W-1] && c1 != {W{1'b0}};
        flat_q <= (s_l == {L_W{1'b0}}) || lz_small;
        mag_pos <= !mag[W-1] && mag != {W{1'b0}};
        out_rdy <= c_act == X_OUT;
        c_out <= zero_c ? {C_W{1'b0}} : sat ? {C_W{1'b1}} : ccode;
        f_out <= s_bad ? {1'b1, 2'b00, s_l == {L_W{1'b0}}, 3'b000}
                       : {1'b0, s_rule, nohl, s_l == {L_W{1'b0}}, !zero_c && sat, s_opp, flat};
    end
    // m_c and m_flags are the free-running registers c_out and f_out: their inputs hold from the output step's
    // first clock (out_rdy is a clock later) until the handover, so they hold while m_tvalid is 1
    assign m_c = c_out;
    assign m_flags = f_out;
    assign m_n = s_n;
    assign m_l = s_l;
    assign m_dzeta = dnq[ANG_W-1:0];
    assign m_zeta0 = rd[S +: ANG_W];         // word R_ZETA while the descriptor waits (step P_OUT)
    wire unused_bits;
    assign unused_bits = &{1'b0, tprod[RB-2:0], hidx[6:4], dnq[ZW-1:ANG_W], rd[PW-1:S+ANG_W], rd[S-1:0]};

    // the register file: a registered read of the next step's word, addressed in the last clock of an ALU step
    // (the steps after the one-clock steps read no word; the output step's word stays in rd); a step's write
    // takes ACC before the step (ACC holds through the step's clocks)
    reg [3:0] ra_q;
    assign rf_ra = ph2 ? ra_of(pc1, flat) : ra_q;
    // write and read in separate processes: a word is read at the earliest two steps after its write, so no
    // read-during-write relation is needed (a word read in a clock it is written is never used; checked in
    // simulation by making such reads X: the descriptors stay the same bit for bit); no_rw_check tells Yosys so,
    // else it keeps the old word with a second register stage on the write port and the read register outside
    // the block RAM
    always @(posedge clk) if (c_rw) rf[c_wa] <= acc;
    always @(posedge clk) rd <= rf[rf_ra];

    always @(posedge clk) begin
        done <= 1'b0;
        acc_en_pre <= !rst && !stp && bph == 2'd1 && c_cd != C_NO && cond;
        ra_q <= rf_ra;
        lam_q <= lam_ok;
        if (rst) begin
            pc1 <= 7'd1;
            bph <= 2'd0;
            ph2 <= 1'b0;
            {c_a, c_ia, c_ib, c_ci, c_b, c_g, c_cd, c_fl, c_rw, c_wa, c_act} <=
                {A_ACC, 1'b0, 1'b0, 1'b0, B_ZERO, 1'b0, C_NO, FL_NO, 1'b0, R_Z0, X_IDLE};
            {a_fast, a_idle, a_div, a_norm, a_shift, a_out} <= kind_of(X_IDLE);
            nb <= 1'b0;
            tsel_exp <= 1'b0;
            m_tvalid <= 1'b0;
            dcnt <= ZW[5:0];
            div_done <= 1'b1;
        end else begin
            if (m_tvalid && m_tready) m_tvalid <= 1'b0;
            bph <= stp ? 2'd0 : bph + 2'd1;
            ph2 <= !stp && bph == 2'd1;
            if (adv) begin
                pc1 <= pc_next + 7'd1;
                if (wrap) begin
                    {c_a, c_ia, c_ib, c_ci, c_b, c_g, c_cd, c_fl, c_rw, c_wa, c_act} <=
                        {A_ACC, 1'b0, 1'b0, 1'b0, B_ZERO, 1'b0, C_NO, FL_NO, 1'b0, R_Z0, X_IDLE};
                    {a_fast, a_idle, a_div, a_norm, a_shift, a_out} <= kind_of(X_IDLE);
                end else begin
                    {c_a, c_ia, c_ib, c_ci, c_b, c_g, c_cd, c_fl, c_rw, c_wa, c_act} <=
                        {t_a, t_ia, t_ib, t_ci, t_b, t_g, t_cd, t_fl, t_rw, t_wa, t_act};
                    {a_fast, a_idle, a_div, a_norm, a_shift, a_out} <= kind_of(t_act);
                end
                nb <= s_n[hidx[3:0]];
                tsel_exp <= !wrap && pc1 >= P_EXP;
            end
            if (acc_en_pre && !(a_div && !lam_q)) acc <= sum;
            if (a_shift && sc_nz) begin
                acc <= acc >>> 1;   // the step's sum (A = ACC >>> 1, B = 0): no ALU needed
                sc <= sc - 6'd1;
                sc_nz <= sc != 6'd1;
            end
            if (stp) case (c_fl)
                FL_HI: f_hi <= !neg;
                FL_LO: f_lo <= neg;
                FL_A: f_a <= !neg;
                FL_B: f_b <= neg;
                FL_NEG: f_neg <= neg;
                FL_BIG: f_big <= neg;
                FL_SAT: sat <= neg;
                default: ;
            endcase
            if (stp) case (c_act)
                // lz holds gamma from the start until the lambda run begins (4 clocks), and flat is first read by
                // step 3: step 1 (3 clocks) takes the registered test in its last clock
                X_FLAT: flat <= flat_q;
                X_LGX, X_LGS: begin
                    lgx <= (c_act == X_LGS) ? {{(F + 2 - STR_W) {1'b0}}, s_str} : flat ? c1[F+1:0] : mag[F+1:0];
                    lg_e <= F + 1;
                    lge_nz <= 1'b1;
                    if (c_act == X_LGX) xpos <= flat ? c1_pos : mag_pos;
                end
                X_NORM: begin
                    if (norm_more) begin
                        lgx <= {lgx[F:0], 1'b0};
                        lg_e <= lg_e - 6'd1;
                        lge_nz <= lg_e != 6'd1;
                    end
                end
                X_TABL: begin
                    tab_a <= lg_j;
                    tr <= lg_r;
                end
                X_TABE: begin
                    tab_a <= acc[LF-1 -: TB];
                    tr <= acc[LF-TB-1 -: RB];
                    big <= p_i > C_W + 1;
                    sc <= sc_init;
                    sc_nz <= sc_init != 6'd0;
                end
                // w0 = word j, read while this step's three clocks run (the address is word j + 1 afterwards)
                X_TAB1: begin
                    tab_a <= tab_a + 1'b1;
                    last <= &tab_a;
                    w0 <= tsel_exp ? ex_w : {{(EF + 1 - LF) {1'b0}}, lg_w};
                end
                X_OUT: begin
                    if (m_tvalid && m_tready) done <= 1'b1;
                    if (div_done && out_rdy && !m_tvalid && !done) m_tvalid <= 1'b1;
                end
                default: ;
            endcase
            // the divider: started by step X_DIV with the numerator in ACC (in its first clock, again while the
            // step waits for lambda), then runs beside the program
            if (a_div && bph == 2'd0) begin
                // a zero vector or a flat span: dzeta = 0, no division
                drem <= {DW{1'b0}};
                dnq <= (s_bad || flat) ? {ZW{1'b0}} : acc[ZW-1:0];
                dcnt <= (s_bad || flat) ? ZW[5:0] : 6'd0;
                div_done <= s_bad || flat;
            end else if (!div_done) begin
                drem <= dge ? ddif[DW-1:0] : dsh[DW-1:0];
                dnq <= {dnq[ZW-2:0], dge};
                dcnt <= dcnt + 6'd1;
                div_done <= dcnt == ZW[5:0] - 6'd1;
            end
        end
    end
endmodule
`default_nettype wire
