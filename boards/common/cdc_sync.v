// cdc_sync - a level signal brought into the clock domain of clk through STAGES flip-flops
// (metastability settles in the first). Only for single bits, or for buses that change one bit at a time.
// Reset value RESET_VAL while rst_n = 0 (synchronous to clk).
`timescale 1ns / 1ps
`default_nettype none
module cdc_sync #(
    parameter STAGES = 2,
    parameter RESET_VAL = 1'b0
) (
    input  wire clk,
    input  wire rst_n,
    input  wire d,        // from another clock domain
    output wire q
);
    (* ASYNC_REG = "TRUE" *) reg [STAGES-1:0] sync;
    always @(posedge clk) begin
        if (!rst_n) sync <= {STAGES{RESET_VAL}};
        else sync <= {sync[STAGES-2:0], d};
    end
    assign q = sync[STAGES-1];
endmodule
`default_nettype wire
