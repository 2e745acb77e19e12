// spec_counter - down-counter 5 of UA 71489 Fig. 1.
// Loaded with the number of intervals l from input 23 while input 24 (load_n) is 0; steps down by one on
// each clock with the count input 34 high; its borrow output 35 is a negative (active-low) pulse on the
// 0 -> maximum step, which ends the span through AND 38 of the control block. After a span the counter
// holds 2^W - 1, as the patent's does: load it again before the next start.
`timescale 1ns / 1ps
`default_nettype none
module spec_counter #(
    parameter W = 16
) (
    input  wire         clk,
    input  wire         rst,       // synchronous, active high: q = 0
    input  wire         load_n,    // 24: load, active low (has priority over count)
    input  wire [W-1:0] d,         // 23: l
    input  wire         count,     // 34: count pulse
    output reg  [W-1:0] q,
    output wire         borrow_n   // 35: low in the cycle that steps 0 -> 2^W - 1
);
    assign borrow_n = ~(count & load_n & (q == {W{1'b0}}));

    always @(posedge clk) begin
        if (rst) q <= {W{1'b0}};
        else if (!load_n) q <= d;
        else if (count) q <= q - {{(W - 1) {1'b0}}, 1'b1};
    end
endmodule
`default_nettype wire
