// spec_setup_imgcheck - simulation-only check of an image spec_setup reads with $readmemh (an EFU table, the exp2
// table, the microcode): `$readmemh` only warns about a missing or short image and the simulation would run on
// with X or zero words, so this stops it ($fatal, non-zero exit) with a message naming the file when the image
// cannot be opened, holds another number of words than WORDS, or has a word of another number of hex digits than
// DIGITS. setuprom writes the images for the parameters in setup_params.vh; a mismatch means the image and the
// header on the include path come from different configurations. Synthesis (SYNTHESIS defined) skips it.
`timescale 1ns / 1ps
`default_nettype none
module spec_setup_imgcheck #(
    parameter FILE = "",
    parameter WORDS = 1,
    parameter DIGITS = 1
) ();
`ifndef SYNTHESIS
    /* verilator coverage_off */
    localparam LINE = 1024;   // characters read a line at most
    integer fd, got, words, n, i;
    reg [8*LINE-1:0] line;
    reg [7:0] ch;
    initial begin
        fd = $fopen(FILE, "r");
        if (fd == 0) begin
            $display("spec_setup: cannot open image '%0s' (%m; a relative path is relative to the simulator's", FILE);
            $display("spec_setup: working directory: pass the file parameters, or put the directory setuprom wrote on");
            $display("spec_setup: the include path with its setup_params.vh, docs/setup.md)");
            $fatal(1);
        end
        words = 0;
        line = {8 * LINE{1'b0}};
        got = $fgets(line, fd);
        while (got > 0) begin
            n = 0;   // hex digits on the line (a word: DIGITS of them and a newline)
            for (i = 0; i < got; i = i + 1) begin
                ch = line[8 * i +: 8];
                if ((ch >= "0" && ch <= "9") || (ch >= "a" && ch <= "f") || (ch >= "A" && ch <= "F")) n = n + 1;
            end
            if (n != 0) begin
                if (n != DIGITS) begin
                    $display("spec_setup: image '%0s' word %0d has %0d hex digits, not %0d: it was made for other", FILE,
                             words, n, DIGITS);
                    $display("spec_setup: parameters than setup_params.vh's (%m)");
                    $fatal(1);
                end
                words = words + 1;
            end
            line = {8 * LINE{1'b0}};
            got = $fgets(line, fd);
        end
        $fclose(fd);
        if (words != WORDS) begin
            $display("spec_setup: image '%0s' holds %0d words, not %0d: it was made for other parameters than", FILE,
                     words, WORDS);
            $display("spec_setup: setup_params.vh's (%m)");
            $fatal(1);
        end
    end
    /* verilator coverage_on */
`endif
endmodule
`default_nettype wire
