// spec_mul11 - multiplier 11 ("second multiplier") of UA 71489 Fig. 1: |register 8| x ROM 9 -> the
// position in ROM 12's tables. cos is even, so the angle's magnitude is used. The product is in quarter
// turns with PROD_FRAC fraction bits.
//   INTERP = 0 (the patent's table lookup): rounded to the nearest of the 2^TBL_AW positions; `zero` is 1
//              when the rounded position is at or past pi/2 (where the BRDF max(0, cos)^n is 0).
//   INTERP = 1: truncated to the position below, with INTERP_FRAC fraction bits `frac` for the
//              interpolator; `zero` is 1 at or past pi/2.
// Seven pipeline stages, so that no stage holds more than a half-width carry chain or one DSP multiply:
//   1  the angle's bits inverted when it is negative, and its sign
//   2  the low half of |angle| (+1 for a negative angle), with its carry
//   3  the high half of |angle| (plus that carry)
//   4  the partial products of the two halves times the scale (16x16 or 18x18 DSP blocks)
//   5  the middle of the sum, pp_hi[low] + pp_lo[high], with its carry
//   6  the top of the sum, pp_hi[high] + that carry
//   7  the table position (rounded, or truncated with its fraction)
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

    // stages 1 to 3: |angle|; -2^(ANG_W-1) becomes 2^(ANG_W-1), which fits ANG_W unsigned bits
    reg [ANG_W-1:0] ang_inv;
    reg ang_neg;
    reg [H:0] lo_plus;
    reg [ANG_W-H-1:0] hi_inv, mag_hi;
    reg [H-1:0] mag_lo;
    reg [SCALE_W-1:0] scale_a, scale_b, scale_c;
    always @(posedge clk) begin
        if (ce) begin
            ang_inv <= angle ^ {ANG_W{angle[ANG_W-1]}};
            ang_neg <= angle[ANG_W-1];
            scale_a <= scale;
            lo_plus <= {1'b0, ang_inv[H-1:0]} + {{H{1'b0}}, ang_neg};
            hi_inv <= ang_inv[ANG_W-1:H];
            scale_b <= scale_a;
            mag_lo <= lo_plus[H-1:0];
            mag_hi <= hi_inv + {{(ANG_W - H - 1) {1'b0}}, lo_plus[H]};
            scale_c <= scale_b;
        end
    end

    // stage 4: partial products of the two halves
    localparam LW = H + SCALE_W;
    reg [LW-1:0] pp_lo, pp_hi;
    always @(posedge clk) begin
        if (ce) begin
            pp_lo <= {{SCALE_W{1'b0}}, mag_lo} * {{H{1'b0}}, scale_c};
            pp_hi <= {{SCALE_W{1'b0}}, mag_hi} * {{H{1'b0}}, scale_c};
        end
    end

    // stages 5 and 6: prod = (pp_hi + pp_lo[LW-1:H]) * 2^H + pp_lo[H-1:0], the addition in two halves
    reg [SCALE_W:0] mid_sum;
    reg [H-1:0] low_part, prod_low, top_part;
    reg [SCALE_W-1:0] prod_mid;
    reg [H-1:0] prod_top;
    always @(posedge clk) begin
        if (ce) begin
            mid_sum <= {1'b0, pp_hi[SCALE_W-1:0]} + {1'b0, pp_lo[LW-1:H]};
            top_part <= pp_hi[LW-1:SCALE_W];
            low_part <= pp_lo[H-1:0];
            prod_top <= top_part + {{(H - 1) {1'b0}}, mid_sum[SCALE_W]};
            prod_mid <= mid_sum[SCALE_W-1:0];
            prod_low <= low_part;
        end
    end
    wire [PW-1:0] prod = {prod_top, prod_mid, prod_low};

    // stage 7: the table position
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
