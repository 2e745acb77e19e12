// spec_mul11 - multiplier 11 ("second multiplier") of UA 71489 Fig. 1: |register 8| x ROM 9 -> the
// position in ROM 12's tables. cos is even, so the angle's magnitude is used. The product is in quarter
// turns with PROD_FRAC fraction bits.
//   INTERP = 0 (the patent's table lookup): rounded to the nearest of the 2^TBL_AW positions; `zero` is 1
//              when the rounded position is at or past pi/2 (where the BRDF max(0, cos)^n is 0).
//   INTERP = 1: truncated to the position below, with INTERP_FRAC fraction bits `frac` for the
//              interpolator; `zero` is 1 at or past pi/2.
// Seven pipeline stages (eight with DSP_FF = 1), so that no stage holds more than a half-width carry chain or
// one DSP multiply:
//   1  the angle's bits inverted when it is negative, its sign, and whether its low half is 0
//   2  both halves of |angle|: inverted low half + sign, inverted high half + (sign and low half 0)
//   3  the same in registers that feed only the DSP blocks (synthesis packs them into the blocks' input
//      registers, so the route to a DSP block at the chip's edge has a clock of its own)
//   4  the partial products of the two halves times the scale (16x16 or 18x18 DSP blocks, their output
//      registers)
//  [4b DSP_FF = 1: a copy of the products in ordinary flip-flops, so that the route from a DSP block at the
//      chip's edge and the carry chain below are not in one clock]
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
    parameter DSP_FF = 0,   // 1: a register stage after the DSP blocks (spec_stream)
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

    // stages 1 to 3: |angle| = (angle ^ sign) + sign; -2^(ANG_W-1) becomes 2^(ANG_W-1), which fits ANG_W
    // unsigned bits. The +1 of a negative angle reaches the high half only when the low half is 0: that is
    // found beside the inversion (stage 1), so both halves' increments run side by side in stage 2.
    reg [ANG_W-1:0] ang_inv;
    reg ang_neg, hi_cin;
    reg [ANG_W-H-1:0] mag_hi, op_hi;
    reg [H-1:0] mag_lo, op_lo;
    reg [SCALE_W-1:0] scale_a, scale_b, op_s;
    wire [H-1:0] lo_sum;
    wire lo_co_unused;
    spec_add #(.W(H), .CO(0)) u_lo (
        .a(ang_inv[H-1:0]), .b({H{1'b0}}), .cin(ang_neg), .p(ang_inv[H-1]), .sum(lo_sum), .cout(lo_co_unused)
    );
    // the high half below its top bit (ang_inv's top bit is always 0), whose carry out is |angle|'s top bit
    wire [ANG_W-H-2:0] hi_sum;
    wire hi_co;
    spec_add #(.W(ANG_W - H - 1)) u_hi (
        .a(ang_inv[ANG_W-2:H]), .b({(ANG_W - H - 1) {1'b0}}), .cin(hi_cin), .p(ang_inv[H]), .sum(hi_sum),
        .cout(hi_co)
    );
    wire unused_top;
    assign unused_top = &{1'b0, ang_inv[ANG_W-1]};
    always @(posedge clk) begin
        if (ce) begin
            ang_inv <= angle ^ {ANG_W{angle[ANG_W-1]}};
            ang_neg <= angle[ANG_W-1];
            hi_cin <= angle[ANG_W-1] & (angle[H-1:0] == {H{1'b0}});
            scale_a <= scale;
            mag_lo <= lo_sum;
            mag_hi <= {hi_co, hi_sum};
            scale_b <= scale_a;
            // stage 3: the operands in registers that feed only the DSP blocks (synthesis packs them into
            // the blocks' input registers)
            op_lo <= mag_lo;
            op_hi <= mag_hi;
            op_s <= scale_b;
        end
    end

    // stage 4: partial products of the two halves
    localparam LW = H + SCALE_W;
    reg [LW-1:0] pp_lo_d, pp_hi_d;
    always @(posedge clk) begin
        if (ce) begin
            pp_lo_d <= {{SCALE_W{1'b0}}, op_lo} * {{H{1'b0}}, op_s};
            pp_hi_d <= {{SCALE_W{1'b0}}, op_hi} * {{H{1'b0}}, op_s};
        end
    end
    wire [LW-1:0] pp_lo, pp_hi;
    spec_delay #(.W(2 * LW), .N((DSP_FF != 0) ? 1 : 0)) u_dsp_ff (
        .clk(clk), .ce(ce), .d({pp_lo_d, pp_hi_d}), .q({pp_lo, pp_hi})
    );

    // stages 5 and 6: prod = (pp_hi + pp_lo[LW-1:H]) * 2^H + pp_lo[H-1:0], the addition in two halves
    reg [SCALE_W:0] mid_sum;
    reg [H-1:0] low_part, prod_low, top_part;
    reg [SCALE_W-1:0] prod_mid;
    reg [H-1:0] prod_top;
    wire [SCALE_W-1:0] mid_s;
    wire mid_co;
    spec_add #(.W(SCALE_W)) u_mid (
        .a(pp_hi[SCALE_W-1:0]), .b(pp_lo[LW-1:H]), .cin(1'b0), .p(pp_lo[0]), .sum(mid_s), .cout(mid_co)
    );
    wire [H-1:0] top_s;
    wire top_co_unused;
    spec_add #(.W(H), .CO(0)) u_top (
        .a(top_part), .b({H{1'b0}}), .cin(mid_sum[SCALE_W]), .p(top_part[0]), .sum(top_s), .cout(top_co_unused)
    );
    always @(posedge clk) begin
        if (ce) begin
            mid_sum <= {mid_co, mid_s};
            top_part <= pp_hi[LW-1:SCALE_W];
            low_part <= pp_lo[H-1:0];
            prod_top <= top_s;
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
            // round to nearest position: ((prod >> (DROP-1)) + 1) >> 1 = (prod >> DROP) + prod[DROP-1]
            wire [TBL_AW-1:0] pos_r;
            wire pos_co;   // the rounded position reaches 2^TBL_AW (pi/2)
            spec_add #(.W(TBL_AW)) u_round (
                .a(prod[PROD_FRAC-1:DROP]), .b({TBL_AW{1'b0}}), .cin(prod[DROP-1]), .p(prod[DROP]), .sum(pos_r),
                .cout(pos_co)
            );
            wire unused_low;
            if (DROP > 1) begin : g_low
                assign unused_low = &{1'b0, prod[DROP-2:0]};
            end else begin : g_nolow
                assign unused_low = 1'b0;
            end
            always @(posedge clk) begin
                if (ce) begin
                    index <= pos_r;
                    frac  <= {FRAC_W{1'b0}};
                    zero  <= past_int | pos_co;
                end
            end
        end
    endgenerate
endmodule
`default_nettype wire
