// spec_setup_pipe - spec_setup's arithmetic fully pipelined: a new span every clock, its descriptor LAT clocks
// later. No stalls (spec_setup holds a FIFO of LAT + more entries and gives credits), no reset but the valid
// flags'. The passes and the back end are SetupModel::run's, bit for bit (sim/setup/setup_model.h):
//
//   in, prescale           the four vectors scaled by powers of two; perpendicular(N1) built from N1
//   P1 (x,y) P2 (z,x)      driven by N1; lanes N1, N2, H1, H2, P          -> the frame where N1 = z
//   opp                    exactly opposite normals: N2's (x, y) := P's
//   P3 (x,y)               driven by N2; lanes N2, H1, H2                  -> N2 in the (z,x) plane
//   P4 (z,x)               driven by N2; lane H2 (H1 waits)                -> H2' = H2 carried onto N1
//   G1 (x,y) G2 (z,x)      driven by H1; lanes H2' (+ N1 = (0, 0, U) in G2) -> the frame where H1 = z
//   Q1 (x,y)               driven by H2'; lane N1                           -> H2' in the (z,x) plane
//   angles                 gamma = atan2(H2'.x, H2'.z), lambda = atan2(N1.x, N1.z), A = |(N1.z, N1.x)|
//   back end               flat / no-highlight / opposite flags, zeta0 = -lambda (+-2 pi), dzeta = gamma / l,
//                          C = 2^-(n (-log2 A) - log2 Is) (log2 and exp2 tables)
`timescale 1ns / 1ps
`default_nettype none
`include "setup_params.vh"
`include "spec_params.vh"
module spec_setup_pipe #(
    parameter VEC_W = `SETUP_VEC_W,
    parameter F = `SETUP_F,
    parameter W = `SETUP_W,
    parameter ITERS = `SETUP_ITERS,
    parameter ZW = `SETUP_ZW,
    parameter ZF = `SETUP_ZF,
    parameter LF = `SETUP_LF,
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
    input  wire               clk,
    input  wire               rst,
    input  wire               in_valid,
    input  wire [12*VEC_W-1:0] in_vec,      // N1, N2, H1, H2; x, y, z each (x lowest)
    input  wire [STR_W-1:0]   in_str,
    input  wire [N_W-1:0]     in_n,
    input  wire [L_W-1:0]     in_l,
    input  wire               in_rule,
    output wire               out_valid,
    output reg  [C_W-1:0]     out_c,
    output reg  [N_W-1:0]     out_n,
    output reg  [L_W-1:0]     out_l,
    output reg  [ANG_W-1:0]   out_zeta0,
    output reg  [ANG_W-1:0]   out_dzeta,
    output reg  [6:0]         out_flags
);
    localparam P = ITERS + 1;                  // clocks per pass
    // clocks from in_* to the registers that hold a span (in_* at one edge is in the prescale registers after it)
    localparam T_PRE = 1;                      // prescale registers
    localparam T_ANG = T_PRE + 8 * P + 1;      // angle passes' outputs (+1: the opposite-normals stage)
    localparam BE = ZW + 1;                    // back end: the divider's ZW stages, then the output registers
    localparam LAT = T_ANG + BE;               // in_* to out_*
    localparam S = ZF - ANG_FRAC;
    localparam SIDE_W = 1 + 1 + STR_W + N_W + L_W;

    // ---- valid flags (the only reset) ----------------------------------------------------------------------
    reg [LAT-1:0] vq;
    always @(posedge clk) begin
        if (rst) vq <= {LAT{1'b0}};
        else vq <= {vq[LAT-2:0], in_valid};
    end
    assign out_valid = vq[LAT-1];

    // ---- prescale -------------------------------------------------------------------------------------------
    wire [3*W-1:0] n1p, n2p, h1p, h2p;
    wire z_n1, z_n2, z_h1, z_h2;
    spec_setup_prescale u_pn1 (.v_i(in_vec[0*3*VEC_W +: 3*VEC_W]), .v_o(n1p), .zero(z_n1));
    spec_setup_prescale u_pn2 (.v_i(in_vec[1*3*VEC_W +: 3*VEC_W]), .v_o(n2p), .zero(z_n2));
    spec_setup_prescale u_ph1 (.v_i(in_vec[2*3*VEC_W +: 3*VEC_W]), .v_o(h1p), .zero(z_h1));
    spec_setup_prescale u_ph2 (.v_i(in_vec[3*3*VEC_W +: 3*VEC_W]), .v_o(h2p), .zero(z_h2));
    // perpendicular(N1) = N1 x e_k, e_k the axis of N1's smallest component (first of x, y, z)
    wire signed [W-1:0] nx = n1p[0 +: W], ny = n1p[W +: W], nz = n1p[2*W +: W];
    wire [W-1:0] ax = nx[W-1] ? -nx : nx, ay = ny[W-1] ? -ny : ny, az = nz[W-1] ? -nz : nz;
    wire [3*W-1:0] ppv = (ax <= ay && ax <= az) ? {-ny, nz, {W{1'b0}}}
                       : (ay <= az)             ? {nx, {W{1'b0}}, -nz}
                                                : {{W{1'b0}}, -nx, ny};
    reg [3*W-1:0] n1, n2, h1, h2, pp;
    reg bad;
    always @(posedge clk) begin
        n1 <= n1p;
        n2 <= n2p;
        h1 <= h1p;
        h2 <= h2p;
        pp <= ppv;
        bad <= z_n1 | z_n2 | z_h1 | z_h2;
    end
    // the side band (strength, n, l, rule, invalid) waits in block RAM until the back end
    wire [SIDE_W-1:0] side_q;
    reg [SIDE_W-1:0] side_d;
    always @(posedge clk) side_d <= {in_rule, 1'b0, in_str, in_n, in_l};
    wire [SIDE_W-1:0] side_in = {side_d[SIDE_W-1], bad, side_d[SIDE_W-3:0]};
    spec_setup_ramdelay #(.W(SIDE_W), .N(T_ANG - T_PRE)) u_side (.clk(clk), .d(side_in), .q(side_q));

    // vector field helpers: {z, y, x}
    `define X_(v) v[0 +: W]
    `define Y_(v) v[W +: W]
    `define Z_(v) v[2*W +: W]

    wire [ZW-1:0] zu1, zu2, zu3, zu4, zu5, zu6, zu7;   // frame passes: no angle lane
    // ---- P1: (x, y) driven by N1 -----------------------------------------------------------------------------
    wire [5*W-1:0] p1a, p1b, p1t;
    spec_cordic_pass #(.LANES(5), .HALVE(0)) u_p1 (
        .clk(clk),
        .a_i({`X_(pp), `X_(h2), `X_(h1), `X_(n2), `X_(n1)}),
        .b_i({`Y_(pp), `Y_(h2), `Y_(h1), `Y_(n2), `Y_(n1)}),
        .t_i({`Z_(pp), `Z_(h2), `Z_(h1), `Z_(n2), `Z_(n1)}),
        .a_o(p1a), .b_o(p1b), .t_o(p1t), .z_o(zu1));
    // ---- P2: (z, x) driven by N1, halving ------------------------------------------------------------------
    wire [5*W-1:0] p2a, p2b, p2t;
    spec_cordic_pass #(.LANES(5), .HALVE(1)) u_p2 (
        .clk(clk), .a_i(p1t), .b_i(p1a), .t_i(p1b), .a_o(p2a), .b_o(p2b), .t_o(p2t), .z_o(zu2));
    // lanes after P2: x = b, y = t, z = a; lane 0 N1 (no longer needed), 1 N2, 2 H1, 3 H2, 4 P
    wire signed [W-1:0] n2x = p2b[1*W +: W], n2y = p2t[1*W +: W], n2z = p2a[1*W +: W];
    // ---- exactly opposite normals: P's projection drives P3 instead of N2's --------------------------------
    localparam signed [W-1:0] TAU = `SETUP_OPP_TAU;
    wire [W-1:0] n2xm = n2x[W-1] ? -n2x : n2x, n2ym = n2y[W-1] ? -n2y : n2y;
    wire exact_opp = n2z[W-1] && (n2xm < TAU) && (n2ym < TAU);
    reg [3*W-1:0] n2o, h1o, h2o;
    reg exo;
    always @(posedge clk) begin
        exo <= exact_opp;
        n2o <= {n2z, exact_opp ? p2t[4*W +: W] : n2y, exact_opp ? p2b[4*W +: W] : n2x};
        h1o <= {p2a[2*W +: W], p2t[2*W +: W], p2b[2*W +: W]};
        h2o <= {p2a[3*W +: W], p2t[3*W +: W], p2b[3*W +: W]};
    end
    // ---- P3: (x, y) driven by N2, halving --------------------------------------------------------------------
    wire [3*W-1:0] p3a, p3b, p3t;
    spec_cordic_pass #(.LANES(3), .HALVE(1)) u_p3 (
        .clk(clk),
        .a_i({`X_(h2o), `X_(h1o), `X_(n2o)}),
        .b_i({`Y_(h2o), `Y_(h1o), `Y_(n2o)}),
        .t_i({`Z_(h2o), `Z_(h1o), `Z_(n2o)}),
        .a_o(p3a), .b_o(p3b), .t_o(p3t), .z_o(zu3));
    // exactly-opposite flag, delayed through P3 beside it
    reg [P-1:0] exq;
    always @(posedge clk) exq <= {exq[P-2:0], exo};
    wire ex3 = exq[P-1];
    // N2 after P3: (rho2, ~0, z2); the opposite flag; exactly opposite: rho2 := 0 for P4 (a pure half turn)
    wire signed [W-1:0] rho2 = p3a[0 +: W], z2 = p3t[0 +: W];
    wire [W+9:0] rho2k = $signed(rho2) * `SETUP_OPP_K;
    wire opp3 = ex3 || (z2[W-1] && ($signed(rho2k) < -$signed({{10{z2[W-1]}}, z2})));
    // ---- P4: (z, x) driven by N2; H1 waits -------------------------------------------------------------------
    wire [2*W-1:0] p4a, p4b, p4t;
    spec_cordic_pass #(.LANES(2), .HALVE(0)) u_p4 (
        .clk(clk),
        .a_i({p3t[2*W +: W], z2}),
        .b_i({p3a[2*W +: W], ex3 ? {W{1'b0}} : rho2}),
        .t_i({p3b[2*W +: W], p3b[0 +: W]}),
        .a_o(p4a), .b_o(p4b), .t_o(p4t), .z_o(zu4));
    wire [3*W-1:0] h1w;
    spec_setup_ramdelay #(.W(3 * W), .N(P)) u_h1wait (
        .clk(clk), .d({p3t[1*W +: W], p3b[1*W +: W], p3a[1*W +: W]}), .q(h1w));
    // H2' = lane 1 of P4: x = b, y = t, z = a
    wire [W-1:0] h2x4 = p4b[W +: W], h2y4 = p4t[W +: W], h2z4 = p4a[W +: W];
    // the opposite flag waits for the back end
    wire opp_q;
    spec_setup_ramdelay #(.W(1), .N(T_ANG - (T_PRE + 3 * P + 1))) u_oppwait (.clk(clk), .d(opp3), .q(opp_q));
    // ---- G1: (x, y) driven by H1, halving --------------------------------------------------------------------
    wire [2*W-1:0] g1a, g1b, g1t;
    spec_cordic_pass #(.LANES(2), .HALVE(1)) u_g1 (
        .clk(clk), .a_i({h2x4, `X_(h1w)}), .b_i({h2y4, `Y_(h1w)}), .t_i({h2z4, `Z_(h1w)}),
        .a_o(g1a), .b_o(g1b), .t_o(g1t), .z_o(zu5));
    // ---- G2: (z, x) driven by H1, halving; N1 joins as (x, y, z) = (0, 0, U) -----------------------------------
    localparam [W-1:0] U = `SETUP_N1_START;
    wire [3*W-1:0] g2a, g2b, g2t;
    spec_cordic_pass #(.LANES(3), .HALVE(1)) u_g2 (
        .clk(clk), .a_i({U, g1t}), .b_i({{W{1'b0}}, g1a}), .t_i({{W{1'b0}}, g1b}),
        .a_o(g2a), .b_o(g2b), .t_o(g2t), .z_o(zu6));
    // lanes: 0 H1, 1 H2', 2 N1; x = b, y = t, z = a
    // ---- Q1: (x, y) driven by H2', halving; N1 follows ------------------------------------------------------
    wire [2*W-1:0] q1a, q1b, q1t;
    spec_cordic_pass #(.LANES(2), .HALVE(1)) u_q1 (
        .clk(clk), .a_i({g2b[2*W +: W], g2b[W +: W]}), .b_i({g2t[2*W +: W], g2t[W +: W]}),
        .t_i({g2a[2*W +: W], g2a[W +: W]}), .a_o(q1a), .b_o(q1b), .t_o(q1t), .z_o(zu7));
    // lanes: 0 H2', 1 N1; x = a, y = b, z = t
    // ---- the angles ------------------------------------------------------------------------------------------
    wire [W-1:0] gam_a_unused, gam_b_unused, lam_b_unused, ang_t_unused0, ang_t_unused1, mag;
    wire [ZW-1:0] gam_z, lam_z;
    spec_cordic_pass #(.LANES(1), .ANGLE(1)) u_gamma (
        .clk(clk), .a_i(q1t[0 +: W]), .b_i(q1a[0 +: W]), .t_i({W{1'b0}}),
        .a_o(gam_a_unused), .b_o(gam_b_unused), .t_o(ang_t_unused0), .z_o(gam_z));
    spec_cordic_pass #(.LANES(1), .ANGLE(1)) u_lambda (
        .clk(clk), .a_i(q1t[W +: W]), .b_i(q1a[W +: W]), .t_i({W{1'b0}}),
        .a_o(mag), .b_o(lam_b_unused), .t_o(ang_t_unused1), .z_o(lam_z));
    wire [W-1:0] c1w;   // cos(theta1) * 2^F / G: N1.z after Q1, waits beside the angle passes
    spec_setup_ramdelay #(.W(W), .N(P)) u_c1wait (.clk(clk), .d(q1t[W +: W]), .q(c1w));
    wire unused_lanes;
    assign unused_lanes = &{1'b0, zu1, zu2, zu3, zu4, zu5, zu6, zu7,
                            gam_a_unused, gam_b_unused, lam_b_unused, ang_t_unused0, ang_t_unused1,
                            p2a[0 +: W], p2b[0 +: W], p2t[0 +: W], p2a[4*W +: W], p3b[2*W-1:W], p3t[3*W-1:W],
                            p3a[3*W-1:W], p4a[0 +: W], p4b[0 +: W], p4t[0 +: W], g2a[0 +: W], g2b[0 +: W],
                            g2t[0 +: W], q1a[W +: W], q1b, q1t[0 +: W], n2x[0]};
    `undef X_
    `undef Y_
    `undef Z_

    // ---- back end: stage k holds what edge T_ANG + k registered ---------------------------------------------
    wire b0_rule = side_q[SIDE_W-1];
    wire b0_bad = side_q[SIDE_W-2];
    wire [STR_W-1:0] b0_s = side_q[N_W+L_W +: STR_W];
    wire [N_W-1:0] b0_n = side_q[L_W +: N_W];
    wire [L_W-1:0] b0_l = side_q[0 +: L_W];
    // dzeta = round(gamma / l): the long path, ZW stages from stage 0
    wire [ZW-1:0] dq;
    spec_setup_div #(.GW(ZW - 1), .LW(L_W), .S(S)) u_div (.clk(clk), .g(gam_z[ZW-2:0]), .l(b0_l), .q(dq));
    // log2 Is: 5 clocks from stage 0
    wire [LF+5:0] ls5;
    spec_setup_log2 #(.TABLE_FILE(LOG2_FILE)) u_log2s (.clk(clk), .x({{(F + 2 - STR_W) {1'b0}}, b0_s}), .y(ls5));
    // 1: flat, -lambda, the middle of the angle interval, A's operand
    localparam signed [ZW-1:0] FLAT_Z = `SETUP_FLAT_Z;
    localparam signed [ZW-1:0] HALF_PI = `SETUP_HALF_PI;
    localparam signed [ZW-1:0] PI_Z = `SETUP_PI;
    localparam signed [ZW-1:0] TWO_PI = `SETUP_TWO_PI;
    wire b0_flat = (b0_l == {L_W{1'b0}}) || ($signed(gam_z) < FLAT_Z);
    reg b1_flat, b1_bad, b1_rule, b1_opp, b1_single, b1_npos, b1_szero, b1_c1pos;
    reg signed [ZW-1:0] b1_z0, b1_mid, b1_g;
    reg [W-1:0] b1_x;
    reg [N_W-1:0] b1_n;
    reg [L_W-1:0] b1_l;
    always @(posedge clk) begin
        b1_flat <= b0_flat;
        b1_bad <= b0_bad;
        b1_rule <= b0_rule;
        b1_opp <= opp_q;
        b1_single <= b0_l == {L_W{1'b0}};
        b1_npos <= b0_n != {N_W{1'b0}};
        b1_szero <= b0_s == {STR_W{1'b0}};
        b1_c1pos <= !c1w[W-1] && (c1w != {W{1'b0}});
        b1_z0 <= -$signed(lam_z);
        b1_mid <= -$signed(lam_z) + ($signed(gam_z) >>> 1);
        b1_g <= gam_z;
        b1_x <= b0_flat ? c1w : mag;
        b1_n <= b0_n;
        b1_l <= b0_l;
    end
    // log2 of A's operand (x > 0; x <= 0 is not used): 5 clocks from stage 1
    wire [LF+5:0] lx6;
    spec_setup_log2 #(.TABLE_FILE(LOG2_FILE)) u_log2x (.clk(clk), .x(b1_x[F+1:0]), .y(lx6));
    // 2: the angle interval moved by 2 pi so that its middle is in [-pi, pi]; x > 0
    reg b2_flat, b2_c1pos, b2_xpos;
    reg [5:0] b2_f;                     // bad, rule, opp, single, npos, szero
    reg signed [ZW-1:0] b2_z0, b2_g;
    reg [N_W-1:0] b2_n;
    reg [L_W-1:0] b2_l;
    always @(posedge clk) begin
        b2_flat <= b1_flat;
        b2_c1pos <= b1_c1pos;
        b2_f <= {b1_bad, b1_rule, b1_opp, b1_single, b1_npos, b1_szero};
        b2_xpos <= !b1_x[W-1] && (b1_x != {W{1'b0}});
        b2_z0 <= (b1_mid > PI_Z) ? b1_z0 - TWO_PI : (b1_mid < -PI_Z) ? b1_z0 + TWO_PI : b1_z0;
        b2_g <= b1_g;
        b2_n <= b1_n;
        b2_l <= b1_l;
    end
    // 3: no highlight, zeta0
    wire signed [ZW-1:0] z0r = (b2_z0 + (1 <<< (S - 1))) >>> S;
    wire unused_z0r;
    assign unused_z0r = &{1'b0, z0r[ZW-1:ANG_W]};
    // the span's facts from here on: {flat, xpos, nohl, bad, rule, opp, single, npos, szero}
    localparam FB = 9;
    reg [FB-1:0] fb[3:10];
    reg [ANG_W-1:0] zq[3:10];
    reg [N_W-1:0] nq[3:10];
    reg [L_W-1:0] lq[3:10];
    always @(posedge clk) begin
        fb[3] <= {b2_flat, b2_xpos,
                  b2_f[1] && (b2_flat ? !b2_c1pos : ((b2_z0 + b2_g <= -HALF_PI) || (b2_z0 >= HALF_PI))), b2_f};
        zq[3] <= b2_flat ? {ANG_W{1'b0}} : z0r[ANG_W-1:0];
        nq[3] <= b2_n;
        lq[3] <= b2_l;
    end
    integer st;
    always @(posedge clk) begin
        for (st = 4; st <= 10; st = st + 1) begin
            fb[st] <= fb[st-1];
            zq[st] <= zq[st-1];
            nq[st] <= nq[st-1];
            lq[st] <= lq[st-1];
        end
    end
    reg [LF+5:0] ls6;
    always @(posedge clk) ls6 <= ls5;
    // 7: -log2 A clamped to [0, 31] (0 when x <= 0: not used), log2 Is
    localparam [LF+6:0] OFF = F << LF;
    localparam [LF+6:0] OFF_FLAT = (F << LF) - `SETUP_LOG2_GAIN;
    localparam [LF+6:0] LA_MAX = 31 << LF;
    wire signed [LF+7:0] la_raw = $signed({1'b0, fb[6][8] ? OFF_FLAT : OFF}) - $signed({2'b00, lx6});
    reg [LF+5:0] b7_la;
    reg signed [LF+7:0] b7_lis;
    always @(posedge clk) begin
        b7_la <= (!fb[6][7] || la_raw < 0) ? {(LF + 6) {1'b0}}
               : (la_raw > $signed({1'b0, LA_MAX})) ? LA_MAX[LF+5:0] : la_raw[LF+5:0];
        b7_lis <= $signed({2'b00, ls6}) - $signed(STR_FRAC << LF);
    end
    // 8-9: n * (-log2 A), two stages for the multiplier
    reg [LF+N_W+5:0] b8_p, b9_p;
    reg signed [LF+7:0] b8_lis, b9_lis;
    always @(posedge clk) begin
        b8_p <= b7_la * nq[7];
        b9_p <= b8_p;
        b8_lis <= b7_lis;
        b9_lis <= b8_lis;
    end
    // 10: p = -log2 C
    localparam PW = LF + N_W + 8;
    reg signed [PW-1:0] b10_p;
    always @(posedge clk) b10_p <= $signed({2'b00, b9_p}) - $signed({{(PW - LF - 8) {b9_lis[LF+7]}}, b9_lis});
    // 11-14: the code
    wire [C_W-1:0] code14;
    spec_setup_exp2 #(.PW(PW), .TABLE_FILE(EXP2_FILE)) u_exp2 (.clk(clk), .p(b10_p), .code(code14));
    // 15: register 1 and the flags
    reg [FB:0] f11, f12, f13, f14;       // the facts and "p <= 0" (C >= 1)
    reg [ANG_W-1:0] z11, z12, z13, z14;
    reg [N_W-1:0] n11, n12, n13, n14;
    reg [L_W-1:0] l11, l12, l13, l14;
    always @(posedge clk) begin
        f11 <= {b10_p <= 0, fb[10]};
        {f12, f13, f14} <= {f11, f12, f13};
        {z11, z12, z13, z14} <= {zq[10], z11, z12, z13};
        {n11, n12, n13, n14} <= {nq[10], n11, n12, n13};
        {l11, l12, l13, l14} <= {lq[10], l11, l12, l13};
    end
    wire e_sat = f14[9], e_flat = f14[8], e_xpos = f14[7], e_nohl = f14[6], e_bad = f14[5], e_rule = f14[4];
    wire e_opp = f14[3], e_single = f14[2], e_npos = f14[1], e_szero = f14[0];
    wire e_zero = e_bad || e_nohl || e_szero || (e_npos && !e_xpos);   // C = 0
    wire [C_W-1:0] e_c = e_zero ? {C_W{1'b0}} : e_sat ? {C_W{1'b1}} : code14;
    wire [6:0] e_flags = e_bad ? {1'b1, 2'b00, e_single, 3'b000}
                               : {1'b0, e_rule, e_nohl, e_single, !e_zero && e_sat, e_opp, e_flat};
    // the descriptor waits for the quotient (stage ZW); flat and invalid spans get dzeta = 0
    localparam FIN_W = C_W + 7 + N_W + L_W + ANG_W;
    localparam WAIT = ZW - 15;
    reg [FIN_W-1:0] fin_d;
    wire [FIN_W-1:0] fin_q;
    always @(posedge clk) fin_d <= {e_c, e_flags, n14, l14, e_bad ? {ANG_W{1'b0}} : z14};
    spec_setup_ramdelay #(.W(FIN_W), .N(WAIT)) u_fin (.clk(clk), .d(fin_d), .q(fin_q));
    wire [6:0] o_flags = fin_q[ANG_W+L_W+N_W +: 7];
    always @(posedge clk) begin
        out_c <= fin_q[ANG_W+L_W+N_W+7 +: C_W];
        out_flags <= o_flags;
        out_n <= fin_q[ANG_W+L_W +: N_W];
        out_l <= fin_q[ANG_W +: L_W];
        out_zeta0 <= fin_q[0 +: ANG_W];
        out_dzeta <= (o_flags[0] || o_flags[6]) ? {ANG_W{1'b0}} : dq[ANG_W-1:0];
    end
    wire unused_dq;
    assign unused_dq = &{1'b0, dq[ZW-1:ANG_W]};
endmodule
`default_nettype wire
