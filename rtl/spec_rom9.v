// spec_rom9 - ROM 9 ("second ROM") of UA 71489 Fig. 1: address = n (register 4), word = the scale of
// multiplier 11 for that n, sqrt(n/k) with k chosen by the Fig. 10 rule, times 2/pi (ROM 12's angle unit is
// the quarter turn; folding 2/pi here spares a constant multiplier). Word 0 (n = 0) is 0, so n = 0 reads
// position 0 of ROM 12, cos^k(0) = 1. Unsigned, SCALE_W bits with SCALE_FRAC fraction bits.
`timescale 1ns / 1ps
`default_nettype none
module spec_rom9 #(
    parameter N_W = 10,
    parameter SCALE_W = 18,
    parameter INIT_FILE = ""
) (
    input  wire               clk,
    input  wire [N_W-1:0]     n,      // register 4
    output wire [SCALE_W-1:0] scale   // to multiplier 11, one clock after n
);
    spec_rom #(
        .AW(N_W),
        .DW(SCALE_W),
        .INIT_FILE(INIT_FILE)
    ) u_mem (
        .clk (clk),
        .en  (1'b1),
        .addr(n),
        .data(scale)
    );
endmodule
`default_nettype wire
