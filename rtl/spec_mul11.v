// spec_mul11 - multiplier 11 ("second multiplier") of UA 71489 Fig. 1: |register 8| x ROM 9 -> the
// position in ROM 12's tables. cos is even, so the angle's magnitude is used. The product is in quarter
// turns with PROD_FRAC fraction bits.
//   INTERP = 0 (the patent's table lookup): rounded to the nearest of the 2^TBL_AW positions; `zero` is 1
//              when the rounded position is at or past pi/2 (where the BRDF max(0, cos)^n is 0).
//   INTERP = 1: truncated to the position below, with INTERP_FRAC fraction bits `frac` for the
//              interpolator; `zero` is 1 at or past pi/2.
// Two pipeline stages: the angle is split into halves whose partial products are registered (they map to
// 16x16 or 18x18 DSP blocks), then summed and rounded.
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

    // |angle|; -2^(ANG_W-1) becomes 2^(ANG_W-1), which fits ANG_W unsigned bits
    wire [ANG_W-1:0] mag = angle[ANG_W-1] ? (~angle + {{(ANG_W - 1) {1'b0}}, 1'b1}) : angle;

    // stage 1: partial products of the two halves
    reg [H+SCALE_W-1:0] pp_lo, pp_hi;
    always @(posedge clk) begin
        if (ce) begin
            pp_lo <= {{SCALE_W{1'b0}}, mag[H-1:0]} * {{H{1'b0}}, scale};
            pp_hi <= {{SCALE_W{1'b0}}, mag[ANG_W-1:H]} * {{H{1'b0}}, scale};
        end
    end

    // stage 2: the product, then the table position
    wire [PW-1:0] prod = {pp_hi, {H{1'b0}}} + {{H{1'b0}}, pp_lo};
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
