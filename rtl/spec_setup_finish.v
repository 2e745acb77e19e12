// spec_setup_finish - spec_setup's finish stage (sim/setup/setup_model.cpp, SetupModel::finish): the program's
// results of a span (spec_setup_machine reads them one a clock, fin_field 0..8 in SetupOut order) and its side
// information (written at the span's start) into spec_stream's descriptor and the flags, in fixed point:
//   - flat: l = 0 or the patent's gamma below 2^FLAT_LOG2; opposite normals: 1 + N1.N2 below OPP_EPS;
//   - not flat: zeta0 = -lambda and gamma to ZF fraction bits, [zeta0, zeta0 + gamma] moved by 2 pi so that its
//     middle is in [-pi, pi], no highlight when it lies beyond +-pi/2; zeta0 rounded to the core's ANG_FRAC bits,
//     dzeta = gamma / l to ANG_FRAC bits;
//   - C = 2^-p from an exp2 table (2^EXP_T intervals, linear interpolation on EXP_R bits): p <= 0 saturates,
//     p >= 64 or an integer part above C_W + 1 gives 0; no highlight or an invalid span: C = 0.
// A conversion to fixed point rounds half away from zero and saturates at |x| = 2^sat. Fully pipelined; a span's
// descriptor leaves seven clocks after its last field. Reset (synchronous): every span's valid bit is cleared, so
// that the results of spans started before the reset never make a descriptor.
`timescale 1ns / 1ps
`default_nettype none
`include "setup_params.vh"
`include "spec_params.vh"
module spec_setup_finish #(
    parameter EXP2_FILE = `SETUP_EXP2_FILE
) (
    input  wire                      clk,
    input  wire                      rst,
    // side information, written at a span's start
    input  wire                      side_we,
    input  wire [`SETUP_STAGE_W-1:0] side_span,
    input  wire                      side_valid,
    input  wire                      side_invalid,
    input  wire                      side_rule,
    input  wire [`SPEC_N_W-1:0]      side_n,
    input  wire [`SPEC_L_W-1:0]      side_l,
    // the program's results
    input  wire                      fin_en,
    input  wire [3:0]                fin_field,
    input  wire [`SETUP_STAGE_W-1:0] fin_span,
    input  wire [`SETUP_W-1:0]       fin_data,
    // the descriptor (a pulse per valid span)
    output reg                       d_valid,
    output reg  [`SPEC_C_W-1:0]      d_c,
    output reg  [`SPEC_N_W-1:0]      d_n,
    output reg  [`SPEC_L_W-1:0]      d_l,
    output reg  [`SPEC_ANG_W-1:0]    d_zeta0,
    output reg  [`SPEC_ANG_W-1:0]    d_dzeta,
    output reg  [6:0]                d_flags
);
    localparam FM = `SETUP_FM, FE = `SETUP_FE, W = `SETUP_W, SW = `SETUP_STAGE_W;
    localparam ZF = `SETUP_ZF, LF = `SETUP_LF, AF = `SPEC_ANG_FRAC, C_W = `SPEC_C_W, N_W = `SPEC_N_W, L_W = `SPEC_L_W;
    localparam ET = `SETUP_EXP_T, ER = `SETUP_EXP_R, EF = `SETUP_EXP_F;
    localparam ZW = ZF + 5;   // angles in fixed point: |x| < 4 (and sums of two), two's complement
    localparam [W-1:0] FLAT_W = `SETUP_FLAT_WORD, OPP_W = `SETUP_OPP_WORD;
    localparam [39:0] PI40 = `SETUP_PI_Z, TWO_PI40 = `SETUP_TWO_PI_Z, HALF_PI40 = `SETUP_HALF_PI_Z;
    localparam signed [ZW-1:0] PI = PI40[ZW-1:0], TWO_PI = TWO_PI40[ZW-1:0], HALF_PI = HALF_PI40[ZW-1:0];

    // a < b for floating-point words (zero has no sign)
    function less;
        input [W-1:0] a, b;
        reg az, bz, an, bn, amag;
        begin
            az = ~|a[FM-1:0];
            bz = ~|b[FM-1:0];
            an = a[W-1] & ~az;
            bn = b[W-1] & ~bz;
            if (an != bn) less = an;
            else begin
                // |a| < |b|
                if (bz) amag = 1'b0;
                else if (az) amag = 1'b1;
                else if (a[W-2:FM] != b[W-2:FM]) amag = $signed(a[W-2:FM]) < $signed(b[W-2:FM]);
                else amag = a[FM-1:0] < b[FM-1:0];
                // both negative: |b| < |a|
                if (an) less = ~amag & (a[W-2:0] != b[W-2:0]);
                else less = amag;
            end
        end
    endfunction

    // ---- side information --------------------------------------------------------------------------------------
    reg [2+N_W+L_W-1:0] side[0:(1 << SW) - 1];
    reg [(1<<SW)-1:0] side_v;
    always @(posedge clk) begin
        if (side_we) side[side_span] <= {side_invalid, side_rule, side_n, side_l};
        if (rst) side_v <= {(1 << SW) {1'b0}};
        else if (side_we) side_v[side_span] <= side_valid;
    end
    reg [3+N_W+L_W-1:0] si;   // this span's, read with field 0
    always @(posedge clk) if (fin_en && fin_field == 4'd0) si <= {side_v[fin_span], side[fin_span]};

    // ---- fixed point (two stages): round(x * 2^frac), half away from zero, |x| < 2^sat
    //   frac, sat by field: gamma, lambda ZF, 2; dzeta AF, 2
    wire [FM-1:0] xm = fin_data[FM-1:0];
    wire signed [FE-1:0] xe = fin_data[W-2:FM];
    wire [6:0] frac = fin_field == 4'd3 ? AF[6:0] : ZF[6:0];
    wire signed [FE+2:0] sh = $signed({{3{xe[FE-1]}}, xe}) - (FM - 1) + $signed({3'b000, frac});   // left shift of m
    reg c1_sat, c1_z, c1_s, c1_rb;
    reg [ZF+2:0] c1_m;     // |x| * 2^frac before rounding, up to 2^(sat + frac)
    reg [6:0] c1_frac;
    reg [3:0] c1_field;
    reg c1_en;
    wire [FM+ZF+2:0] lsh = {{(ZF + 3) {1'b0}}, xm} << (sh > 0 ? sh[5:0] : 6'd0);
    wire [FM:0] rsh = {xm, 1'b0} >> (sh < 0 ? (-sh > FM + 1 ? FM + 1 : -sh) : 0);
    always @(posedge clk) begin
        c1_en <= fin_en;
        c1_field <= fin_field;
        c1_frac <= frac;
        c1_z <= ~|xm;
        c1_s <= fin_data[W-1];
        c1_sat <= xe >= 2;
        c1_m <= sh >= 0 ? lsh[ZF+2:0] : {{(ZF + 3 - FM) {1'b0}}, rsh[FM:1]};
        c1_rb <= sh < 0 && rsh[0];
    end
    wire [ZF+2:0] top = c1_frac == AF[6:0] ? {{(ZF - AF) {1'b0}}, {(AF + 3) {1'b1}}} >> 1 : {(ZF + 3) {1'b1}} >> 1;
    wire [ZF+3:0] mr = {1'b0, c1_m} + {{(ZF + 3) {1'b0}}, c1_rb};
    wire [ZF+2:0] mag = c1_z ? {(ZF + 3) {1'b0}} : (c1_sat || mr > {1'b0, top}) ? top : mr[ZF+2:0];
    wire signed [ZW-1:0] fx = c1_s ? -$signed({{(ZW - ZF - 3) {1'b0}}, mag}) : $signed({{(ZW - ZF - 3) {1'b0}}, mag});

    // ---- the fields ------------------------------------------------------------------------------------------------
    reg flat_g, c1_le0, opp, ok;
    reg signed [ZW-1:0] g, z0, dz;
    reg [W-1:0] p_nf, p_f;
    reg last;   // the last field arrived
    always @(posedge clk) begin
        last <= ~rst & fin_en & (fin_field == 4'd8);
        if (fin_en) begin
            case (fin_field)
                4'd0: flat_g <= less(fin_data, FLAT_W);
                4'd4: p_nf <= fin_data;
                4'd5: p_f <= fin_data;
                4'd6: c1_le0 <= (~|fin_data[FM-1:0]) | fin_data[W-1];
                4'd7: opp <= less(fin_data, OPP_W);
                4'd8: ok <= |fin_data[FM-1:0];
                default: ;
            endcase
        end
        if (c1_en) begin
            case (c1_field)
                4'd1: g <= fx;
                4'd2: z0 <= -fx;
                4'd3: dz <= fx;
                default: ;
            endcase
        end
    end

    // ---- the tail: flat, wrap, no highlight, p -> C -----------------------------------------------------------------
    // 1: take the span
    reg t1_v, t1_valid, t1_invalid, t1_rule, t1_flat, t1_c1le0, t1_opp, t1_ok;
    reg [N_W-1:0] t1_n;
    reg [L_W-1:0] t1_l;
    reg signed [ZW-1:0] t1_g, t1_z0, t1_dz, t1_mid;
    reg [W-1:0] t1_p;
    always @(posedge clk) begin
        t1_v <= last & ~rst;
        {t1_valid, t1_invalid, t1_rule, t1_n, t1_l} <= si;
        t1_flat <= (si[L_W-1:0] == {L_W{1'b0}}) | flat_g;
        t1_c1le0 <= c1_le0;
        t1_opp <= opp;
        t1_ok <= ok;
        t1_g <= g;
        t1_z0 <= z0;
        t1_dz <= dz;
        t1_mid <= z0 + (g >>> 1);
        t1_p <= ((si[L_W-1:0] == {L_W{1'b0}}) | flat_g) ? p_f : p_nf;
    end
    // 2: the interval's middle into [-pi, pi]
    reg t2_v, t2_valid, t2_invalid, t2_rule, t2_flat, t2_c1le0, t2_opp, t2_ok;
    reg [N_W-1:0] t2_n;
    reg [L_W-1:0] t2_l;
    reg signed [ZW-1:0] t2_g, t2_z0, t2_dz;
    reg [W-1:0] t2_p;
    always @(posedge clk) begin
        t2_v <= t1_v & ~rst;
        {t2_valid, t2_invalid, t2_rule, t2_flat, t2_c1le0, t2_opp, t2_ok, t2_n, t2_l} <=
            {t1_valid, t1_invalid, t1_rule, t1_flat, t1_c1le0, t1_opp, t1_ok, t1_n, t1_l};
        t2_g <= t1_g;
        t2_dz <= t1_dz;
        t2_p <= t1_p;
        t2_z0 <= t1_mid > PI ? t1_z0 - TWO_PI : (t1_mid < -PI ? t1_z0 + TWO_PI : t1_z0);
    end
    // 3: no highlight, zeta0 rounded; p to fixed point (first half)
    wire signed [ZW-1:0] zend = t2_z0 + t2_g;
    wire nohl = (t2_n != {N_W{1'b0}}) && (t2_flat ? t2_c1le0 : (zend <= -HALF_PI || t2_z0 >= HALF_PI));
    wire [FM-1:0] pm = t2_p[FM-1:0];
    wire signed [FE-1:0] pe = t2_p[W-2:FM];
    wire signed [FE+2:0] psh = $signed({{3{pe[FE-1]}}, pe}) - (FM - 1) + LF;
    wire [FM+LF+6:0] plsh = {{(LF + 7) {1'b0}}, pm} << (psh > 0 ? psh[5:0] : 6'd0);
    wire [FM:0] prsh = {pm, 1'b0} >> (psh < 0 ? (-psh > FM + 1 ? FM + 1 : -psh) : 0);
    reg t3_v, t3_valid, t3_invalid, t3_rule, t3_flat, t3_opp, t3_ok, t3_nohl, t3_sat, t3_zero, t3_rb;
    reg [N_W-1:0] t3_n;
    reg [L_W-1:0] t3_l;
    reg signed [ZW-1:0] t3_z0, t3_dz;
    reg [LF+6:0] t3_q;
    always @(posedge clk) begin
        t3_v <= t2_v & ~rst;
        {t3_valid, t3_invalid, t3_rule, t3_flat, t3_opp, t3_ok, t3_n, t3_l} <=
            {t2_valid, t2_invalid, t2_rule, t2_flat, t2_opp, t2_ok, t2_n, t2_l};
        t3_nohl <= nohl;
        t3_z0 <= (t2_z0 + (1 <<< (ZF - AF - 1))) >>> (ZF - AF);
        t3_dz <= t2_dz;
        t3_sat <= (~|pm) | t2_p[W-1];             // p <= 0: C >= 1
        t3_zero <= pe >= 6;                        // p >= 64: C = 0
        t3_q <= psh >= 0 ? plsh[LF+6:0] : {{(LF + 7 - FM) {1'b0}}, prsh[FM:1]};
        t3_rb <= psh < 0 && prsh[0];
    end
    // 4: p rounded; the exp2 table's position
    wire [LF+7:0] q = {1'b0, t3_q} + {{(LF + 7) {1'b0}}, t3_rb};
    wire [6:0] pint = q[LF+6:LF];
    wire [ET+ER-1:0] pos = q[LF-1 -: ET + ER];
    reg t4_v, t4_valid, t4_invalid, t4_rule, t4_flat, t4_opp, t4_ok, t4_nohl, t4_sat, t4_zero;
    reg [N_W-1:0] t4_n;
    reg [L_W-1:0] t4_l;
    reg signed [ZW-1:0] t4_z0, t4_dz;
    reg [6:0] t4_pint;
    reg [ET-1:0] t4_i;
    reg [ER-1:0] t4_f;
    always @(posedge clk) begin
        t4_v <= t3_v & ~rst;
        {t4_valid, t4_invalid, t4_rule, t4_flat, t4_opp, t4_ok, t4_nohl, t4_sat, t4_n, t4_l} <=
            {t3_valid, t3_invalid, t3_rule, t3_flat, t3_opp, t3_ok, t3_nohl, t3_sat, t3_n, t3_l};
        t4_zero <= t3_zero | (q[LF+7:LF] > C_W + 1);
        t4_z0 <= t3_z0;
        t4_dz <= t3_dz;
        t4_pint <= pint;
        t4_i <= pos[ET+ER-1:ER];
        t4_f <= pos[ER-1:0];
    end
    // 5: the table (two reads, the last interval's end word a constant)
    reg [EF:0] e2rom[0:(1 << ET) - 1];
    initial $readmemh(EXP2_FILE, e2rom);
    spec_setup_imgcheck #(.FILE(EXP2_FILE), .WORDS(1 << ET), .DIGITS((EF + 4) / 4)) u_check ();
    wire [ET-1:0] i1 = t4_i + 1'b1;
    reg [EF:0] t5_a, t5_b;
    reg t5_end;
    reg t5_v, t5_valid, t5_invalid, t5_rule, t5_flat, t5_opp, t5_ok, t5_nohl, t5_sat, t5_zero;
    reg [N_W-1:0] t5_n;
    reg [L_W-1:0] t5_l;
    reg signed [ZW-1:0] t5_z0, t5_dz;
    reg [6:0] t5_pint;
    reg [ER-1:0] t5_f;
    always @(posedge clk) begin
        t5_a <= e2rom[t4_i];
        t5_b <= e2rom[i1];
        t5_end <= &t4_i;
        t5_v <= t4_v & ~rst;
        {t5_valid, t5_invalid, t5_rule, t5_flat, t5_opp, t5_ok, t5_nohl, t5_sat, t5_zero, t5_n, t5_l} <=
            {t4_valid, t4_invalid, t4_rule, t4_flat, t4_opp, t4_ok, t4_nohl, t4_sat, t4_zero, t4_n, t4_l};
        t5_z0 <= t4_z0;
        t5_dz <= t4_dz;
        t5_pint <= t4_pint;
        t5_f <= t4_f;
    end
    // 6: (next - this) * fraction
    wire [EF:0] e2end = `SETUP_EXP2_END;
    wire signed [EF+1:0] ed = $signed({1'b0, t5_end ? e2end : t5_b}) - $signed({1'b0, t5_a});
    reg signed [EF+ER+2:0] t6_p;
    reg [EF:0] t6_a;
    reg t6_v, t6_valid, t6_invalid, t6_rule, t6_flat, t6_opp, t6_ok, t6_nohl, t6_sat, t6_zero;
    reg [N_W-1:0] t6_n;
    reg [L_W-1:0] t6_l;
    reg signed [ZW-1:0] t6_z0, t6_dz;
    reg [6:0] t6_pint;
    always @(posedge clk) begin
        t6_p <= ed * $signed({1'b0, t5_f});
        t6_a <= t5_a;
        t6_v <= t5_v & ~rst;
        {t6_valid, t6_invalid, t6_rule, t6_flat, t6_opp, t6_ok, t6_nohl, t6_sat, t6_zero, t6_n, t6_l} <=
            {t5_valid, t5_invalid, t5_rule, t5_flat, t5_opp, t5_ok, t5_nohl, t5_sat, t5_zero, t5_n, t5_l};
        t6_z0 <= t5_z0;
        t6_dz <= t5_dz;
        t6_pint <= t5_pint;
    end
    // 7: 2^-f, then shifted by the integer part and rounded: C
    wire signed [EF+ER+2:0] epr = t6_p + (1 <<< (ER - 1));
    wire signed [EF+ER+2:0] epr_s = epr >>> ER;
    wire signed [EF+2:0] e2v = $signed({2'b00, t6_a}) + epr_s[EF+2:0];
    wire [7:0] cshift = EF - C_W + t6_pint;    // >= 1
    wire [EF+1:0] code = ({e2v[EF:0], 1'b0} + ({{EF{1'b0}}, 2'b10} << (cshift - 1))) >> (cshift + 1);
    wire [C_W-1:0] cmax = {C_W{1'b1}};
    always @(posedge clk) begin
        d_valid <= t6_v & t6_valid & ~rst;
        d_n <= t6_n;
        d_l <= t6_l;
        d_flags <= {t6_invalid, t6_rule & ~t6_ok & ~t6_flat & ~t6_invalid, ~t6_invalid & t6_nohl,
                    t6_l == {L_W{1'b0}}, ~t6_invalid & ~t6_nohl & t6_sat, ~t6_invalid & t6_opp,
                    ~t6_invalid & t6_flat};
        if (t6_invalid || t6_nohl) begin
            d_c <= {C_W{1'b0}};
        end else if (t6_sat) begin
            d_c <= cmax;
        end else if (t6_zero) begin
            d_c <= {C_W{1'b0}};
        end else begin
            d_c <= code > {{(EF + 2 - C_W) {1'b0}}, cmax} ? cmax : code[C_W-1:0];
        end
        d_zeta0 <= (t6_invalid || t6_flat) ? {`SPEC_ANG_W{1'b0}} : t6_z0[`SPEC_ANG_W-1:0];
        d_dzeta <= (t6_invalid || t6_flat) ? {`SPEC_ANG_W{1'b0}} : t6_dz[`SPEC_ANG_W-1:0];
    end
    wire unused;
    assign unused = &{1'b0, lsh[FM+ZF+2:ZF+3], plsh[FM+LF+6:LF+7], q[LF+7], epr[ER-1:0], epr_s[EF+ER+2:EF+3], e2v[EF+2:EF+1], code[EF+1],
                      mr[ZF+3], t6_z0[ZW-1:`SPEC_ANG_W], t6_dz[ZW-1:`SPEC_ANG_W], pos};
endmodule
`default_nettype wire
