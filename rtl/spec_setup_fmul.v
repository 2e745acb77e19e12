// spec_setup_fmul - spec_setup's floating-point multiplier (rom/gen/setup_fp.h, fp_mul): a * b * 2^scale, the
// exact product of the mantissas rounded once. Pipelined, a new operation every clock; the result leaves
// LAT - 1 clocks after the operands (LAT counts the issue clock, in which the machine reads its banks).
//   1  sign, exponent sum with the scale, the mantissas into the multiplier
//   2  the partial products: the top 18 x 18 bits on a DSP block, the rest (FM - 18 low bits of either
//      operand, FM <= 24) as shift-and-add in logic, so that one DSP block does each product
//   3  their sum
//   4-6  spec_setup_fpround (NORM1: the product's leading one is one of its top two bits)
`timescale 1ns / 1ps
`default_nettype none
module spec_setup_fmul #(
    parameter FM = 22,
    parameter FE = 8,
    parameter SCALE_W = 4
) (
    input  wire               clk,
    input  wire [FE+FM:0]     a,
    input  wire [FE+FM:0]     b,
    input  wire [SCALE_W-1:0] scale,
    output wire [FE+FM:0]     r
);
    localparam KW = FE + 4;
    reg s1_s;
    reg signed [KW-1:0] s1_k;
    reg [FM-1:0] s1_ma, s1_mb;
    always @(posedge clk) begin
        s1_s <= a[FE+FM] ^ b[FE+FM];
        // value = ma * mb * 2^(ea + eb - 2 (FM - 1) + scale)
        s1_k <= $signed({{(KW - FE) {a[FE+FM-1]}}, a[FE+FM-1:FM]}) + $signed({{(KW - FE) {b[FE+FM-1]}}, b[FE+FM-1:FM]}) +
                $signed({{(KW - SCALE_W) {scale[SCALE_W-1]}}, scale}) - 2 * (FM - 1);
        s1_ma <= a[FM-1:0];
        s1_mb <= b[FM-1:0];
    end
    reg [2*FM-1:0] s3_p;
    reg s2_s, s3_s;
    reg signed [KW-1:0] s2_k, s3_k;
    generate
        if (FM <= 18) begin : g_one
            reg [2*FM-1:0] s2_p;
            always @(posedge clk) begin
                s2_p <= s1_ma * s1_mb;
                s3_p <= s2_p;
            end
        end else begin : g_split
            // ma = ah 2^L + al, mb = bh 2^L + bl: ah bh on the DSP block; ah bl + al bh by shift and add
            localparam L = FM - 18;
            wire [17:0] ah = s1_ma[FM-1:L], bh = s1_mb[FM-1:L];
            wire [L-1:0] al = s1_ma[L-1:0], bl = s1_mb[L-1:0];
            reg [35:0] s2_hh;
            reg [18+L:0] s2_x;       // ah bl + al bh
            reg [2*L-1:0] s2_ll;
            reg [18+L:0] x;
            reg [2*L-1:0] ll;
            integer i;
            always @(*) begin
                x = {(19 + L) {1'b0}};
                ll = {(2 * L) {1'b0}};
                for (i = 0; i < L; i = i + 1) begin
                    if (bl[i]) x = x + ({{(L + 1) {1'b0}}, ah} << i);
                    if (al[i]) x = x + ({{(L + 1) {1'b0}}, bh} << i);
                    if (bl[i]) ll = ll + ({{L{1'b0}}, al} << i);   // in logic too, not on a second DSP block
                end
            end
            always @(posedge clk) begin
                s2_hh <= ah * bh;
                s2_x <= x;
                s2_ll <= ll;
                s3_p <= ({{(2 * FM - 36) {1'b0}}, s2_hh} << (2 * L)) + ({{(2 * FM - 19 - L) {1'b0}}, s2_x} << L) +
                        {{(2 * FM - 2 * L) {1'b0}}, s2_ll};
            end
        end
    endgenerate
    always @(posedge clk) begin
        s2_s <= s1_s;
        s2_k <= s1_k;
        s3_s <= s2_s;
        s3_k <= s2_k;
    end
    spec_setup_fpround #(.FM(FM), .FE(FE), .XW(2 * FM), .KW(KW), .NORM1(1)) u_round (
        .clk(clk), .s(s3_s), .x(s3_p), .k(s3_k), .r(r)
    );
endmodule
`default_nettype wire
