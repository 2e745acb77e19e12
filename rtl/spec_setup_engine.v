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
    reg [2:0] run_vec;
    reg run_plane, run_halve;
    reg [1:0] run_role;
    reg [4:0] run;
    always @* begin
        case (run)
            5'd0:  {run_vec, run_plane, run_role, run_halve} = {3'd0, 1'b0, 2'd0, 1'b0};   // P1 N1
            5'd1:  {run_vec, run_plane, run_role, run_halve} = {3'd1, 1'b0, 2'd1, 1'b0};   //    N2
            5'd2:  {run_vec, run_plane, run_role, run_halve} = {3'd2, 1'b0, 2'd1, 1'b0};   //    H1
            5'd3:  {run_vec, run_plane, run_role, run_halve} = {3'd3, 1'b0, 2'd1, 1'b0};   //    H2
            5'd4:  {run_vec, run_plane, run_role, run_halve} = {3'd4, 1'b0, 2'd1, 1'b0};   //    P
            5'd5:  {run_vec, run_plane, run_role, run_halve} = {3'd0, 1'b1, 2'd0, 1'b1};   // P2 N1
            5'd6:  {run_vec, run_plane, run_role, run_halve} = {3'd1, 1'b1, 2'd1, 1'b1};   //    N2
            5'd7:  {run_vec, run_plane, run_role, run_halve} = {3'd2, 1'b1, 2'd1, 1'b1};   //    H1
            5'd8:  {run_vec, run_plane, run_role, run_halve} = {3'd3, 1'b1, 2'd1, 1'b1};   //    H2
            5'd9:  {run_vec, run_plane, run_role, run_halve} = {3'd4, 1'b1, 2'd1, 1'b1};   //    P
            5'd10: {run_vec, run_plane, run_role, run_halve} = {3'd1, 1'b0, 2'd0, 1'b1};   // P3 N2
            5'd11: {run_vec, run_plane, run_role, run_halve} = {3'd2, 1'b0, 2'd1, 1'b1};   //    H1
            5'd12: {run_vec, run_plane, run_role, run_halve} = {3'd3, 1'b0, 2'd1, 1'b1};   //    H2
            5'd13: {run_vec, run_plane, run_role, run_halve} = {3'd1, 1'b1, 2'd0, 1'b0};   // P4 N2
            5'd14: {run_vec, run_plane, run_role, run_halve} = {3'd3, 1'b1, 2'd1, 1'b0};   //    H2
            5'd15: {run_vec, run_plane, run_role, run_halve} = {3'd2, 1'b0, 2'd0, 1'b1};   // G1 H1
            5'd16: {run_vec, run_plane, run_role, run_halve} = {3'd3, 1'b0, 2'd1, 1'b1};   //    H2
            5'd17: {run_vec, run_plane, run_role, run_halve} = {3'd2, 1'b1, 2'd0, 1'b1};   // G2 H1
            5'd18: {run_vec, run_plane, run_role, run_halve} = {3'd3, 1'b1, 2'd1, 1'b1};   //    H2
            5'd19: {run_vec, run_plane, run_role, run_halve} = {3'd5, 1'b1, 2'd1, 1'b1};   //    M1
            5'd20: {run_vec, run_plane, run_role, run_halve} = {3'd3, 1'b0, 2'd0, 1'b1};   // Q1 H2
            5'd21: {run_vec, run_plane, run_role, run_halve} = {3'd5, 1'b0, 2'd1, 1'b1};   //    M1
            5'd22: {run_vec, run_plane, run_role, run_halve} = {3'd3, 1'b1, 2'd2, 1'b0};   // gamma
            default: {run_vec, run_plane, run_role, run_halve} = {3'd5, 1'b1, 2'd2, 1'b0}; // lambda
        endcase
    end

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

    // prescale of the input vector being loaded
    reg [2:0] ld_v;                       // 0..3: N1, N2, H1, H2; 4: P; 5: M1
    reg [1:0] ld_c;
    wire [3*W-1:0] pre_v;
    wire pre_zero;
    spec_setup_prescale u_pre (.v_i(vec_in[(ld_v[1:0])*3*VEC_W +: 3*VEC_W]), .v_o(pre_v), .zero(pre_zero));
    reg [3*W-1:0] n1p;                    // prescaled N1, for P
    wire signed [W-1:0] nx = n1p[0 +: W], ny = n1p[W +: W], nz = n1p[2*W +: W];
    wire [W-1:0] ax = nx[W-1] ? -nx : nx, ay = ny[W-1] ? -ny : ny, az = nz[W-1] ? -nz : nz;
    wire [3*W-1:0] ppv = (ax <= ay && ax <= az) ? {-ny, nz, {W{1'b0}}}
                       : (ay <= az)             ? {nx, {W{1'b0}}, -nz}
                                                : {{W{1'b0}}, -nx, ny};

    // ---- the CORDIC lane -------------------------------------------------------------------------------------
    reg signed [W-1:0] la, lb, lt, acc;   // pair, third coordinate, gain sum
    reg signed [ZW-1:0] lz;
    reg [ITERS-1:0] drec;                 // the driver's directions (1: rotate by -atan)
    reg neg;                              // the driver's pair was turned by pi
    reg [4:0] it;                         // micro-rotation
    wire d_now = (run_role == 2'd1) ? drec[it] : ~lb[W-1];
    wire signed [W-1:0] as = la >>> it;
    wire signed [W-1:0] bs = lb >>> it;
    localparam [7:0] GN = `SETUP_GAIN_N, HN = `SETUP_HALF_N;
    wire [7:0] nterm = run_halve ? HN : GN;
    reg signed [W-1:0] term;
    reg tneg;
    integer q;
    always @* begin
        term = {W{1'b0}};
        tneg = 1'b0;
        for (q = 0; q < `SETUP_GAIN_N; q = q + 1) begin
            if (!run_halve && it == q[4:0]) begin
                term = GSH[8*q+7] ? (lt <<< 1) : (lt >>> GSH[8*q +: 8]);
                tneg = GNEG[q];
            end
        end
        for (q = 0; q < `SETUP_HALF_N; q = q + 1) begin
            if (run_halve && it == q[4:0]) begin
                term = HSH[8*q+7] ? (lt <<< 1) : (lt >>> HSH[8*q +: 8]);
                tneg = HNEG[q];
            end
        end
    end
    reg [ZW-1:0] atan_i;
    always @* begin
        atan_i = {ZW{1'b0}};
        for (q = 0; q < ITERS; q = q + 1) if (it == q[4:0]) atan_i = ATAN[q*ZW +: ZW];
    end

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
    reg [F+1:0] lgx;
    reg [5:0] lg_e;
    integer k;
    always @* begin
        lg_e = 6'd0;
        for (k = 0; k < F + 2; k = k + 1) if (lgx[k]) lg_e = k[5:0];
    end
    wire [F+1+TB+RB:0] lg_n = {lgx, {(TB + RB) {1'b0}}} << (F + 1 - lg_e);
    wire [TB-1:0] lg_j = lg_n[F+TB+RB -: TB];
    wire [RB-1:0] lg_r = lg_n[F+RB -: RB];
    wire unused_lgn;
    assign unused_lgn = &{1'b0, lg_n[F+1+TB+RB], lg_n[F:0]};

    // ---- back end registers ------------------------------------------------------------------------------------
    reg flat, nohl, xpos, sat;
    reg [LF+5:0] lx, ls;                  // log2 of A's operand, log2 of the strength
    reg [LF+5:0] la_v;                    // -log2 A, clamped
    reg [LF+N_W+5:0] nla;                 // n * la_v (shift and add)
    localparam PW = LF + N_W + 8;
    reg signed [PW-1:0] pv;
    reg signed [ZW-1:0] z0;
    reg [ANG_W-1:0] zeta0, dzeta;
    reg [C_W-1:0] ccode;
    reg [EF:0] ev;
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
    wire [5:0] p_sh = EF - C_W + {1'b0, p_i[4:0]};
    wire [EF+1:0] p_round = ({1'b0, ev} + ({{(EF + 1) {1'b0}}, 1'b1} << (p_sh - 1))) >> p_sh;
    wire [5:0] nbit6 = bs_step - 6'd7;   // steps 7..16: bit nbit of n
    wire [3:0] nbit = nbit6[3:0];
    wire zero_c = bad || nohl || (s_reg == {STR_W{1'b0}}) || ((n_reg != {N_W{1'b0}}) && !xpos);
    wire unused_bits;
    assign unused_bits = &{1'b0, z0r[ZW-1:ANG_W], p_i[PW-LF-1:5], nterm, nbit6[5:4]};

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
                    v_we <= 1'b1;
                    v_wa <= {ld_v, ld_c};
                    if (ld_v < 3'd4) begin
                        v_wd <= pre_v[ld_c*W +: W];
                        if (ld_v == 3'd0) n1p <= pre_v;
                        if (ld_c == 2'd0 && pre_zero) bad <= 1'b1;
                    end else if (ld_v == 3'd4) begin
                        v_wd <= ppv[ld_c*W +: W];
                    end else begin
                        v_wd <= (ld_c == 2'd2) ? U : {W{1'b0}};
                    end
                    if (ld_c == 2'd2) begin
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
                            lt <= v_rd;
                            acc <= {W{1'b0}};
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
                    la <= d_now ? la + bs : la - bs;
                    lb <= d_now ? lb - as : lb + as;
                    lz <= d_now ? lz + $signed(atan_i) : lz - $signed(atan_i);
                    if (run_role != 2'd1) drec[it] <= d_now;
                    if (it < nterm[4:0]) acc <= tneg ? acc - term : acc + term;
                    it <= it + 5'd1;
                    if (it == ITERS - 1) begin
                        st <= ST_WR;
                        ph <= 4'd0;
                    end
                end
                ST_WR: begin
                    ph <= ph + 4'd1;
                    v_we <= 1'b1;
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
                        end
                        6'd4: begin
                            st <= ST_LG;      // log2 of the strength, then step 5
                            ph <= 4'd0;
                        end
                        6'd5: begin
                            ls <= {lg_e, {LF{1'b0}}} + {6'd0, w0[LF-1:0]} + {6'd0, tprod_r[LF+RB-1:RB]};
                        end
                        6'd6: begin
                            la_v <= (!xpos || la_raw < 0) ? {(LF + 6) {1'b0}}
                                  : (la_raw > $signed({1'b0, LA_MAX})) ? LA_MAX[LF+5:0] : la_raw[LF+5:0];
                            nla <= {(LF + N_W + 6) {1'b0}};
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
                                   : (p_round > {{(EF + 2 - C_W) {1'b0}}, {C_W{1'b1}}}) ? {C_W{1'b1}} : p_round[C_W-1:0];
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
                        if (n_reg[nbit]) nla <= nla + ({{N_W{1'b0}}, la_v} << nbit);
                    end
                    // the divider runs beside the back end from step 1 on
                    if (bs_step != 6'd0 && dcnt != ZW[5:0]) begin
                        drem <= dge ? ddif[DW-1:0] : dsh[DW-1:0];
                        dnq <= {dnq[ZW-2:0], dge};
                        dcnt <= dcnt + 6'd1;
                        if (dcnt == ZW[5:0] - 6'd1) dzeta <= {dnq[ANG_W-2:0], dge};
                    end
                end
                // a log2 lookup of lgx: read words j and j + 1, interpolate (back to ST_BE)
                ST_LG: begin
                    ph <= ph + 4'd1;
                    case (ph)
                        4'd0: tab_a <= lg_j;
                        4'd1: tab_a <= lg_j + 1'b1;
                        4'd2: begin
                            w0 <= {{(EF + 1 - LF) {1'b0}}, lg_w};
                            tr <= lg_r;
                        end
                        4'd3: tdiff <= ((&lg_j) ? (1 << LF) : {{(EF + 1 - LF) {1'b0}}, lg_w}) - w0;
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
                        4'd4: ev <= w0 - tprod_r[EF+RB:RB];
                        default: st <= ST_BE;
                    endcase
                end
                default: st <= ST_IDLE;
            endcase
        end
    end
endmodule
`default_nettype wire
