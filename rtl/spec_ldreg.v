// spec_ldreg - a register that takes `d` in the cycles where `ld` is 1 and holds otherwise.
// Written as (d & ld) | (q & ~ld), so that synthesis keeps the choice as logic in front of each flip-flop
// instead of making `ld` the flip-flops' clock enable: nextpnr-ice40 gives the four widest clock-enable nets a
// global buffer, and a global buffer after logic is a long detour (about 8 ns from the logic's output to the
// enables on the UP5K), whereas `ld` as a logic net reaches a few hundred LUTs in fabric routing. The
// behaviour is that of `if (ld) q <= d;` in every tool, 4-state simulators included (an X in q does not
// survive a load).
`timescale 1ns / 1ps
`default_nettype none
module spec_ldreg #(
    parameter W = 1
) (
    input  wire         clk,
    input  wire         ld,
    input  wire [W-1:0] d,
    output reg  [W-1:0] q
);
    always @(posedge clk) q <= (d & {W{ld}}) | (q & {W{~ld}});
endmodule
`default_nettype wire
