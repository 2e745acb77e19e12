// spec_setup_misc - spec_setup's compare-and-select unit (rom/gen/setup_program.cpp): a < b ? 1 : 0, c ? a : b,
// min(a, b), max(a, b) on the signed values (zero has no sign), the result times 2^scale (zero stays zero; out of
// range: zero or the largest value, as fp_scale). For SEL, a and b are the two values (ports 0, 1) and c the
// condition (port 2: its bank keeps only whether the value was zero). Two register stages.
`timescale 1ns / 1ps
`default_nettype none
module spec_setup_misc #(
    parameter FM = 22,
    parameter FE = 8,
    parameter SCALE_W = 4
) (
    input  wire               clk,
    input  wire [FE+FM:0]     a,
    input  wire [FE+FM:0]     b,
    input  wire               c,
    input  wire [1:0]         op,      // 0 a < b, 1 c ? a : b, 2 min, 3 max
    input  wire [SCALE_W-1:0] scale,
    output reg  [FE+FM:0]     r
);
    localparam W = FE + FM + 1;
    localparam KW = FE + 4;
    localparam signed [KW-1:0] EMIN = -(1 <<< (FE - 1));
    localparam signed [KW-1:0] EMAX = (1 <<< (FE - 1)) - 1;

    // ---- 1: a < b
    wire az = ~|a[FM-1:0], bz = ~|b[FM-1:0];
    wire an = a[FE+FM] & ~az, bn = b[FE+FM] & ~bz;
    wire signed [FE-1:0] ea = a[FE+FM-1:FM], eb = b[FE+FM-1:FM];
    // |a| < |b| and |b| < |a| (a zero is the smallest magnitude)
    wire amag_lt = bz ? 1'b0 : (az ? 1'b1 : (ea != eb ? ea < eb : a[FM-1:0] < b[FM-1:0]));
    wire bmag_lt = az ? 1'b0 : (bz ? 1'b1 : (ea != eb ? eb < ea : b[FM-1:0] < a[FM-1:0]));
    wire lt = an != bn ? an : (an ? bmag_lt : amag_lt);
    reg [W-1:0] s1_a, s1_b;
    reg s1_c, s1_lt;
    reg [1:0] s1_op;
    reg signed [KW-1:0] s1_k;
    always @(posedge clk) begin
        s1_a <= a;
        s1_b <= b;
        s1_c <= c;
        s1_lt <= lt;
        s1_op <= op;
        s1_k <= $signed({{(KW - SCALE_W) {scale[SCALE_W-1]}}, scale});
    end

    // ---- 2: the choice, scaled
    reg [W-1:0] v;
    always @(*) begin
        case (s1_op)
            2'd0: v = s1_lt ? {1'b0, {FE{1'b0}}, 1'b1, {(FM - 1) {1'b0}}} : {W{1'b0}};
            2'd1: v = s1_c ? s1_a : s1_b;
            2'd2: v = s1_lt ? s1_a : s1_b;
            default: v = s1_lt ? s1_b : s1_a;
        endcase
    end
    wire signed [KW-1:0] e = $signed({{(KW - FE) {v[FE+FM-1]}}, v[FE+FM-1:FM]}) + s1_k;
    always @(posedge clk) begin
        if (~|v[FM-1:0] || e < EMIN) r <= {W{1'b0}};
        else if (e > EMAX) r <= {v[FE+FM], EMAX[FE-1:0], {FM{1'b1}}};
        else r <= {v[FE+FM], e[FE-1:0], v[FM-1:0]};
    end
endmodule
`default_nettype wire
