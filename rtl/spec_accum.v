// spec_accum - the accumulating adder of UA 71489 Fig. 1: adder 6, multiplexer 7 and register 8 ("fourth").
// On strobe 37, register 8 takes the start angle of register 3 (select 36 = 0) or register 8 + register 2
// (select 36 = 1). Departure from the patent: adder 6 saturates at the format's ends instead of wrapping,
// so a span that runs off the angle range stays off it (and gives 0 for n > 0) instead of jumping back.
`timescale 1ns / 1ps
`default_nettype none
module spec_accum #(
    parameter W = 32
) (
    input  wire         clk,
    input  wire         rst,      // synchronous, active high: register 8 = 0
    input  wire         we,       // 37: write register 8
    input  wire         sel,      // 36: 0 = start angle (register 3), 1 = adder 6
    input  wire [W-1:0] start,    // register 3, two's complement
    input  wire [W-1:0] step,     // register 2, two's complement
    output reg  [W-1:0] angle     // register 8, two's complement
);
    // adder 6, one guard bit
    wire [W:0] sum = {angle[W-1], angle} + {step[W-1], step};
    wire overflow = sum[W] ^ sum[W-1];
    wire [W-1:0] sat = sum[W] ? {1'b1, {(W - 1) {1'b0}}} : {1'b0, {(W - 1) {1'b1}}};
    // multiplexer 7
    wire [W-1:0] mux7 = sel ? (overflow ? sat : sum[W-1:0]) : start;

    always @(posedge clk) begin
        if (rst) angle <= {W{1'b0}};
        else if (we) angle <= mux7;
    end
endmodule
`default_nettype wire
