// spec_setup_engine - spec_setup's arithmetic one span at a time through shared units, for small FPGAs
// (the iCE40 UP5K): one CORDIC lane (two coordinates, the angle lane, the gain adder for the third
// coordinate), a vector memory (block RAM), one log2 / exp2 table each read twice per lookup, a multiplier
// for the interpolations, a serial divider. The same integer operations as spec_setup_pipe in the same order,
// so the same descriptors and flags bit for bit (SetupModel::run).
//
// A pass with k lanes is k runs of the lane: the driving vector first (its micro-rotation directions are
// recorded), then each follower replaying them. A run: read a, b and the third coordinate t of one vector
// (3 clocks, + 1 for the memory), ITERS micro-rotations with the gain terms of t added beside them, write
// a, b, t back (3 clocks). The runs (P1..Q1, the angles) are the table `run_*` below.
//
// Handshake: s_tready is 1 while idle (a register); m_tvalid and the output fields are registers and hold until
// m_tready; a finished span waits for the output register to be free. rst: back to idle, output empty.
`timescale 1ns / 1ps
`default_nettype none
`include "setup_params.vh"
`include "spec_params.vh"
module spec_setup_engine #(
    parameter VEC_W = `SETUP_VEC_W,
    parameter F = `SETUP_F,
    parameter W = `SETUP_W,
    parameter ITERS = `SETUP_ITERS,
    parameter ZW = `SETUP_ZW,
    parameter ZF = `SETUP_ZF,
    parameter LF = `SETUP_LF,
    parameter EF = `SETUP_EF,
    parameter TB = `SETUP_TB,
    parameter RB = `SETUP_RB,
    parameter STR_W = `SETUP_STR_W,
    parameter STR_FRAC = `SETUP_STR_FRAC,
    parameter C_W = `SPEC_C_W,
    parameter N_W = `SPEC_N_W,
    parameter L_W = `SPEC_L_W,
    parameter ANG_W = `SPEC_ANG_W,
    parameter ANG_FRAC = `SPEC_ANG_FRAC,
    parameter LOG2_FILE = `SETUP_LOG2_FILE,
    parameter EXP2_FILE = `SETUP_EXP2_FILE
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
    output reg                 m_tvalid,
    input  wire                m_tready,
    output reg  [C_W-1:0]      m_c,
    output reg  [N_W-1:0]      m_n,
    output reg  [L_W-1:0]      m_l,
    output reg  [ANG_W-1:0]    m_zeta0,
    output reg  [ANG_W-1:0]    m_dzeta,
    output reg  [6:0]          m_flags
);
    localparam S = ZF - ANG_FRAC;
    localparam NRUN = 24;
    localparam [ITERS*ZW-1:0] ATAN = `SETUP_ATAN;
    localparam [8*`SETUP_GAIN_N-1:0] GSH = `SETUP_GAIN_SHIFT;
    localparam [`SETUP_GAIN_N-1:0] GNEG = `SETUP_GAIN_NEG;
    localparam [8*`SETUP_HALF_N-1:0] HSH = `SETUP_HALF_SHIFT;
    localparam [`SETUP_HALF_N-1:0] HNEG = `SETUP_HALF_NEG;
    localparam signed [ZW-1:0] HALF_PI = `SETUP_HALF_PI;
    localparam signed [ZW-1:0] PI_Z = `SETUP_PI;
    localparam signed [ZW-1:0] TWO_PI = `SETUP_TWO_PI;
    localparam signed [ZW-1:0] FLAT_Z = `SETUP_FLAT_Z;
    localparam [W-1:0] U = `SETUP_N1_START;
    localparam [W-1:0] TAU = `SETUP_OPP_TAU;

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
    wire [2:0] run_vec;
    wire run_plane, run_halve;
    wire [1:0] run_role;
    assign {run_vec, run_plane, run_role, run_halve} = RUNS[run*7 +: 7];

    // ---- vector memory: address = vector * 4 + coordinate (0 x, 1 y, 2 z) -----------------------------------
    reg [W-1:0] vmem[0:31];
    reg [4:0] v_ra, v_wa;
    reg v_we;
    reg [W-1:0] v_wd, v_rd;
    always @(posedge clk) begin
        if (v_we) vmem[v_wa] <= v_wd;
        v_rd <= vmem[v_ra];
    end
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
    reg signed [ZW-1:0] gam, lam;
    reg [W-1:0] mag, c1;

    // the vectors into the vector memory, one component a clock: the input vectors are shifted out of vec_in,
    // every component shifted left by its vector's common amount (SetupModel::prescale) in one shifter; then
    // P = perpendicular(N1) from N1's codes (N1 x e_k, e_k the axis of its smallest component) and M1 = (0, 0, U)
    reg [2:0] ld_v;                       // 0..3: N1, N2, H1, H2; 4: P; 5: M1
    reg [1:0] ld_c;                       // 0: the vector's shift; 1..3: its x, y, z
    reg [5:0] ld_sh, n1_sh;               // the shift of the vector being loaded, N1's
    reg [3*VEC_W-1:0] n1q;                // N1's codes
    wire signed [VEC_W-1:0] cx = vec_in[0 +: VEC_W], cy = vec_in[VEC_W +: VEC_W], cz = vec_in[2*VEC_W +: VEC_W];
    wire [VEC_W-1:0] mx = cx[VEC_W-1] ? -cx : cx, my = cy[VEC_W-1] ? -cy : cy, mz = cz[VEC_W-1] ? -cz : cz;
    wire [VEC_W-1:0] mor = mx | my | mz;   // its leading one is the largest magnitude's
    localparam [5:0] FM1 = F - 1;
    reg [5:0] lead;
    integer k;
    always @* begin
        lead = 6'd0;
        for (k = 0; k < VEC_W; k = k + 1) if (mor[k]) lead = k[5:0];
    end
    wire signed [VEC_W-1:0] qx = n1q[0 +: VEC_W], qy = n1q[VEC_W +: VEC_W], qz = n1q[2*VEC_W +: VEC_W];
    wire [VEC_W-1:0] ax = qx[VEC_W-1] ? -qx : qx, ay = qy[VEC_W-1] ? -qy : qy, az = qz[VEC_W-1] ? -qz : qz;
    wire [1:0] pk = (ax <= ay && ax <= az) ? 2'd0 : (ay <= az) ? 2'd1 : 2'd2;
    // P's component c (1 x, 2 y, 3 z): k = x: (0, nz, -ny); k = y: (-nz, 0, nx); k = z: (ny, -nx, 0)
    reg signed [VEC_W:0] pc;
    always @* begin
        case ({pk, ld_c})
            {2'd0, 2'd2}: pc = {qz[VEC_W-1], qz};
            {2'd0, 2'd3}: pc = -{qy[VEC_W-1], qy};
            {2'd1, 2'd1}: pc = -{qz[VEC_W-1], qz};
            {2'd1, 2'd3}: pc = {qx[VEC_W-1], qx};
            {2'd2, 2'd1}: pc = {qy[VEC_W-1], qy};
            {2'd2, 2'd2}: pc = -{qx[VEC_W-1], qx};
            default: pc = {(VEC_W + 1) {1'b0}};
        endcase
    end
    wire signed [VEC_W:0] ld_val = (ld_v == 3'd4) ? pc : {cx[VEC_W-1], cx};
    wire signed [W-1:0] ld_ext = {{(W - VEC_W - 1) {ld_val[VEC_W]}}, ld_val};
    wire signed [W-1:0] ld_word = ld_ext <<< ((ld_v == 3'd4) ? n1_sh : ld_sh);

    // ---- the CORDIC lane -------------------------------------------------------------------------------------
    reg signed [W-1:0] la, lb, acc;       // the pair, the third coordinate's gain sum
    reg signed [ZW-1:0] lz;
    reg [ITERS-1:0] drec;                 // the driver's directions (1: rotate by -atan)
    reg neg;                              // the driver's pair was turned by pi
    reg [4:0] it;                         // micro-rotation
    wire d_now = (run_role == 2'd1) ? drec[0] : ~lb[W-1];
    wire signed [W-1:0] as = la >>> it;
    wire signed [W-1:0] bs = lb >>> it;
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
    localparam [8*32-1:0] GSH32 = {{(8 * (32 - `SETUP_GAIN_N)) {1'b0}}, GSH};
    localparam [8*32-1:0] HSH32 = {{(8 * (32 - `SETUP_HALF_N)) {1'b0}}, HSH};
    localparam [31:0] GNEG32 = {{(32 - `SETUP_GAIN_N) {1'b0}}, GNEG};
    localparam [31:0] HNEG32 = {{(32 - `SETUP_HALF_N) {1'b0}}, HNEG};
    wire [1:0] gterm[0:ITERS+1];
    wire [1:0] hterm[0:ITERS+1];
    wire [ZW-1:0] atab[0:31];
    genvar g;
    generate
        for (g = 0; g <= ITERS + 1; g = g + 1) begin : g_terms
            assign gterm[g] = term_of(GSH32, GNEG32, `SETUP_GAIN_N, g - 1);
            assign hterm[g] = term_of(HSH32, HNEG32, `SETUP_HALF_N, g - 1);
        end
        for (g = 0; g < 32; g = g + 1) begin : g_atab
            assign atab[g] = (g < ITERS) ? ATAN[(g % ITERS)*ZW +: ZW] : {ZW{1'b0}};
        end
    endgenerate
    reg signed [W-1:0] lts;               // t >>> it during the micro-rotations
    wire [1:0] tc_rot = run_halve ? hterm[it + 1] : gterm[it + 1];
    wire [1:0] tc_first = run_halve ? hterm[0] : gterm[0];
    wire [1:0] tc_last = run_halve ? hterm[ITERS + 1] : gterm[ITERS + 1];
    wire [ZW-1:0] atan_i = atab[it];

    // ---- table lookups with interpolation: log2 (TB + RB bits of position) and exp2 -----------------------------
    reg [TB-1:0] tab_a;
    wire [LF-1:0] lg_w;
    wire [EF:0] ex_w;
    spec_rom #(.AW(TB), .DW(LF), .INIT_FILE(LOG2_FILE)) u_log2 (.clk(clk), .en(1'b1), .addr(tab_a), .data(lg_w));
    spec_rom #(.AW(TB), .DW(EF + 1), .INIT_FILE(EXP2_FILE)) u_exp2 (.clk(clk), .en(1'b1), .addr(tab_a), .data(ex_w));
    reg [EF:0] w0;                        // the first word of a lookup
    reg [RB-1:0] tr;                      // position between the words
    reg [EF:0] tdiff;
    wire [EF+RB:0] tprod = tdiff * tr;    // the interpolation product (a DSP)
    localparam [EF+RB:0] HALF_R = 1 << (RB - 1);
    wire [EF+RB:0] tprod_r = tprod + HALF_R;
    wire unused_tprod;
    assign unused_tprod = &{1'b0, tprod_r[RB-1:0]};

    // log2 operand: leading one and the bits below it
    // the operand is normalized by shifting it left one bit a clock until its leading one is at the top (lg_e
    // counts down from its position F + 1); then the TB + RB bits below it are the table index and position
    reg [F+1:0] lgx;
    reg [5:0] lg_e;
    wire [TB-1:0] lg_j = lgx[F -: TB];
    wire [RB-1:0] lg_r = lgx[F-TB -: RB];
    wire unused_lgx;
    assign unused_lgx = &{1'b0, lgx[F-TB-RB:0]};

    // ---- back end registers ------------------------------------------------------------------------------------
    reg flat, nohl, xpos, sat;
    reg [LF+5:0] lx, ls;                  // log2 of A's operand, log2 of the strength
    reg [LF+N_W+5:0] nla, la_sh;          // n * la_v (shift and add: la_v doubled a clock)
    localparam PW = LF + N_W + 8;
    reg signed [PW-1:0] pv;
    reg signed [ZW-1:0] z0;
    reg [ANG_W-1:0] zeta0, dzeta;
    reg [C_W-1:0] ccode;
    // divider
    localparam DW = L_W + S;
    reg [DW-1:0] drem, dden;
    reg [ZW-1:0] dnq;                     // numerator bits left above the quotient bits made
    reg [5:0] dcnt;
    wire [DW:0] dsh = {drem, dnq[ZW-1]};
    wire dge = dsh >= {1'b0, dden};
    wire [DW:0] ddif = dsh - {1'b0, dden};
    wire unused_ddif = ddif[DW];
    wire [W+9:0] rho2k = $signed(la) * `SETUP_OPP_K;   // the opposite test, rho2 * OPP_K

    // ---- control ----------------------------------------------------------------------------------------------------
    localparam ST_IDLE = 5'd0, ST_LOAD = 5'd1, ST_RD = 5'd2, ST_ROT = 5'd3, ST_WR = 5'd4, ST_BE = 5'd5,
               ST_LG = 5'd6, ST_EX = 5'd7;
    reg [4:0] st;
    reg [3:0] ph;                         // phase within a state
    reg [5:0] bs_step;                    // back end step

    wire signed [ZW-1:0] mid = z0 + (gam >>> 1);
    wire signed [ZW-1:0] z0r = (z0 + (1 <<< (S - 1))) >>> S;
    wire [ZW-1:0] gnum = {1'b0, gam[ZW-2:0]} + ({{(ZW - L_W) {1'b0}}, l_reg} << (S - 1));
    localparam [LF+6:0] OFF = F << LF;
    localparam [LF+6:0] OFF_FLAT = (F << LF) - `SETUP_LOG2_GAIN;
    localparam [LF+6:0] LA_MAX = 31 << LF;
    wire signed [LF+7:0] la_raw = $signed({1'b0, flat ? OFF_FLAT : OFF}) - $signed({2'b00, lx});
    wire signed [LF+7:0] lis = $signed({2'b00, ls}) - $signed(STR_FRAC << LF);
    wire [PW-LF-1:0] p_i = pv[PW-1:LF];
    wire [5:0] p_sh1 = EF - C_W - 1 + {1'b0, p_i[4:0]};
    wire [W-1:0] p_inc = as + 1'b1;
    wire [W-2:0] p_round = p_inc[W-1:1];
    wire [5:0] nbit6 = bs_step - 6'd7;   // steps 7..16: bit nbit of n
    wire [3:0] nbit = nbit6[3:0];
    wire zero_c = bad || nohl || (s_reg == {STR_W{1'b0}}) || ((n_reg != {N_W{1'b0}}) && !xpos);
    wire unused_bits;
    assign unused_bits = &{1'b0, z0r[ZW-1:ANG_W], p_i[PW-LF-1:5], nbit6[5:4], p_sh1[5], p_inc[0]};

    always @(posedge clk) begin
        v_we <= 1'b0;
        if (rst) begin
            st <= ST_IDLE;
            s_tready <= 1'b0;
            m_tvalid <= 1'b0;
        end else begin
            if (m_tvalid && m_tready) m_tvalid <= 1'b0;
            case (st)
                ST_IDLE: begin
                    s_tready <= 1'b1;
                    if (s_tvalid && s_tready) begin
                        s_tready <= 1'b0;
                        vec_in <= s_vec;
                        s_reg <= s_str;
                        n_reg <= s_n;
                        l_reg <= s_l;
                        rule_reg <= s_rule;
                        bad <= 1'b0;
                        ld_v <= 3'd0;
                        ld_c <= 2'd0;
                        st <= ST_LOAD;
                    end
                end
                // write the prescaled vectors (and P, and M1 = (0, 0, U)) into the vector memory
                ST_LOAD: begin
                    if (ld_c == 2'd0) begin
                        // the vector's shift (input vectors) from its components' leading one
                        ld_sh <= FM1 - lead;
                        if (ld_v == 3'd0) begin
                            n1_sh <= FM1 - lead;
                            n1q <= vec_in[0 +: 3*VEC_W];
                        end
                        if (ld_v < 3'd4 && mor == {VEC_W{1'b0}}) bad <= 1'b1;
                        ld_c <= 2'd1;
                    end else begin
                        v_we <= 1'b1;
                        v_wa <= {ld_v, ld_c - 2'd1};
                        v_wd <= (ld_v == 3'd5) ? ((ld_c == 2'd3) ? U : {W{1'b0}}) : ld_word;
                        if (ld_v < 3'd4) vec_in <= {{VEC_W{1'b0}}, vec_in[12*VEC_W-1:VEC_W]};   // the next component
                        if (ld_c == 2'd3) begin
                            ld_c <= 2'd0;
                            ld_v <= ld_v + 3'd1;
                            if (ld_v == 3'd5) begin
                                run <= 5'd0;
                                ph <= 4'd0;
                                st <= bad ? ST_BE : ST_RD;
                                bs_step <= 6'd0;
                            end
                        end else begin
                            ld_c <= ld_c + 2'd1;
                        end
                    end
                end
                // read a, b, t of the run's vector (the memory's read is registered: data one clock later)
                ST_RD: begin
                    ph <= ph + 4'd1;
                    case (ph)
                        4'd0: v_ra <= {run_vec, ca};
                        4'd1: v_ra <= {run_vec, cb};
                        4'd2: begin
                            v_ra <= {run_vec, ct};
                            la <= run_halve ? ($signed(v_rd + 1'b1) >>> 1) : $signed(v_rd);
                        end
                        4'd3: lb <= run_halve ? ($signed(v_rd + 1'b1) >>> 1) : $signed(v_rd);
                        default: begin
                            lts <= v_rd;
                            acc <= !tc_first[1] ? {W{1'b0}} : tc_first[0] ? -($signed(v_rd) <<< 1) : ($signed(v_rd) <<< 1);
                            it <= 5'd0;
                            lz <= {ZW{1'b0}};
                            // the turn before the micro-rotations: by pi (frame passes; the driver decides,
                            // followers replay), a quarter turn (angle runs)
                            if (run_role == 2'd2) begin
                                if (la[W-1]) begin
                                    la <= lb[W-1] ? -lb : lb;
                                    lb <= lb[W-1] ? la : -la;
                                    lz <= lb[W-1] ? -HALF_PI : HALF_PI;
                                end
                            end else if ((run_role == 2'd0) ? la[W-1] : neg) begin
                                la <= -la;
                                lb <= -lb;
                            end
                            if (run_role == 2'd0) neg <= la[W-1];
                            st <= ST_ROT;
                        end
                    endcase
                end
                ST_ROT: begin
                    // one adder each: the direction folded into the operand (x - y = x + ~y + 1)
                    la <= la + (bs ^ {W{~d_now}}) + {{(W - 1) {1'b0}}, ~d_now};         // d: la + bs, else la - bs
                    lb <= lb + (as ^ {W{d_now}}) + {{(W - 1) {1'b0}}, d_now};           // d: lb - as, else lb + as
                    lz <= lz + (atan_i ^ {ZW{~d_now}}) + {{(ZW - 1) {1'b0}}, ~d_now};   // d: + atan, else - atan
                    // the directions: the driver records them, followers replay them (a rotating register)
                    drec <= {d_now, drec[ITERS-1:1]};
                    if (tc_rot[1]) acc <= acc + (lts ^ {W{tc_rot[0]}}) + {{(W - 1) {1'b0}}, tc_rot[0]};
                    lts <= lts >>> 1;
                    it <= it + 5'd1;
                    if (it == ITERS - 1) begin
                        st <= ST_WR;
                        ph <= 4'd0;
                    end
                end
                ST_WR: begin
                    ph <= ph + 4'd1;
                    v_we <= 1'b1;
                    if (ph == 4'd0 && tc_last[1]) acc <= acc + (lts ^ {W{tc_last[0]}}) + {{(W - 1) {1'b0}}, tc_last[0]};
                    case (ph)
                        4'd0: begin
                            v_wa <= {run_vec, ca};
                            v_wd <= la;
                            if (run == 5'd10 && exact_opp) v_wd <= {W{1'b0}};   // P3: exactly opposite: rho2 := 0
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
                            v_we <= (run == 5'd9) && exact_opp;
                            v_wa <= {3'd1, 2'd0};
                            v_wd <= lb;
                        end
                        default: begin
                            v_we <= (run == 5'd9) && exact_opp;
                            v_wa <= {3'd1, 2'd1};
                            v_wd <= acc;
                        end
                    endcase
                    if (ph == 4'd0) begin
                        // P2's N2 run (plane z, x: a = z, b = x, t = y): exactly opposite?
                        if (run == 5'd6) exact_opp <= la[W-1] && ((lb[W-1] ? -lb : lb) < TAU) && ((acc[W-1] ? -acc : acc) < TAU);
                        // P3's N2 run (plane x, y: a = rho2, t = z2): the opposite flag
                        if (run == 5'd10) opp <= exact_opp || (acc[W-1] && ($signed(rho2k) < -$signed({{10{acc[W-1]}}, acc})));
                        if (run == 5'd21) c1 <= acc;
                        if (run == 5'd22) gam <= lz;
                        if (run == 5'd23) begin
                            lam <= lz;
                            mag <= la;
                        end
                    end
                    if (ph == 4'd4) begin
                        ph <= 4'd0;
                        if (run == NRUN - 1) begin
                            st <= ST_BE;
                            bs_step <= 6'd0;
                        end else begin
                            run <= run + 5'd1;
                            st <= ST_RD;
                        end
                    end
                end
                // the back end (SetupModel::run after the angles)
                ST_BE: begin
                    bs_step <= bs_step + 6'd1;
                    case (bs_step)
                        6'd0: begin
                            flat <= (l_reg == {L_W{1'b0}}) || (gam < FLAT_Z);
                            z0 <= -lam;
                            // the division starts: numerator gamma + l 2^(S-1), divisor l 2^S
                            drem <= {DW{1'b0}};
                            dden <= {l_reg, {S{1'b0}}};
                            dnq <= gnum;
                            dcnt <= 6'd0;
                        end
                        6'd1: begin
                            z0 <= (mid > PI_Z) ? z0 - TWO_PI : (mid < -PI_Z) ? z0 + TWO_PI : z0;
                            lgx <= flat ? c1[F+1:0] : mag[F+1:0];
                            lg_e <= F + 1;
                            xpos <= flat ? (!c1[W-1] && c1 != {W{1'b0}}) : (!mag[W-1] && mag != {W{1'b0}});
                        end
                        6'd2: begin
                            nohl <= (n_reg != {N_W{1'b0}}) && (flat ? (c1[W-1] || c1 == {W{1'b0}})
                                                                   : ((z0 + gam <= -HALF_PI) || (z0 >= HALF_PI)));
                            zeta0 <= flat ? {ANG_W{1'b0}} : z0r[ANG_W-1:0];
                            st <= ST_LG;      // log2 of A's operand, then back here at step 3
                            ph <= 4'd0;
                        end
                        6'd3: begin
                            lx <= {lg_e, {LF{1'b0}}} + {6'd0, w0[LF-1:0]} + {6'd0, tprod_r[LF+RB-1:RB]};
                            lgx <= {{(F + 2 - STR_W) {1'b0}}, s_reg};
                            lg_e <= F + 1;
                        end
                        6'd4: begin
                            st <= ST_LG;      // log2 of the strength, then step 5
                            ph <= 4'd0;
                        end
                        6'd5: begin
                            ls <= {lg_e, {LF{1'b0}}} + {6'd0, w0[LF-1:0]} + {6'd0, tprod_r[LF+RB-1:RB]};
                        end
                        6'd6: begin
                            nla <= {(LF + N_W + 6) {1'b0}};
                            la_sh <= {{N_W{1'b0}}, (!xpos || la_raw < 0) ? {(LF + 6) {1'b0}}
                                      : (la_raw > $signed({1'b0, LA_MAX})) ? LA_MAX[LF+5:0] : la_raw[LF+5:0]};
                        end
                        6'd7, 6'd8, 6'd9, 6'd10, 6'd11, 6'd12, 6'd13, 6'd14, 6'd15, 6'd16: begin
                            // n * la_v, one bit of n a clock (below)
                        end
                        6'd17: begin
                            pv <= $signed({2'b00, nla}) - $signed({{(PW - LF - 8) {lis[LF+7]}}, lis});
                        end
                        6'd18: begin
                            sat <= pv <= 0;
                            st <= ST_EX;      // exp2 of the fraction of p, then step 19
                            ph <= 4'd0;
                        end
                        6'd19: begin
                            ccode <= (p_i > C_W + 1) ? {C_W{1'b0}}
                                   : (p_round > {{(W - 1 - C_W) {1'b0}}, {C_W{1'b1}}}) ? {C_W{1'b1}} : p_round[C_W-1:0];
                        end
                        default: begin       // 20: wait for the divider and the output register (and stay)
                            if (dcnt == ZW[5:0] && !(m_tvalid && !m_tready)) begin
                                m_tvalid <= 1'b1;
                                m_dzeta <= bad || flat ? {ANG_W{1'b0}} : dzeta;
                                m_zeta0 <= bad ? {ANG_W{1'b0}} : zeta0;
                                m_l <= l_reg;
                                m_n <= n_reg;
                                m_c <= zero_c ? {C_W{1'b0}} : sat ? {C_W{1'b1}} : ccode;
                                m_flags <= bad ? {1'b1, 2'b00, l_reg == {L_W{1'b0}}, 3'b000}
                                               : {1'b0, rule_reg, nohl, l_reg == {L_W{1'b0}}, !zero_c && sat, opp, flat};
                                st <= ST_IDLE;
                            end else begin
                                bs_step <= bs_step;
                            end
                        end
                    endcase
                    if (bs_step >= 6'd7 && bs_step <= 6'd16) begin
                        if (n_reg[nbit]) nla <= nla + la_sh;
                        la_sh <= {la_sh[LF+N_W+4:0], 1'b0};
                    end
                    // the divider runs beside the back end from step 1 on
                    if (bs_step != 6'd0 && dcnt != ZW[5:0]) begin
                        drem <= dge ? ddif[DW-1:0] : dsh[DW-1:0];
                        dnq <= {dnq[ZW-2:0], dge};
                        dcnt <= dcnt + 6'd1;
                        if (dcnt == ZW[5:0] - 6'd1) dzeta <= {dnq[ANG_W-2:0], dge};
                    end
                end
                // a log2 lookup of lgx: normalize, read words j and j + 1, interpolate (back to ST_BE)
                ST_LG: begin
                    ph <= ph + 4'd1;
                    case (ph)
                        4'd0: begin
                            if (!lgx[F+1] && lg_e != 6'd0) begin
                                lgx <= {lgx[F:0], 1'b0};
                                lg_e <= lg_e - 6'd1;
                                ph <= ph;
                            end
                        end
                        4'd1: tab_a <= lg_j;
                        4'd2: tab_a <= lg_j + 1'b1;
                        4'd3: begin
                            w0 <= {{(EF + 1 - LF) {1'b0}}, lg_w};
                            tr <= lg_r;
                        end
                        4'd4: tdiff <= ((&lg_j) ? (1 << LF) : {{(EF + 1 - LF) {1'b0}}, lg_w}) - w0;
                        default: st <= ST_BE;   // tprod is ready
                    endcase
                end
                // an exp2 lookup of p's fraction (back to ST_BE)
                ST_EX: begin
                    ph <= ph + 4'd1;
                    case (ph)
                        4'd0: tab_a <= pv[LF-1 -: TB];
                        4'd1: tab_a <= pv[LF-1 -: TB] + 1'b1;
                        4'd2: begin
                            w0 <= ex_w;
                            tr <= pv[LF-TB-1 -: RB];
                        end
                        4'd3: tdiff <= w0 - ((&pv[LF-1 -: TB]) ? (1 << (EF - 1)) : ex_w);
                        4'd4: begin
                            // 2^-f in la, and the rounding shift (EF - C_W + i, at most EF + 1 when the code is
                            // not 0) less one in it: code = ((la >>> it) + 1) >> 1, with the lane's shifter
                            la <= {{(W - EF - 1) {1'b0}}, w0 - tprod_r[EF+RB:RB]};
                            it <= p_sh1[4:0];
                        end
                        default: st <= ST_BE;
                    endcase
                end
                default: st <= ST_IDLE;
            endcase
        end
    end
endmodule
`default_nettype wire
