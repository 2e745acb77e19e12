// spec_interp - linear interpolation between ROM 12 positions (INTERP = 1 only; not in the patent).
// A ROM 12 word holds {delta_i, table[i]} with delta_i = table[i] - table[i+1] >= 0 (the tables fall
// monotonically); the result is table[i] - round(delta_i * frac / 2^INTERP_FRAC) (half up), which never
// underflows (the step is at most delta_i). It lets a table of 2^8 positions keep the accuracy of the patent's
// plain table of 2^12 (docs/decisions.md), so the core fits small FPGAs' block RAM.
// Two pipeline stages (three with DSP_FF = 1: a copy of the product in ordinary flip-flops between them):
//   1  delta * frac: a DSP block. `delta` and `frac` must come straight from registers that feed nothing
//      else, so that synthesis can pack them into the block's input registers (SB_MAC16 A/B, MULT18X18D
//      inputs) and the product register into its output register: no path through the multiplier is left
//      to the fabric's timing model;
//   2  one subtraction that also rounds: v - floor((p + 2^(F-1)) / 2^F) = v - p_hi - p[F-1], computed as
//      v + ~p_hi + ~p[F-1] (mod 2^TBL_DW; p_hi = p >> F): one carry chain, ~p[F-1] its carry in.
`timescale 1ns / 1ps
`default_nettype none
module spec_interp #(
    parameter TBL_DW = 17,
    parameter DELTA_W = 10,
    parameter INTERP_FRAC = 10,
    parameter DSP_FF = 0   // 1: a register stage after the DSP block's output (spec_stream)
) (
    input  wire                   clk,
    input  wire                   ce,
    input  wire [TBL_DW-1:0]      v,       // ROM 12: table[i]
    input  wire [DELTA_W-1:0]     delta,   // ROM 12: table[i] - table[i+1]
    input  wire [INTERP_FRAC-1:0] frac,    // multiplier 11
    output reg  [TBL_DW-1:0]      value
);
    localparam PW = DELTA_W + INTERP_FRAC;

    // stage 1: delta * frac
    reg [PW-1:0] prod_d;
    reg [TBL_DW-1:0] v_d;
    always @(posedge clk) begin
        if (ce) begin
            prod_d <= {{INTERP_FRAC{1'b0}}, delta} * {{DELTA_W{1'b0}}, frac};
            v_d <= v;
        end
    end
    // the rounded difference (never negative: round(prod / 2^F) <= delta <= v), in XW + 1 bits, with the
    // product's inverted bits ~p_hi and ~p[F-1] (inverted before the DSP_FF register when there is one, so
    // that the carry chain's operands come straight from flip-flops)
    localparam XW = (TBL_DW > DELTA_W) ? TBL_DW : DELTA_W;
    wire [DELTA_W:0] n_d = ~prod_d[PW-1:INTERP_FRAC-1];   // {~p_hi, ~p[F-1]}
    wire [DELTA_W:0] n_q;
    wire [TBL_DW-1:0] v_q;
    spec_delay #(.W(DELTA_W + 1 + TBL_DW), .N((DSP_FF != 0) ? 1 : 0)) u_dsp_ff (
        .clk(clk), .ce(ce), .d({n_d, v_d}), .q({n_q, v_q})
    );
    wire [XW-1:0] v_x = {{(XW - TBL_DW) {1'b0}}, v_q};
    wire [XW-1:0] n_x = {{(XW - DELTA_W) {1'b1}}, n_q[DELTA_W:1]};   // ~p_hi in XW bits
    wire [XW-1:0] diff;
    wire diff_co;
    // v + ~p_hi + ~p[F-1] = v - p_hi - p[F-1] (mod 2^XW)
    spec_add #(.W(XW), .CO(0)) u_sub (.a(v_x), .b(n_x), .cin(n_q[0]), .p(v_q[0]), .sum(diff), .cout(diff_co));
    wire unused_low;
    assign unused_low = &{1'b0, diff_co, diff, prod_d};
    always @(posedge clk) begin
        if (ce) value <= diff[TBL_DW-1:0];
    end
endmodule
`default_nettype wire
