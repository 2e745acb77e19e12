// spec_setup_ramdelay - a fixed delay of N clocks (N >= 3) in a memory instead of N register stages: the
// side band of spec_setup_pipe (n, l, strength, flags) waits there while the CORDIC passes run. spec_delay's
// block-RAM form (RAM = 1) with the enable always on: the pipeline never stops. The first N outputs after
// power-up are unknown; the valid flags beside it are reset.
`timescale 1ns / 1ps
`default_nettype none
module spec_setup_ramdelay #(
    parameter W = 8,
    parameter N = 8
) (
    input  wire         clk,
    input  wire [W-1:0] d,
    output wire [W-1:0] q
);
    spec_delay #(.W(W), .N(N), .RAM(1)) u_mem (.clk(clk), .ce(1'b1), .d(d), .q(q));
endmodule
`default_nettype wire
