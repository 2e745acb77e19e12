// spec_setup_fadd - spec_setup's floating-point adder (rom/gen/setup_fp.h, fp_add): (a + b * 2^bscale) * 2^scale.
// The larger magnitude keeps FG guard bits below its last bit, the smaller is shifted right by the exponent
// difference (the bits below the guard bits dropped), the two are added or subtracted and rounded once.
// Pipelined, a new operation every clock:
//   1  b scaled by 2^bscale (zero stays zero; out of range: zero or the largest value, as fp_scale)
//   2  the larger magnitude to x, the smaller to y
//   3  y aligned to x
//   4  the sum or difference
//   5-7  spec_setup_fpround
`timescale 1ns / 1ps
`default_nettype none
module spec_setup_fadd #(
    parameter FM = 22,
    parameter FE = 8,
    parameter FG = 3,
    parameter SCALE_W = 4
) (
    input  wire               clk,
    input  wire [FE+FM:0]     a,
    input  wire [FE+FM:0]     b,
    input  wire [2:0]         bscale,
    input  wire [SCALE_W-1:0] scale,
    output wire [FE+FM:0]     r
);
    localparam W = FE + FM + 1;
    localparam KW = FE + 4;
    localparam signed [KW-1:0] EMIN = -(1 <<< (FE - 1));
    localparam signed [KW-1:0] EMAX = (1 <<< (FE - 1)) - 1;
    localparam XW = FM + FG + 1;

    // ---- 1: b * 2^bscale
    wire b_z = ~|b[FM-1:0];
    wire signed [KW-1:0] eb = $signed({{(KW - FE) {b[FE+FM-1]}}, b[FE+FM-1:FM]}) + $signed({{(KW - 3) {bscale[2]}}, bscale});
    reg [W-1:0] s1_a, s1_b;
    reg signed [KW-1:0] s1_k;
    always @(posedge clk) begin
        s1_a <= a;
        if (b_z || eb < EMIN) s1_b <= {W{1'b0}};
        else if (eb > EMAX) s1_b <= {b[FE+FM], EMAX[FE-1:0], {FM{1'b1}}};
        else s1_b <= {b[FE+FM], eb[FE-1:0], b[FM-1:0]};
        s1_k <= $signed({{(KW - SCALE_W) {scale[SCALE_W-1]}}, scale});
    end

    // ---- 2: |a| < |b| (a zero is the smallest; zero words are all 0) -> swap
    wire a_z = ~|s1_a[FM-1:0], bz = ~|s1_b[FM-1:0];
    wire signed [FE-1:0] ea = s1_a[FE+FM-1:FM], ebb = s1_b[FE+FM-1:FM];
    wire a_less = bz ? 1'b0 : (a_z ? 1'b1 : (ea != ebb ? ea < ebb : s1_a[FM-1:0] < s1_b[FM-1:0]));
    reg [W-1:0] s2_x, s2_y;
    reg signed [KW-1:0] s2_k;
    always @(posedge clk) begin
        s2_x <= a_less ? s1_b : s1_a;
        s2_y <= a_less ? s1_a : s1_b;
        s2_k <= s1_k;
    end

    // ---- 3: align
    wire signed [FE:0] d = $signed({s2_x[FE+FM-1], s2_x[FE+FM-1:FM]}) - $signed({s2_y[FE+FM-1], s2_y[FE+FM-1:FM]});
    wire far = d >= FM + FG;
    wire [FM+FG-1:0] yx = {s2_y[FM-1:0], {FG{1'b0}}};
    reg [FM+FG-1:0] s3_xm, s3_ym;
    reg s3_sub, s3_s;
    reg signed [KW-1:0] s3_k;
    always @(posedge clk) begin
        s3_xm <= {s2_x[FM-1:0], {FG{1'b0}}};
        s3_ym <= far ? {(FM + FG) {1'b0}} : yx >> d[FE-1:0];
        s3_sub <= s2_x[FE+FM] ^ s2_y[FE+FM];
        s3_s <= s2_x[FE+FM];
        // the sum's last bit is worth 2^(ex - (FM - 1) - FG)
        s3_k <= $signed({{(KW - FE) {s2_x[FE+FM-1]}}, s2_x[FE+FM-1:FM]}) - (FM - 1) - FG + s2_k;
    end

    // ---- 4: add or subtract (x >= y in magnitude)
    reg [XW-1:0] s4_x;
    reg s4_s;
    reg signed [KW-1:0] s4_k;
    always @(posedge clk) begin
        s4_x <= s3_sub ? {1'b0, s3_xm} - {1'b0, s3_ym} : {1'b0, s3_xm} + {1'b0, s3_ym};
        s4_s <= s3_s;
        s4_k <= s3_k;
    end
    spec_setup_fpround #(.FM(FM), .FE(FE), .XW(XW), .KW(KW)) u_round (
        .clk(clk), .s(s4_s), .x(s4_x), .k(s4_k), .r(r)
    );
    wire unused;
    assign unused = &{1'b0, d[FE]};
endmodule
`default_nettype wire
