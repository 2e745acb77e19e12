// spec_setup_idot - spec_setup's exact front end (rom/gen/setup_program.cpp, setup_idot): a dot product, a
// component of a cross product, a component, or a scalar of the span-ends beat, computed exactly from the 16-bit
// fields and rounded once to floating point (the strength times 2^-STR_FRAC). The vectors are N1, N2, H1, H2 and
// PN = N1 x e_k (spec_setup's pre-stage); the scalars the rule, the strength, n and l. Pipelined:
//   1  the operands of the three products for the mode
//   2  the products (DSP blocks)
//   3  their sum (the second one subtracted for a cross product), its magnitude
//   4-6  spec_setup_fpround
`timescale 1ns / 1ps
`default_nettype none
module spec_setup_idot #(
    parameter FM = 22,
    parameter FE = 8,
    parameter VEC_W = 16,
    parameter STR_W = 16,
    parameter STR_FRAC = 15,
    parameter N_W = 10,
    parameter L_W = 16
) (
    input  wire                 clk,
    input  wire [15*VEC_W+14:0] vec,      // N1, N2, H1, H2, PN: x, y, z each, VEC_W + 1 bits two's complement
    input  wire                 rule,
    input  wire [STR_W-1:0]     strength,
    input  wire [N_W-1:0]       n,
    input  wire [L_W-1:0]       l,
    input  wire [2:0]           mode,     // 0 dot, 1..3 cross x, y, z, 4 component, 5 scalar
    input  wire [2:0]           va,       // vectors (0 N1 .. 4 PN)
    input  wire [2:0]           vb,
    input  wire [1:0]           comp,     // component (mode 4) or scalar (mode 5: rule, strength, n, l)
    output wire [FE+FM:0]       r
);
    localparam XW = VEC_W + 1;   // operand width (a component; a scalar zero-extended)
    localparam CW = VEC_W + 1;
    localparam KW = FE + 4;

    // the two vectors (5:1 each), then the components by the mode
    function [3*CW-1:0] pick(input [2:0] sel, input [15*CW-1:0] v);
        case (sel)
            3'd0: pick = v[0 +: 3 * CW];
            3'd1: pick = v[3 * CW +: 3 * CW];
            3'd2: pick = v[6 * CW +: 3 * CW];
            3'd3: pick = v[9 * CW +: 3 * CW];
            default: pick = v[12 * CW +: 3 * CW];
        endcase
    endfunction
    wire [3*CW-1:0] A = pick(va, vec);
    wire [3*CW-1:0] B = pick(vb, vec);
    wire [XW-1:0] a0 = A[0 +: CW], a1 = A[CW +: CW], a2 = A[2*CW +: CW];
    wire [XW-1:0] b0 = B[0 +: CW], b1 = B[CW +: CW], b2 = B[2*CW +: CW];
    wire [XW-1:0] ac = comp == 2'd0 ? a0 : (comp == 2'd1 ? a1 : a2);
    reg [XW-1:0] sc;
    always @(*) begin
        case (comp)
            2'd0: sc = {{(XW - 1) {1'b0}}, rule};
            2'd1: sc = {{(XW - STR_W) {1'b0}}, strength};
            2'd2: sc = {{(XW - N_W) {1'b0}}, n};
            default: sc = {{(XW - L_W) {1'b0}}, l};
        endcase
    end
    localparam [XW-1:0] ONE = 1, ZERO = 0;

    // ---- 1: the operands
    reg [XW-1:0] s1_x0, s1_x1, s1_x2, s1_y0, s1_y1, s1_y2;
    reg s1_neg;
    reg signed [KW-1:0] s1_k;
    always @(posedge clk) begin
        s1_neg <= 1'b0;
        s1_k <= 0;
        case (mode)
            3'd0: {s1_x0, s1_y0, s1_x1, s1_y1, s1_x2, s1_y2} <= {a0, b0, a1, b1, a2, b2};
            3'd1: {s1_x0, s1_y0, s1_x1, s1_y1, s1_x2, s1_y2} <= {a1, b2, a2, b1, ZERO, ZERO};
            3'd2: {s1_x0, s1_y0, s1_x1, s1_y1, s1_x2, s1_y2} <= {a2, b0, a0, b2, ZERO, ZERO};
            3'd3: {s1_x0, s1_y0, s1_x1, s1_y1, s1_x2, s1_y2} <= {a0, b1, a1, b0, ZERO, ZERO};
            3'd4: {s1_x0, s1_y0, s1_x1, s1_y1, s1_x2, s1_y2} <= {ac, ONE, ZERO, ZERO, ZERO, ZERO};
            default: {s1_x0, s1_y0, s1_x1, s1_y1, s1_x2, s1_y2} <= {sc, ONE, ZERO, ZERO, ZERO, ZERO};
        endcase
        if (mode == 3'd1 || mode == 3'd2 || mode == 3'd3) s1_neg <= 1'b1;
        if (mode > 3'd4 && comp == 2'd1) s1_k <= -STR_FRAC;
    end

    // ---- 2: the products
    reg signed [2*XW-1:0] s2_p0, s2_p1, s2_p2;
    reg s2_neg;
    reg signed [KW-1:0] s2_k;
    always @(posedge clk) begin
        s2_p0 <= $signed(s1_x0) * $signed(s1_y0);
        s2_p1 <= $signed(s1_x1) * $signed(s1_y1);
        s2_p2 <= $signed(s1_x2) * $signed(s1_y2);
        s2_neg <= s1_neg;
        s2_k <= s1_k;
    end

    // ---- 3: the sum
    wire signed [2*XW+1:0] p0 = {{2{s2_p0[2*XW-1]}}, s2_p0}, p1 = {{2{s2_p1[2*XW-1]}}, s2_p1}, p2 = {{2{s2_p2[2*XW-1]}}, s2_p2};
    wire signed [2*XW+1:0] sum = p0 + (s2_neg ? -p1 : p1) + p2;
    reg s3_s;
    reg [2*XW+1:0] s3_x;
    reg signed [KW-1:0] s3_k;
    always @(posedge clk) begin
        s3_s <= sum < 0;
        s3_x <= sum < 0 ? -sum : sum;
        s3_k <= s2_k;
    end
    spec_setup_fpround #(.FM(FM), .FE(FE), .XW(2 * XW + 2), .KW(KW)) u_round (
        .clk(clk), .s(s3_s), .x(s3_x), .k(s3_k), .r(r)
    );
endmodule
`default_nettype wire
