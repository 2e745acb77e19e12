// ODDRX1F - simulation model of the ECP5 generic DDR output register (Lattice TN1265): D0 and D1 are taken at
// the rising edge of SCLK; Q shows D0 while SCLK is high and D1 while it is low, so D0 leaves first.
// RST (asynchronous, active high) clears both. Not for synthesis.
`timescale 1ns / 1ps
`default_nettype none
module ODDRX1F (
    input  wire SCLK,
    input  wire RST,
    input  wire D0,
    input  wire D1,
    output wire Q
);
    reg q0 = 1'b0, q1 = 1'b0;
    always @(posedge SCLK or posedge RST) begin
        if (RST) begin
            q0 <= 1'b0;
            q1 <= 1'b0;
        end else begin
            q0 <= D0;
            q1 <= D1;
        end
    end
    assign Q = SCLK ? q0 : q1;
endmodule
`default_nettype wire
