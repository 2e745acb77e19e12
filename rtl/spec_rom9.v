// spec_rom9 - ROM 9 ("second ROM") of UA 71489 Fig. 1: address = n (register 4), word = the scale of
// multiplier 11 for that n, times 2/pi (ROM 12's angle unit is the quarter turn; folding 2/pi here spares a
// constant multiplier). Word 0 (n = 0) is 0, so n = 0 reads position 0 of ROM 12, cos^k(0) = 1.
// Unsigned, SCALE_W bits with SCALE_FRAC fraction bits.
//   DECODER_ROM = 0 (the patent): the scale is sqrt(n/k) with k chosen by the Fig. 10 rule; decoder 10's gates
//                 choose the table, `table_sel` is 0.
//   DECODER_ROM = 1 (tuned mode, other table sets; docs/tuned.md): each word also holds, in TSEL_W bits above
//                 the scale, the table of ROM 12 for that n - decoder 10 as a ROM, which the patent allows
//                 ("decoder 10 may also be a ROM"). The generator fills both fields (specrom --mode tuned).
// The image's first line (written by specrom) names the parameters it was made for; a simulation whose
// parameters differ stops at time 0 with a message naming the file and the fields (spec_rom, HEADER = 9).
`timescale 1ns / 1ps
`default_nettype none
module spec_rom9 #(
    parameter N_W = 10,
    parameter SCALE_W = 18,
    parameter SCALE_FRAC = 15,
    parameter DECODER_ROM = 0,
    parameter TSEL_W = 2,
    parameter INIT_FILE = ""
) (
    input  wire               clk,
    input  wire               en,         // read enable
    input  wire [N_W-1:0]     n,          // register 4
    output wire [SCALE_W-1:0] scale,      // to multiplier 11, one clock after n
    output wire [TSEL_W-1:0]  table_sel   // DECODER_ROM = 1: ROM 12's table for n, one clock after n; else 0
);
    localparam DW = SCALE_W + ((DECODER_ROM != 0) ? TSEL_W : 0);
    wire [DW-1:0] word;
    spec_rom #(
        .AW(N_W),
        .DW(DW),
        .INIT_FILE(INIT_FILE),
        .HEADER(9), .H0(N_W), .H1(SCALE_W), .H2(SCALE_FRAC), .H3((DECODER_ROM != 0) ? 1 : 0),
        .H4((DECODER_ROM != 0) ? TSEL_W : -1)
    ) u_mem (
        .clk (clk),
        .en  (en),
        .addr(n),
        .data(word)
    );
    assign scale = word[SCALE_W-1:0];
    generate
        if (DECODER_ROM != 0) begin : g_field
            assign table_sel = word[DW-1:SCALE_W];
        end else begin : g_gates
            assign table_sel = {TSEL_W{1'b0}};
        end
    endgenerate
endmodule
`default_nettype wire
