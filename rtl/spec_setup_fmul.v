// spec_setup_fmul - spec_setup's floating-point multiplier (rom/gen/setup_fp.h, fp_mul): a * b * 2^scale, the
// exact product of the mantissas rounded once. Pipelined, a new operation every clock; the result leaves
// LAT - 1 clocks after the operands (LAT counts the issue clock, in which the machine reads its banks).
//   1  sign, exponent sum with the scale, the mantissas into the multiplier
//   2  the product (FM x FM: DSP blocks)
//   3  the product again (the DSP's output register)
//   4-6  spec_setup_fpround
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
    reg [2*FM-1:0] s2_p, s3_p;
    reg s2_s, s3_s;
    reg signed [KW-1:0] s2_k, s3_k;
    always @(posedge clk) begin
        s2_p <= s1_ma * s1_mb;
        s2_s <= s1_s;
        s2_k <= s1_k;
        s3_p <= s2_p;
        s3_s <= s2_s;
        s3_k <= s2_k;
    end
    spec_setup_fpround #(.FM(FM), .FE(FE), .XW(2 * FM), .KW(KW)) u_round (
        .clk(clk), .s(s3_s), .x(s3_p), .k(s3_k), .r(r)
    );
endmodule
`default_nettype wire
