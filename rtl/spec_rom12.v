// spec_rom12 - ROM 12 ("first ROM") of UA 71489 Fig. 1: the four tables cos^k(x), k = 1, 2, 4, 16,
// x = i * (pi/2) / 2^TBL_AW. Address = {table_sel (decoder 10), index (multiplier 11)}; the patent drives
// the top address bits with the four one-hot lines 30..33, of which only 4 of 16 codes occur - the 2-bit
// code addresses the same four tables without the unused space. Other table sets (docs/tuned.md): up to
// 2^TSEL_W tables, whatever powers k the image holds (the generator's --tables).
// Words UQ1.TBL_FRAC (TBL_FRAC + 1 bits): 1.0 exact; with interpolation (INTERP = 1, not in the patent) each
// word also carries the step to the next position in DELTA_W bits above the value.
// The image's first line (written by specrom) names the parameters it was made for; a simulation whose
// parameters differ stops at time 0 with a message naming the file and the fields (spec_rom, HEADER = 12).
`timescale 1ns / 1ps
`default_nettype none
module spec_rom12 #(
    parameter TBL_AW = 12,
    parameter TSEL_W = 2,
    parameter TBL_FRAC = 16,
    parameter INTERP = 0,
    parameter DELTA_W = 10,
    parameter WORD_W = TBL_FRAC + 1 + ((INTERP != 0) ? DELTA_W : 0),
    parameter INIT_FILE = ""
) (
    input  wire              clk,
    input  wire              en,
    input  wire [TSEL_W-1:0] table_sel,
    input  wire [TBL_AW-1:0] index,
    output wire [WORD_W-1:0] value   // one clock after the address
);
    spec_rom #(
        .AW(TBL_AW + TSEL_W),
        .DW(WORD_W),
        .INIT_FILE(INIT_FILE),
        .HEADER(12), .H0(TBL_AW), .H1(TSEL_W), .H2(TBL_FRAC), .H3((INTERP != 0) ? 1 : 0),
        .H4((INTERP != 0) ? DELTA_W : -1)
    ) u_mem (
        .clk (clk),
        .en  (en),
        .addr({table_sel, index}),
        .data(value)
    );
endmodule
`default_nettype wire
