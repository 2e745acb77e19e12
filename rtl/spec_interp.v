// spec_interp - linear interpolation between ROM 12 positions (INTERP = 1 only; not in the patent).
// A ROM 12 word holds {delta_i, table[i]} with delta_i = table[i] - table[i+1] >= 0 (the tables fall
// monotonically); the result is table[i] - round(delta_i * frac / 2^INTERP_FRAC), which never underflows
// (the step is at most delta_i). Two pipeline stages: the product (a DSP block), then one subtraction
// that also rounds: v - floor((p + 2^(F-1)) / 2^F) = floor((v * 2^F + 2^(F-1) - 1 - p) / 2^F). It lets a table of 2^8 positions keep the accuracy of
// the patent's plain table of 2^12 (docs/decisions.md), so the core fits small FPGAs' block RAM.
`timescale 1ns / 1ps
`default_nettype none
module spec_interp #(
    parameter TBL_DW = 17,
    parameter DELTA_W = 10,
    parameter INTERP_FRAC = 10
) (
    input  wire                      clk,
    input  wire                      ce,
    input  wire [DELTA_W+TBL_DW-1:0] word,    // ROM 12
    input  wire [INTERP_FRAC-1:0]    frac,    // multiplier 11
    output reg  [TBL_DW-1:0]         value
);
    localparam PW = DELTA_W + INTERP_FRAC;
    localparam SW = TBL_DW + INTERP_FRAC;
    wire [TBL_DW-1:0] v = word[TBL_DW-1:0];
    wire [DELTA_W-1:0] d = word[DELTA_W+TBL_DW-1:TBL_DW];

    // stage 1: delta * frac
    reg [PW-1:0] prod;
    reg [TBL_DW-1:0] v_q;
    always @(posedge clk) begin
        if (ce) begin
            prod <= {{INTERP_FRAC{1'b0}}, d} * {{DELTA_W{1'b0}}, frac};
            v_q <= v;
        end
    end

    // stage 2: the rounded difference (never negative: round(prod / 2^F) <= delta <= v)
    wire [INTERP_FRAC-1:0] bias = {1'b0, {(INTERP_FRAC - 1) {1'b1}}};   // 2^(F-1) - 1
    wire [SW-1:0] diff = {v_q, bias} - {{(SW - PW) {1'b0}}, prod};
    wire unused_low;
    assign unused_low = &{1'b0, diff[INTERP_FRAC-1:0]};
    always @(posedge clk) begin
        if (ce) value <= diff[SW-1:INTERP_FRAC];
    end
endmodule
`default_nettype wire
