// spec_setup_ramdelay - a fixed delay of N clocks (N >= 3) in a memory instead of N register stages: the
// side band of spec_setup_pipe (n, l, strength, flags) waits there while the CORDIC passes run. Written every
// clock at a counting address and read N - 1 addresses behind it through a registered read, so block RAM
// holds it (DP16KD on ECP5). No stalls: the pipeline never stops. The first N outputs after power-up are
// unknown; the valid flags beside it are reset.
`timescale 1ns / 1ps
`default_nettype none
module spec_setup_ramdelay #(
    parameter W = 8,
    parameter N = 8
) (
    input  wire         clk,
    input  wire [W-1:0] d,
    output reg  [W-1:0] q
);
    localparam AW = (N <= 4) ? 2 : (N <= 8) ? 3 : (N <= 16) ? 4 : (N <= 32) ? 5 : (N <= 64) ? 6 : (N <= 128) ? 7 :
                    (N <= 256) ? 8 : (N <= 512) ? 9 : 10;
    reg [W-1:0] mem[0:(1 << AW) - 1];
    reg [AW-1:0] wa = {AW{1'b0}};
    localparam integer BACK = N - 1;
    wire [AW-1:0] ra = wa - BACK[AW-1:0];   // what was written N - 1 clocks ago; the read register adds one
    always @(posedge clk) begin
        mem[wa] <= d;
        q <= mem[ra];
        wa <= wa + 1'b1;
    end
endmodule
`default_nettype wire
