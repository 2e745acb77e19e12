// spec_mul11 - multiplier 11 ("second multiplier") of UA 71489 Fig. 1: |register 8| x ROM 9 -> the
// position in ROM 12's tables. cos is even, so the angle's magnitude is used. The product is in quarter
// turns with PROD_FRAC fraction bits; it is rounded to the nearest of the 2^TBL_AW table positions.
// `zero` is 1 when the rounded position is at or past pi/2 (where the BRDF max(0, cos)^n is 0).
// Registered output (one pipeline stage).
`timescale 1ns / 1ps
`default_nettype none
module spec_mul11 #(
    parameter ANG_W = 32,
    parameter SCALE_W = 18,
    parameter PROD_FRAC = 43,
    parameter TBL_AW = 12
) (
    input  wire              clk,
    input  wire              en,
    input  wire [ANG_W-1:0]  angle,   // register 8, two's complement
    input  wire [SCALE_W-1:0] scale,  // ROM 9
    output reg  [TBL_AW-1:0] index,   // low address bits of ROM 12
    output reg               zero     // past pi/2: output 0
);
    localparam PW = ANG_W + SCALE_W;
    localparam DROP = PROD_FRAC - TBL_AW;  // fraction bits below the table position

    // |angle|; -2^(ANG_W-1) becomes 2^(ANG_W-1), which fits ANG_W unsigned bits
    wire [ANG_W-1:0] mag = angle[ANG_W-1] ? (~angle + {{(ANG_W - 1) {1'b0}}, 1'b1}) : angle;
    wire [PW-1:0] prod = {{SCALE_W{1'b0}}, mag} * {{ANG_W{1'b0}}, scale};
    // round to nearest position: ((prod >> (DROP-1)) + 1) >> 1, on the fraction bits
    wire [TBL_AW:0] half_pos = prod[PROD_FRAC-1:DROP-1];
    wire [TBL_AW+1:0] pos_r = {1'b0, half_pos} + {{(TBL_AW + 1) {1'b0}}, 1'b1};
    wire past_int = |prod[PW-1:PROD_FRAC];   // >= one quarter turn
    wire unused_low;
    assign unused_low = &{1'b0, prod[DROP-2:0], pos_r[0]};

    always @(posedge clk) begin
        if (en) begin
            index <= pos_r[TBL_AW:1];
            zero  <= past_int | pos_r[TBL_AW+1];
        end
    end
endmodule
`default_nettype wire
