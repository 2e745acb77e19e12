// spec_setup_engine - spec_setup's arithmetic one span at a time through shared units, for small FPGAs
// (the iCE40 UP5K; docs/setup.md): the vectors in a memory (block RAM), one CORDIC lane (two coordinates,
// the angle lane, the gain adder for the third coordinate) for the passes and the angles, then
// spec_setup_backend (one adder driven by a micro-program) for everything after the angles. The same integer
// operations as spec_setup_pipe in the same order, so the same descriptors and flags bit for bit
// (SetupModel::run).
//
// A pass with k lanes is k runs of the lane: the driving vector first (its micro-rotation directions are
// recorded), then each follower replaying them. A run: read a, b and the third coordinate t of one vector and
// load them (8 clocks), the turn before the micro-rotations if any (3 clocks a quarter turn), ITERS
// micro-rotations with the gain terms of t added beside them (3 clocks each), write a, b, t back (5 clocks;
// not for the angle runs). The runs (P1..Q1, the angles) are the table `run_*` below. The back end starts when
// gamma is in the angle lane and takes lambda when the last run is done.
//
// Timing (issue 13, docs/setup.md): every adder of the lane has registers only in front (the run's fields, the
// shifted and direction-folded operands, the gain term, the loads and turns through the same operand
// registers and a synchronous clear of the pair), the angle lane's adder is split in halves with a registered
// carry, and the load's shift, tests and words are registered, at the price of clocks per span.
//
// Handshake: s_tready is 1 while idle (a register); m_tvalid and the output fields are registers and hold until
// m_tready; the next span is taken once the descriptor has been handed over. rst: back to idle, output empty.
`timescale 1ns / 1ps
`default_nettype none
`include "setup_small_params.vh"
`include "spec_params.vh"
module spec_setup_engine #(
    parameter VEC_W = `SMALL_VEC_W,
    parameter F = `SMALL_F,
    parameter W = `SMALL_W,
    parameter ITERS = `SMALL_ITERS,
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
    input  wire         clk,
    input  wire         rst,
    input  wire                s_tvalid,
    output reg                 s_tready,
    input  wire [12*VEC_W-1:0] s_vec,      // N1, N2, H1, H2; x, y, z each (x lowest)
    input  wire [STR_W-1:0]    s_str,
    input  wire [N_W-1:0]      s_n,
    input  wire [L_W-1:0]      s_l,
    input  wire                s_rule,
    output wire                m_tvalid,
    input  wire                m_tready,
    output wire [C_W-1:0]      m_c,
    output wire [N_W-1:0]      m_n,
    output wire [L_W-1:0]      m_l,
    output wire [ANG_W-1:0]    m_zeta0,
    output wire [ANG_W-1:0]    m_dzeta,
    output wire [6:0]          m_flags
);
    localparam NRUN = 24;
    localparam [ITERS*ZW-1:0] ATAN = `SMALL_ATAN;
    localparam [8*`SMALL_GAIN_N-1:0] GSH = `SMALL_GAIN_SHIFT;
    localparam [`SMALL_GAIN_N-1:0] GNEG = `SMALL_GAIN_NEG;
    localparam [8*`SMALL_HALF_N-1:0] HSH = `SMALL_HALF_SHIFT;
    localparam [`SMALL_HALF_N-1:0] HNEG = `SMALL_HALF_NEG;
    localparam signed [ZW-1:0] HALF_PI = `SMALL_HALF_PI;
    localparam [W-1:0] U = `SMALL_N1_START;
    localparam signed [W-1:0] TAU = `SMALL_OPP_TAU;

    // ---- the runs: vector, plane (0: a = x, b = y, t = z; 1: a = z, b = x, t = y), role, halving -----------
    // vectors: 0 N1, 1 N2, 2 H1, 3 H2, 4 P (perpendicular(N1)), 5 N1 of the H1 frame ("M1")
    // roles: 0 drive (frame), 1 follow, 2 drive with the angle lane
    // the runs, 7 bits each {vector, plane, role, halving}, run 0 in the lowest bits (a ROM in LUTs):
    //    0: P1 N1     vector 0, plane (x,y), drive
    //    1: N2        vector 1, plane (x,y), follow
    //    2: H1        vector 2, plane (x,y), follow
    //    3: H2        vector 3, plane (x,y), follow
    //    4: P         vector 4, plane (x,y), follow
    //    5: P2 N1     vector 0, plane (z,x), drive, halving
    //    6: N2        vector 1, plane (z,x), follow, halving
    //    7: H1        vector 2, plane (z,x), follow, halving
    //    8: H2        vector 3, plane (z,x), follow, halving
    //    9: P         vector 4, plane (z,x), follow, halving
    //   10: P3 N2     vector 1, plane (x,y), drive, halving
    //   11: H1        vector 2, plane (x,y), follow, halving
    //   12: H2        vector 3, plane (x,y), follow, halving
    //   13: P4 N2     vector 1, plane (z,x), drive
    //   14: H2        vector 3, plane (z,x), follow
    //   15: G1 H1     vector 2, plane (x,y), drive, halving
    //   16: H2        vector 3, plane (x,y), follow, halving
    //   17: G2 H1     vector 2, plane (z,x), drive, halving
    //   18: H2        vector 3, plane (z,x), follow, halving
    //   19: M1        vector 5, plane (z,x), follow, halving
    //   20: Q1 H2     vector 3, plane (x,y), drive, halving
    //   21: M1        vector 5, plane (x,y), follow, halving
    //   22: gamma     vector 3, plane (z,x), angle
    //   23: lambda    vector 5, plane (z,x), angle
    localparam [7*NRUN-1:0] RUNS = 168'hb8f29b1b6ed4b342e8c3346465bb566c4c26488900;
    reg [4:0] run;
    // the current run's fields and the run tests below are registers, loaded with the run number (the table is
    // read at the next run's number one clock ahead), so that no adder sees run -> table -> select
    reg [6:0] run_fields;
    reg [4:0] run_tests;
    wire [2:0] run_vec;
    wire run_plane, run_halve;
    wire [1:0] run_role;
    wire run_p2n2, run_p2p, run_p3n2, run_gamma, run_last;   // runs 6, 9, 10, 22, NRUN - 1
    assign {run_vec, run_plane, run_role, run_halve} = run_fields;
    assign {run_p2n2, run_p2p, run_p3n2, run_gamma, run_last} = run_tests;
    function [4:0] tests_of(input [4:0] r);
        tests_of = {r == 5'd6, r == 5'd9, r == 5'd10, r == 5'd22, r == NRUN - 1};
    endfunction

    localparam ST_IDLE = 3'd0, ST_LOAD = 3'd1, ST_RD = 3'd2, ST_ROT = 3'd3, ST_WR = 3'd4, ST_BE = 3'd5;
    reg [2:0] st;
    reg [4:0] it;                         // micro-rotation
    reg [1:0] rph;                        // its clock: 0 coarse shift, 1 fine shift, 2 sums
    reg [1:0] qt;                         // quarter turns left before the micro-rotations
    wire [4:0] run_nx = (st == ST_LOAD) ? 5'd0 : run + 5'd1;   // the run that a run change loads

    // ---- vector memory: address = vector * 4 + coordinate (0 x, 1 y, 2 z) -----------------------------------
    // No word read in the clock it is written is ever used (the read address stays on the word being written
    // back or loaded; checked in simulation by making such reads X: the small shader's descriptors and pixels
    // stay the same bit for bit). no_rw_check tells Yosys so: without it, Yosys keeps the old word on a collision
    // with a second register stage on the write port and the read register outside the block RAM (about 60
    // flip-flops without a LUT in front).
    (* no_rw_check *) reg [W-1:0] vmem[0:31];
    reg [4:0] v_ra, v_wa;
    reg v_we;
    reg [W-1:0] v_wd, v_rd;
    always @(posedge clk) if (v_we) vmem[v_wa] <= v_wd;
    always @(posedge clk) v_rd <= vmem[v_ra];
    // the coordinates of a, b, t for the current run
    wire [1:0] ca = run_plane ? 2'd2 : 2'd0;
    wire [1:0] cb = run_plane ? 2'd0 : 2'd1;
    wire [1:0] ct = run_plane ? 2'd1 : 2'd2;

    // ---- span registers ------------------------------------------------------------------------------------
    reg [12*VEC_W-1:0] vec_in;
    reg [STR_W-1:0] s_reg;
    reg [N_W-1:0] n_reg;
    reg [L_W-1:0] l_reg;
    reg rule_reg, bad, exact_opp, opp;

    // the vectors into the vector memory, one component a clock: the input vectors are shifted out of vec_in,
    // every component shifted left by its vector's common amount (SetupModel::prescale) in one shifter; then
    // P = perpendicular(N1) from N1's codes (N1 x e_k, e_k the axis of its smallest component) and M1 = (0, 0, U)
    reg [2:0] ld_v;                       // 0..3: N1, N2, H1, H2; 4: P; 5: M1
    reg [1:0] ld_c;                       // 0: the vector's shift; 1..3: its x, y, z
    // the prescale shift F - 1 - lead is F - VEC_W (wiring) plus VEC_W - 1 - lead, SHB bits
    localparam SHB = (VEC_W <= 16) ? 4 : (VEC_W <= 32) ? 5 : 6;
    reg [SHB-1:0] ld_sh;                  // the variable part of the shift of the vector being loaded
    wire signed [VEC_W-1:0] cx = vec_in[0 +: VEC_W], cy = vec_in[VEC_W +: VEC_W], cz = vec_in[2*VEC_W +: VEC_W];
    // the vector's shift, P's axis and the zero test through three free-running registers (magnitudes; their OR
    // and P's axis; the shift): the vector's first load clock (ld_c = 0) waits for them (ph 0..4)
    reg [VEC_W-1:0] mx, my, mz, mor;       // mor: its leading one is the largest magnitude's
    reg [1:0] pk_q;
    reg [SHB-1:0] sh_q;
    always @(posedge clk) begin
        mx <= cx[VEC_W-1] ? -cx : cx;
        my <= cy[VEC_W-1] ? -cy : cy;
        mz <= cz[VEC_W-1] ? -cz : cz;
        mor <= mx | my | mz;
        pk_q <= (mx <= my && mx <= mz) ? 2'd0 : (my <= mz) ? 2'd1 : 2'd2;
    end
    reg [5:0] lead;
    integer k;
    always @* begin
        lead = 6'd0;
        for (k = 0; k < VEC_W; k = k + 1) if (mor[k]) lead = k[5:0];
    end
    wire signed [W-1:0] ld_ext = {{(W - VEC_W) {cx[VEC_W-1]}}, cx};
    wire signed [W-1:0] ld_word = (ld_ext <<< (F - VEC_W)) <<< ld_sh;
    // P = N1 x e_k (e_k the axis of N1's smallest component, the first of equals): k = x: (0, nz, -ny);
    // k = y: (-nz, 0, nx); k = z: (ny, -nx, 0), from N1's prescaled words (the same shift): component c is 0
    // for c = k, else the remaining axis 3 - k - c of N1, negated for c = k + 2 (mod 3)
    reg [1:0] pk;
    wire [1:0] p_c = ph[1:0] - 2'd3;      // the component written at phase ph (3..5)
    wire [1:0] p_src = 2'd3 - pk - ph[1:0];   // the axis read at phase ph (0..2)
    wire p_neg = p_c == ((pk == 2'd0) ? 2'd2 : pk - 2'd1);
    // the words of the load, registers: a prescaled input component (ld_word a clock after vec_in holds the
    // component: vec_in shifts a clock ahead of the writes), N1's word read and negated (with v_in) for P
    reg signed [W-1:0] ld_wq, v_neg;
    always @(posedge clk) begin
        ld_wq <= ld_word;
        v_neg <= -$signed(v_rd);
    end
    localparam [5:0] VM1 = VEC_W - 1;
    wire [5:0] sh_var = VM1 - lead;       // 0 .. VEC_W - 1
    wire unused_sh = &{1'b0, sh_var};
    always @(posedge clk) sh_q <= sh_var[SHB-1:0];

    // ---- the CORDIC lane -------------------------------------------------------------------------------------
    reg signed [W-1:0] la, lb, acc;       // the pair, the third coordinate's gain sum
    // the angle lane's adder in two halves: the high half adds (with the low half's carry, registered) one clock
    // after the low half; nothing reads lz in that clock (the lane's directions come from the pair)
    localparam ZL = ZW / 2;
    reg signed [ZW-1:0] lz;
    reg lz_cy, lz_hi;                     // the low half's carry; the high half adds in this clock
    reg [ITERS-1:0] drec;                 // the driver's directions (1: rotate by -atan)
    reg neg;                              // the driver's pair was turned by pi
    wire d_now = (run_role == 2'd1) ? drec[0] : ~lb[W-1];
    // The pair's shifter in two register stages (free-running; it and the sources hold through a
    // micro-rotation): cs = src >>> (it & ~3), then op = (cs >>> it[1:0]) ^ x, where x folds the direction in
    // (x - y = x + ~y + 1, the carry in ci is x too). The adders then see registers only: la <= la + op_b + ci_la,
    // lb <= lb + op_a + ci_lb. The loads and the turns go through the same lane with it = 0 and the pair cleared
    // (a synchronous reset) before the sum: a load takes v_in as the source (sel_v*), a quarter turn
    // (la, lb) <= (lb ^ xb + xb, la ^ xa + xa) with xa = d, xb = ~d, i.e. (lb, -la) for d = 1, (-lb, la) for d = 0.
    reg sel_va, sel_vb;                   // the source is v_in (a load), else la / lb
    reg op_xa, op_xb;
    reg ci_la, ci_lb;                     // the carries into la's and lb's adders (x, or the rounding bit)
    reg signed [W-1:0] cs_a, cs_b;
    wire signed [W-1:0] fs_a = cs_a >>> it[1:0];   // (signed on its own: an XOR with x would make it logical)
    wire signed [W-1:0] fs_b = cs_b >>> it[1:0];
    // The gain of the third coordinate (SetupModel::gain_mul: sum of sign * floor(t / 2^shift)) without a barrel
    // shifter: lts runs through t, t >>> 1, t >>> 2, ... (arithmetic shifts compose exactly), one step per
    // micro-rotation, and the term of shift i is added when it is one of the pass's terms. Shift -1 (t * 2) is
    // added as the run starts, shift ITERS as its first write-back clock (the generator keeps the shifts in
    // -1 .. ITERS). gterm / hterm[s + 1] = {is a term, minus} for shift s, the tables of G and G/2.
    function [1:0] term_of(input [8*32-1:0] sh, input [31:0] minus, input integer n, input integer s);
        integer q;
        begin
            term_of = 2'b00;
            for (q = 0; q < n; q = q + 1)
                if ({{24{sh[8*q+7]}}, sh[8*q +: 8]} == s) term_of = {1'b1, minus[q]};
        end
    endfunction
    localparam [8*32-1:0] GSH32 = {{(8 * (32 - `SMALL_GAIN_N)) {1'b0}}, GSH};
    localparam [8*32-1:0] HSH32 = {{(8 * (32 - `SMALL_HALF_N)) {1'b0}}, HSH};
    localparam [31:0] GNEG32 = {{(32 - `SMALL_GAIN_N) {1'b0}}, GNEG};
    localparam [31:0] HNEG32 = {{(32 - `SMALL_HALF_N) {1'b0}}, HNEG};
    wire [1:0] gterm[0:ITERS+1];
    wire [1:0] hterm[0:ITERS+1];
    wire [ZW-1:0] atab[0:31];
    genvar g;
    generate
        for (g = 0; g <= ITERS + 1; g = g + 1) begin : g_terms
            assign gterm[g] = term_of(GSH32, GNEG32, `SMALL_GAIN_N, g - 1);
            assign hterm[g] = term_of(HSH32, HNEG32, `SMALL_HALF_N, g - 1);
        end
        for (g = 0; g < 32; g = g + 1) begin : g_atab
            assign atab[g] = (g < ITERS) ? ATAN[(g % ITERS)*ZW +: ZW] : {ZW{1'b0}};
        end
    endgenerate
    reg signed [W-1:0] lts;               // t >>> it during the micro-rotations
    // the micro-rotation's term, looked up a clock ahead (a free-running register: it and the run hold from a
    // micro-rotation's first clock on, and op_t takes the term in its second), so no table is in front of op_t
    reg [1:0] tc_rot;
    always @(posedge clk) tc_rot <= run_halve ? hterm[it + 1] : gterm[it + 1];
    wire [1:0] tc_first = run_halve ? hterm[0] : gterm[0];
    wire [1:0] tc_last = run_halve ? hterm[ITERS + 1] : gterm[ITERS + 1];
    wire [ZW-1:0] atan_i = atab[it];

    // ---- control ----------------------------------------------------------------------------------------------------
    reg [3:0] ph;                         // phase within a state
    // vec_in takes the beat in every idle clock (so it holds the accepted one when the load starts) and shifts
    // to the next component at phase 4 of an input vector's first load clock and after its x and y (three shifts
    // a vector); the shift's enable is a register loaded a clock ahead, so vec_in's 192 enables see two
    // registers and the state's decode only (nothing reads vec_in outside the load)
    reg vin_sh;
    always @(posedge clk) begin
        vin_sh <= !rst && st == ST_LOAD && ld_v < 3'd4 && ((ld_c == 2'd0 && (ph == 4'd3 || ph == 4'd4)) || ld_c == 2'd1);
        if (st == ST_IDLE) vec_in <= s_vec;
        else if (vin_sh) vec_in <= {{VEC_W{1'b0}}, vec_in[12*VEC_W-1:VEC_W]};
    end
    reg be_start;                         // the back end starts (one clock)
    wire be_done;
    // a coordinate rounded to half, (v + 1) >>> 1 = (v >>> 1) + v[0]: the shift here, the bit (v_rnd) is the
    // carry into the pair's adder as the word is loaded
    wire signed [W-1:0] v_half = $signed(v_rd) >>> 1;
    // the word read, rounded to half for a halving run (a free-running register)
    reg signed [W-1:0] v_in;
    reg v_rnd;
    always @(posedge clk) begin
        v_in <= run_halve ? v_half : $signed(v_rd);
        v_rnd <= run_halve & v_rd[0];
    end
    // the opposite test, rho2 * OPP_K, a free-running register (the DSP's output register): read at ST_WR's
    // phase 2, two clocks after the pair's last sum
    reg signed [W+9:0] rho2k;
    always @(posedge clk) rho2k <= $signed(la) * `SMALL_OPP_K;
    // the pair's operands (shifter stages, free-running), the angle lane's operand (set at rph 0) and the third
    // coordinate's gain term (or 0) with its carry in (set at rph 1)
    reg signed [W-1:0] op_a, op_b, op_t;
    reg signed [ZW-1:0] op_z;
    reg op_d, op_tc, op_zc;
    always @(posedge clk) begin
        cs_a <= (sel_va ? v_in : la) >>> {it[4:2], 2'b00};
        cs_b <= (sel_vb ? v_in : lb) >>> {it[4:2], 2'b00};
        op_a <= fs_a ^ {W{op_xa}};
        op_b <= fs_b ^ {W{op_xb}};
    end
    // rho2 * OPP_K < -z2 as the sign of rho2 * OPP_K + z2; |x| < TAU as -TAU < x < TAU (no negations)
    wire signed [W+10:0] opp_sum = {rho2k[W+9], rho2k} + {{11{acc[W-1]}}, acc};
    reg lb_small, acc_small;              // registers (free-running): read at ST_WR's phase 3
    // TAU = 2^TK (the generator's 2^(F + opp_tau_log2)): -TAU < x < TAU is "the bits above TK - 1 all 0, or all 1
    // with a nonzero bit below", no comparator; any other TAU, the comparisons
    localparam integer TK = $clog2(TAU);
    generate
        if (TAU > 1 && TAU < (1 << (W - 2)) && TAU == (1 << TK)) begin : g_tau_pow2
            always @(posedge clk) begin
                lb_small <= (lb[W-1:TK] == {(W - TK) {1'b0}}) || (&lb[W-1:TK] && |lb[TK-1:0]);
                acc_small <= (acc[W-1:TK] == {(W - TK) {1'b0}}) || (&acc[W-1:TK] && |acc[TK-1:0]);
            end
        end else begin : g_tau_cmp
            always @(posedge clk) begin
                lb_small <= (lb < TAU) && (lb > -TAU);
                acc_small <= (acc < TAU) && (acc > -TAU);
            end
        end
    endgenerate

    // the pair's registers: a synchronous clear (ST_RD's first clock, a turn's second) and the sums (ST_RD's
    // phases 5 and 6, a micro-rotation's or turn's third clock), nothing else, so the clear maps to the flip-flops'
    // reset and the adders' sums go straight into them
    wire pair_clr = !rst && ((st == ST_RD && ph == 4'd0) || (st == ST_ROT && rph == 2'd1 && qt != 2'd0));
    wire la_add = !rst && ((st == ST_RD && ph == 4'd5) || (st == ST_ROT && rph == 2'd2));
    wire lb_add = !rst && ((st == ST_RD && ph == 4'd6) || (st == ST_ROT && rph == 2'd2));
    always @(posedge clk) begin
        if (pair_clr) la <= {W{1'b0}};
        else if (la_add) la <= la + op_b + {{(W - 1) {1'b0}}, ci_la};
        if (pair_clr) lb <= {W{1'b0}};
        else if (lb_add) lb <= lb + op_a + {{(W - 1) {1'b0}}, ci_lb};
    end

    always @(posedge clk) begin
        v_we <= 1'b0;
        be_start <= 1'b0;
        lz_hi <= 1'b0;
        if (lz_hi) lz[ZW-1:ZL] <= lz[ZW-1:ZL] + op_z[ZW-1:ZL] + {{(ZW - ZL - 1) {1'b0}}, lz_cy};
        if (rst) begin
            st <= ST_IDLE;
            s_tready <= 1'b0;
        end else begin
            case (st)
                ST_IDLE: begin
                    s_tready <= 1'b1;
                    if (s_tvalid && s_tready) begin
                        s_tready <= 1'b0;
                        run_fields <= RUNS[6:0];   // run 0 (not halving) while the load reads P's words by v_in
                        s_reg <= s_str;
                        n_reg <= s_n;
                        l_reg <= s_l;
                        rule_reg <= s_rule;
                        bad <= 1'b0;
                        ld_v <= 3'd0;
                        ld_c <= 2'd0;
                        ph <= 4'd0;
                        st <= ST_LOAD;
                    end
                end
                // write the prescaled vectors (and P, and M1 = (0, 0, U)) into the vector memory
                ST_LOAD: begin
                    if (ld_v == 3'd4) begin
                        // P: read N1's words at phases 0..2, write P's at 3..5 (the read and v_in / v_neg take
                        // three clocks; v_in is the word itself: run_fields are run 0's, not halving)
                        ph <= ph + 4'd1;
                        if (ph < 4'd3) v_ra <= {3'd0, p_src};
                        if (ph >= 4'd3) begin
                            v_we <= 1'b1;
                            v_wa <= {3'd4, p_c};
                            v_wd <= (p_c == pk) ? {W{1'b0}} : p_neg ? v_neg : v_in;
                        end
                        if (ph == 4'd5) begin
                            ph <= 4'd0;
                            ld_v <= 3'd5;
                        end
                    end else if (ld_c == 2'd0) begin
                        // the vector's shift (input vectors) from its components' leading one
                        // (phase 3: the shift; phase 4: ld_wq holds the x word, vec_in moves on to y)
                        ph <= ph + 4'd1;
                        if (ph == 4'd3) begin
                            ld_sh <= sh_q;
                            if (ld_v == 3'd0) pk <= pk_q;
                            if (ld_v < 3'd4 && mor == {VEC_W{1'b0}}) bad <= 1'b1;
                        end
                        if (ph == 4'd4) begin
                            ph <= 4'd0;
                            ld_c <= 2'd1;
                        end
                    end else begin
                        v_we <= 1'b1;
                        v_wa <= {ld_v, ld_c - 2'd1};
                        v_wd <= (ld_v == 3'd5) ? ((ld_c == 2'd3) ? U : {W{1'b0}}) : ld_wq;
                        if (ld_c == 2'd3) begin
                            ld_c <= 2'd0;
                            ld_v <= ld_v + 3'd1;
                            if (ld_v == 3'd5) begin
                                run <= run_nx;
                                run_fields <= RUNS[run_nx*7 +: 7];
                                run_tests <= tests_of(run_nx);
                                ph <= 4'd0;
                                st <= bad ? ST_BE : ST_RD;
                                be_start <= bad;
                            end
                        end else begin
                            ld_c <= ld_c + 2'd1;
                        end
                    end
                end
                // read a, b, t of the run's vector (the memory's read is registered: data one clock later)
                // (a word read at phase k is in v_rd at k + 2 and in v_in, rounded to half or not, at k + 3; the
                // negated pair at phase 6)
                ST_RD: begin
                    ph <= ph + 4'd1;
                    case (ph)
                        4'd0: begin
                            v_ra <= {run_vec, ca};
                            it <= 5'd0;
                            lz <= {ZW{1'b0}};
                            op_xa <= 1'b0;
                            op_xb <= 1'b0;
                        end
                        4'd1: v_ra <= {run_vec, cb};
                        4'd2: begin
                            v_ra <= {run_vec, ct};
                            sel_vb <= 1'b1;             // a' (in v_in at phase 3) -> cs_b -> op_b -> la
                        end
                        4'd3: begin
                            sel_vb <= 1'b0;
                            sel_va <= 1'b1;             // b' (in v_in at phase 4) -> cs_a -> op_a -> lb
                            ci_la <= v_rnd;
                        end
                        4'd4: begin
                            sel_va <= 1'b0;
                            ci_lb <= v_rnd;
                        end
                        4'd5: begin
                            // the first gain term (shift -1: t * 2) through the gain adder (at phase 6)
                            lts <= v_rd;
                            acc <= {W{1'b0}};
                            op_t <= tc_first[1] ? (($signed(v_rd) <<< 1) ^ {W{tc_first[0]}}) : {W{1'b0}};
                            op_tc <= tc_first[1] & tc_first[0];
                        end
                        4'd6: begin
                            acc <= acc + op_t + {{(W - 1) {1'b0}}, op_tc};
                        end
                        default: begin
                            // the turn before the micro-rotations: by pi (frame passes; the driver decides,
                            // followers replay; two quarter turns), a quarter turn (angle runs, la < 0)
                            if (run_role == 2'd2) qt <= la[W-1] ? 2'd1 : 2'd0;
                            else qt <= ((run_role == 2'd0) ? la[W-1] : neg) ? 2'd2 : 2'd0;
                            if (run_role == 2'd0) neg <= la[W-1];
                            rph <= 2'd0;
                            st <= ST_ROT;
                        end
                    endcase
                end
                // a micro-rotation in three clocks (rph): the coarse shift, the fine shift with the direction, the
                // sums (an adder each with registers only in front); first the turns (qt) the same way
                ST_ROT: begin
                    rph <= (rph == 2'd2) ? 2'd0 : rph + 2'd1;
                    if (rph == 2'd0) begin
                        if (qt != 2'd0) begin
                            // a quarter turn: the angle runs' by the sign of b (gamma / lambda's quarter), pi as two
                            op_xa <= (run_role == 2'd2) ? ~lb[W-1] : 1'b1;
                            op_xb <= (run_role == 2'd2) ? lb[W-1] : 1'b0;
                            ci_lb <= (run_role == 2'd2) ? ~lb[W-1] : 1'b1;
                            ci_la <= (run_role == 2'd2) ? lb[W-1] : 1'b0;
                            op_z <= (run_role == 2'd2) ? (lb[W-1] ? -HALF_PI : HALF_PI) : {ZW{1'b0}};
                            op_zc <= 1'b0;
                        end else begin
                            op_xa <= d_now;                 // d: lb - as, else lb + as
                            op_xb <= ~d_now;                // d: la + bs, else la - bs
                            ci_lb <= d_now;
                            ci_la <= ~d_now;
                            op_z <= atan_i ^ {ZW{~d_now}};  // d: + atan, else - atan
                            op_zc <= ~d_now;
                            op_d <= d_now;
                        end
                    end else if (rph == 2'd1) begin
                        if (qt == 2'd0) begin
                            // the third coordinate's gain term (tc_rot: the term of this micro-rotation's it)
                            op_t <= tc_rot[1] ? (lts ^ {W{tc_rot[0]}}) : {W{1'b0}};
                            op_tc <= tc_rot[1] & tc_rot[0];
                        end
                    end else begin
                        {lz_cy, lz[ZL-1:0]} <= {1'b0, lz[ZL-1:0]} + {1'b0, op_z[ZL-1:0]} + {{ZL{1'b0}}, op_zc};
                        lz_hi <= 1'b1;
                        if (qt != 2'd0) begin
                            qt <= qt - 2'd1;
                        end else begin
                            // the directions: the driver records them, followers replay them (a rotating register)
                            drec <= {op_d, drec[ITERS-1:1]};
                            acc <= acc + op_t + {{(W - 1) {1'b0}}, op_tc};
                            lts <= lts >>> 1;
                            it <= it + 5'd1;
                            if (it == ITERS - 1) begin
                                st <= ST_WR;
                                ph <= 4'd0;
                            end
                        end
                    end
                end
                ST_WR: begin
                    ph <= ph + 4'd1;
                    v_we <= run_role != 2'd2;   // the angle runs keep their vectors (M1.z stays cos theta1)
                    // the last gain term (shift ITERS) through the pair's operand register and the adder
                    if (ph == 4'd0) begin
                        op_t <= tc_last[1] ? (lts ^ {W{tc_last[0]}}) : {W{1'b0}};
                        op_tc <= tc_last[1] & tc_last[0];
                    end
                    if (ph == 4'd1) acc <= acc + op_t + {{(W - 1) {1'b0}}, op_tc};
                    case (ph)
                        4'd0: begin
                            v_wa <= {run_vec, ca};
                            v_wd <= la;
                            if (run_p3n2 && exact_opp) v_wd <= {W{1'b0}};   // P3: exactly opposite: rho2 := 0
                        end
                        4'd1: begin
                            v_wa <= {run_vec, cb};
                            v_wd <= lb;
                        end
                        4'd2: begin
                            v_wa <= {run_vec, ct};
                            v_wd <= acc;
                        end
                        // after P2's P run: exactly opposite normals take P's (x, y) for N2's
                        4'd3: begin
                            v_we <= run_p2p && exact_opp;
                            v_wa <= {3'd1, 2'd0};
                            v_wd <= lb;
                        end
                        default: begin
                            v_we <= run_p2p && exact_opp;
                            v_wa <= {3'd1, 2'd1};
                            v_wd <= acc;
                        end
                    endcase
                    // The tests below read acc after the last gain term (added at phase 1), as the model's
                    // coordinate: the term (t >>> ITERS, nonzero for a negative t) can move a value across
                    // the threshold (seen with the narrow format, where TAU is 16 units).
                    // P2's N2 run (plane z, x: a = z, b = x, t = y): exactly opposite? (the pair's and acc's tests of
                    // phase 2, registered)
                    if (ph == 4'd3 && run_p2n2) exact_opp <= la[W-1] && lb_small && acc_small;
                    if (ph == 4'd0) begin
                        // gamma is ready in lz: the back end starts (and waits for lambda at its step 3)
                        if (run_gamma) be_start <= 1'b1;
                    end
                    // P3's N2 run (plane x, y: a = rho2, t = z2): the opposite flag
                    if (ph == 4'd2 && run_p3n2) opp <= exact_opp || (acc[W-1] && opp_sum[W+10]);
                    if (ph == 4'd4) begin
                        ph <= 4'd0;
                        if (run_last) begin
                            st <= ST_BE;
                        end else begin
                            run <= run_nx;
                            run_fields <= RUNS[run_nx*7 +: 7];
                            run_tests <= tests_of(run_nx);
                            st <= ST_RD;
                        end
                    end
                end
                // the back end (spec_setup_backend) makes the descriptor; lambda and A stay in lz and la
                ST_BE: begin
                    v_ra <= {3'd5, 2'd2};       // M1.z after Q1 for the back end: cos(theta1) * 2^F / G
                    if (be_done) st <= ST_IDLE;
                end
                // verilator coverage_off
                default: st <= ST_IDLE;   // st has six values; the other two are never reached
                // verilator coverage_on
            endcase
        end
    end

    spec_setup_backend #(
        .F(F), .W(W), .ZW(ZW), .ZF(ZF), .LF(LF), .EF(EF), .TB(TB), .RB(RB), .STR_W(STR_W), .STR_FRAC(STR_FRAC),
        .C_W(C_W), .N_W(N_W), .L_W(L_W), .ANG_W(ANG_W), .ANG_FRAC(ANG_FRAC), .LOG2_FILE(LOG2_FILE), .EXP2_FILE(EXP2_FILE)
    ) u_back (
        .clk(clk), .rst(rst), .start(be_start), .lam_ok(st == ST_BE), .done(be_done), .lz(lz), .mag(la), .c1(v_rd),
        .s_str(s_reg), .s_n(n_reg), .s_l(l_reg), .s_rule(rule_reg), .s_bad(bad), .s_opp(opp),
        .m_tvalid(m_tvalid), .m_tready(m_tready), .m_c(m_c), .m_n(m_n), .m_l(m_l), .m_zeta0(m_zeta0),
        .m_dzeta(m_dzeta), .m_flags(m_flags)
    );
endmodule
`default_nettype wire
