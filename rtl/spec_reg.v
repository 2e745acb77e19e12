// spec_reg - registers 1, 2, 3 and 4 of UA 71489 Fig. 1 (C, angle step, start angle, exponent n).
// Written when `we` is 1 (inputs 16, 18, 20, 22); cleared to 0 by the synchronous reset (input 25, init_n low).
`timescale 1ns / 1ps
`default_nettype none
module spec_reg #(
    parameter W = 16
) (
    input  wire         clk,
    input  wire         rst,   // synchronous, active high (from init_n = 0)
    input  wire         we,    // write strobe, active 1
    input  wire [W-1:0] d,
    output reg  [W-1:0] q
);
    always @(posedge clk) begin
        if (rst) q <= {W{1'b0}};
        else if (we) q <= d;
    end
endmodule
`default_nettype wire
