// spec_setup_fpround - the rounding every floating-point unit of spec_setup ends with (rom/gen/setup_fp.h,
// fp_round): the value (-1)^s * x * 2^k, x an exact unsigned integer, rounded half up on the magnitude to a
// mantissa of FM bits with its leading one; a result below 2^emin is zero, one above the largest value saturates.
// A word is {sign, exponent (FE bits, two's complement), mantissa (FM bits)}; zero has every bit 0.
// Three register stages (valid three clocks after the input):
//   1  the leading one's position lp of x
//   2  x shifted so that lp lands on bit FM - 1, the rounding bit beside it; the exponent k + lp
//   3  the rounding bit added (a carry into bit FM moves the point once more), the range, the word
// NORM1 = 1 (the multiplier's: x is 0 or the product of two mantissas with their leading ones, so its leading
// one is bit XW - 1 or XW - 2): stage 1 looks at those two bits and stage 2 is a choice of two shifts, the same
// result for every such x without the priority encoder and the shifters.
`timescale 1ns / 1ps
`default_nettype none
module spec_setup_fpround #(
    parameter FM = 22,
    parameter FE = 8,
    parameter XW = 44,   // width of x
    parameter KW = 12,   // width of k (two's complement)
    parameter NORM1 = 0
) (
    input  wire                 clk,
    input  wire                 s,
    input  wire [XW-1:0]        x,
    input  wire signed [KW-1:0] k,
    output reg  [FE+FM:0]       r
);
    localparam LW = (XW > 64) ? 7 : (XW > 32) ? 6 : (XW > 16) ? 5 : (XW > 8) ? 4 : 3;   // bits of lp
    localparam signed [KW-1:0] EMIN = -(1 <<< (FE - 1));
    localparam signed [KW-1:0] EMAX = (1 <<< (FE - 1)) - 1;
    localparam [31:0] LP_TOP32 = XW - 1;
    localparam [LW-1:0] LP_TOP = LP_TOP32[LW-1:0];

    // ---- 1: the leading one
    reg [LW-1:0] lp;
    integer i;
    always @(*) begin
        lp = {LW{1'b0}};
        if (NORM1 != 0) lp = x[XW-1] ? LP_TOP : LP_TOP - 1'b1;
        else
            for (i = 0; i < XW; i = i + 1)
                if (x[i]) lp = i[LW-1:0];
    end
    reg s1_s, s1_z;
    reg [XW-1:0] s1_x;
    reg signed [KW-1:0] s1_k;
    reg [LW-1:0] s1_lp;
    always @(posedge clk) begin
        s1_s <= s;
        s1_z <= ~|x;
        s1_x <= x;
        s1_k <= k;
        s1_lp <= lp;
    end

    // ---- 2: the shift (right by lp - (FM - 1) with the rounding bit, or left by FM - 1 - lp, exact)
    wire right = {{(32 - LW) {1'b0}}, s1_lp} >= FM - 1;
    wire [LW-1:0] rsh = s1_lp - (FM - 1);
    wire [LW-1:0] lsh = (FM - 1) - s1_lp;
    wire [XW:0] xr = {s1_x, 1'b0} >> rsh;          // bit 0: the rounding bit
    wire [XW+FM-1:0] xl = {{FM{1'b0}}, s1_x} << lsh;
    // NORM1: lp is XW - 1 or XW - 2, the right shift XW - FM or XW - FM - 1
    wire [FM:0] xr1 = s1_lp == LP_TOP ? s1_x[XW-1:XW-FM-1] : s1_x[XW-2:XW-FM-2];
    reg s2_s, s2_z, s2_rb;
    reg [FM-1:0] s2_m;
    reg signed [KW-1:0] s2_e;
    always @(posedge clk) begin
        s2_s <= s1_s;
        s2_z <= s1_z;
        if (NORM1 != 0) begin
            s2_m <= xr1[FM:1];
            s2_rb <= xr1[0];
        end else begin
            s2_m <= right ? xr[FM:1] : xl[FM-1:0];
            s2_rb <= right & xr[0];
        end
        s2_e <= s1_k + $signed({{(KW - LW) {1'b0}}, s1_lp});
    end

    // ---- 3: round, range, word
    wire [FM:0] t = {1'b0, s2_m} + {{FM{1'b0}}, s2_rb};
    wire carry = t[FM];
    wire [FM-1:0] m = carry ? t[FM:1] : t[FM-1:0];
    wire signed [KW-1:0] e = s2_e + {{(KW - 1) {1'b0}}, carry};
    always @(posedge clk) begin
        if (s2_z || e < EMIN) r <= {(FE + FM + 1) {1'b0}};
        else if (e > EMAX) r <= {s2_s, EMAX[FE-1:0], {FM{1'b1}}};
        else r <= {s2_s, e[FE-1:0], m};
    end
    wire unused;
    assign unused = &{1'b0, xr[XW:FM+1], xl[XW+FM-1:FM], rsh, lsh, xr1};
endmodule
`default_nettype wire
