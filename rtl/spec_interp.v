// spec_interp - linear interpolation between ROM 12 positions (INTERP = 1 only; not in the patent).
// A ROM 12 word holds {delta_i, table[i]} with delta_i = table[i] - table[i+1] >= 0 (the tables fall
// monotonically); the result is table[i] - round(delta_i * frac / 2^INTERP_FRAC), which never underflows
// (the step is at most delta_i). One pipeline stage. It lets a table of 2^8 positions keep the accuracy of
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
    wire [TBL_DW-1:0] v = word[TBL_DW-1:0];
    wire [DELTA_W-1:0] d = word[DELTA_W+TBL_DW-1:TBL_DW];
    wire [PW-1:0] prod = {{INTERP_FRAC{1'b0}}, d} * {{DELTA_W{1'b0}}, frac};
    // cannot overflow: (2^D - 1)(2^F - 1) + 2^(F-1) < 2^(D+F)
    wire [PW-1:0] rnd = prod + ({{(PW - 1) {1'b0}}, 1'b1} << (INTERP_FRAC - 1));
    wire [DELTA_W-1:0] step = rnd[PW-1:INTERP_FRAC];
    wire unused_low;
    assign unused_low = &{1'b0, rnd[INTERP_FRAC-1:0]};

    always @(posedge clk) begin
        if (ce) value <= v - {{(TBL_DW - DELTA_W) {1'b0}}, step};
    end
endmodule
`default_nettype wire
