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
// parameters differ stops at time 0 with a message naming the file and the field (spec_rom checks the rest).
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
        .INIT_FILE(INIT_FILE)
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

`ifndef SYNTHESIS
    integer fd, got, f_n_w, f_scale_w, f_scale_frac, f_decoder_rom, f_tsel_w;
    reg [8*256-1:0] line;
    initial begin
        fd = $fopen(INIT_FILE, "r");
        if (fd != 0) begin   // spec_rom reports a file that cannot be opened
            line = 0;
            got = $fgets(line, fd);
            $fclose(fd);
            // blanks above the characters read (Verilator's $sscanf does not skip the NUL bytes there)
            if (got > 0) line = line | ({256{8'h20}} << (8 * got));
            got = $sscanf(line, " // specrom ROM 9: n_w=%d scale_w=%d scale_frac=%d decoder_rom=%d tsel_w=%d",
                          f_n_w, f_scale_w, f_scale_frac, f_decoder_rom, f_tsel_w);
            if (got != 5) begin
                $display("spec_rom9: ROM image '%0s' does not start with specrom's ROM 9 line (%m); make it with specrom",
                         INIT_FILE);
                $fatal(1);
            end
            if (f_n_w != N_W || f_scale_w != SCALE_W || f_scale_frac != SCALE_FRAC ||
                f_decoder_rom != DECODER_ROM || (DECODER_ROM != 0 && f_tsel_w != TSEL_W)) begin
                $display("spec_rom9: ROM image '%0s' was made for other parameters (%m):", INIT_FILE);
                $display("spec_rom9:   image: N_W=%0d SCALE_W=%0d SCALE_FRAC=%0d DECODER_ROM=%0d TSEL_W=%0d",
                         f_n_w, f_scale_w, f_scale_frac, f_decoder_rom, f_tsel_w);
                $display("spec_rom9:   core:  N_W=%0d SCALE_W=%0d SCALE_FRAC=%0d DECODER_ROM=%0d TSEL_W=%0d",
                         N_W, SCALE_W, SCALE_FRAC, DECODER_ROM, TSEL_W);
                $fatal(1);
            end
        end
    end
`endif
endmodule
`default_nettype wire
