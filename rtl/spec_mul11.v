// spec_mul11 - multiplier 11 ("second multiplier") of UA 71489 Fig. 1: |register 8| x ROM 9 -> the
// position in ROM 12's tables. cos is even, so the angle's magnitude is used. The product is in quarter
// turns with PROD_FRAC fraction bits.
//   INTERP = 0 (the patent's table lookup): rounded to the nearest of the 2^TBL_AW positions; `zero` is 1
//              when the rounded position is at or past pi/2 (where the BRDF max(0, cos)^n is 0).
//   INTERP = 1: truncated to the position below, with INTERP_FRAC fraction bits `frac` for the
//              interpolator; `zero` is 1 at or past pi/2.
// Five pipeline stages, so that no stage holds more than one carry chain or one DSP multiply:
//   1  m = angle, or ~angle = |angle| - 1 for a negative angle (no carry chain: the +1 comes back in 3)
//   2  the partial products of m's two halves times the scale (16x16 or 18x18 DSP blocks)
//   3  + scale for a negative angle, so that the sum is exactly |angle| * scale
//   4  the product
//   5  the table position (rounded, or truncated with its fraction)
`timescale 1ns / 1ps
`default_nettype none
module spec_mul11 #(
    parameter ANG_W = 32,
    parameter SCALE_W = 18,
    parameter PROD_FRAC = 43,
    parameter TBL_AW = 12,
    parameter INTERP = 0,
    parameter INTERP_FRAC = 10,
    parameter FRAC_W = (INTERP != 0) ? INTERP_FRAC : 1
) (
    input  wire               clk,
    input  wire               ce,      // clock enable (stall when 0)
    input  wire [ANG_W-1:0]   angle,   // register 8, two's complement
    input  wire [SCALE_W-1:0] scale,   // ROM 9
    output reg  [TBL_AW-1:0]  index,   // low address bits of ROM 12
    output reg  [FRAC_W-1:0]  frac,    // position fraction for the interpolator (0 when INTERP = 0)
    output reg                zero     // past pi/2: output 0
);
    localparam H = ANG_W / 2;
    localparam PW = ANG_W + SCALE_W;
    localparam DROP = PROD_FRAC - TBL_AW;  // fraction bits below the table position

    // stage 1: m = |angle| - neg (-2^(ANG_W-1) gives 2^(ANG_W-1) - 1), the sign and the scale
    reg [ANG_W-1:0] mag;
    reg neg1;
    reg [SCALE_W-1:0] scale1;
    always @(posedge clk) begin
        if (ce) begin
            mag <= angle ^ {ANG_W{angle[ANG_W-1]}};
            neg1 <= angle[ANG_W-1];
            scale1 <= scale;
        end
    end

    // stage 2: partial products of the two halves
    reg [H+SCALE_W-1:0] pp_lo, pp_hi;
    reg [SCALE_W-1:0] corr2;   // scale for a negative angle, else 0
    always @(posedge clk) begin
        if (ce) begin
            pp_lo <= {{SCALE_W{1'b0}}, mag[H-1:0]} * {{H{1'b0}}, scale1};
            pp_hi <= {{SCALE_W{1'b0}}, mag[ANG_W-1:H]} * {{H{1'b0}}, scale1};
            corr2 <= neg1 ? scale1 : {SCALE_W{1'b0}};
        end
    end

    // stage 3: the low partial product corrected (cannot overflow: the whole sum is |angle| * scale)
    reg [H+SCALE_W-1:0] pp_lo3, pp_hi3;
    always @(posedge clk) begin
        if (ce) begin
            pp_lo3 <= pp_lo + {{H{1'b0}}, corr2};
            pp_hi3 <= pp_hi;
        end
    end

    // stage 4: the product
    reg [PW-1:0] prod;
    always @(posedge clk) begin
        if (ce) prod <= {pp_hi3, {H{1'b0}}} + {{H{1'b0}}, pp_lo3};
    end

    // stage 5: the table position
    wire past_int = |prod[PW-1:PROD_FRAC];   // >= one quarter turn

    generate
        if (INTERP != 0) begin : g_interp
            wire unused_low;
            if (DROP > INTERP_FRAC) begin : g_low
                assign unused_low = &{1'b0, prod[DROP-INTERP_FRAC-1:0]};
            end else begin : g_nolow
                assign unused_low = 1'b0;
            end
            always @(posedge clk) begin
                if (ce) begin
                    index <= prod[PROD_FRAC-1:DROP];
                    frac  <= prod[DROP-1:DROP-INTERP_FRAC];
                    zero  <= past_int;
                end
            end
        end else begin : g_round
            // round to nearest position: ((prod >> (DROP-1)) + 1) >> 1, on the fraction bits
            wire [TBL_AW:0] half_pos = prod[PROD_FRAC-1:DROP-1];
            wire [TBL_AW+1:0] pos_r = {1'b0, half_pos} + {{(TBL_AW + 1) {1'b0}}, 1'b1};
            wire unused_low;
            if (DROP > 1) begin : g_low
                assign unused_low = &{1'b0, prod[DROP-2:0], pos_r[0]};
            end else begin : g_nolow
                assign unused_low = &{1'b0, pos_r[0]};
            end
            always @(posedge clk) begin
                if (ce) begin
                    index <= pos_r[TBL_AW:1];
                    frac  <= {FRAC_W{1'b0}};
                    zero  <= past_int | pos_r[TBL_AW+1];
                end
            end
        end
    endgenerate
endmodule
`default_nettype wire
