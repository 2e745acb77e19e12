// spec_rom - a read-only memory with a registered read, loaded by $readmemh from INIT_FILE.
// The registered read lets Yosys map it to block RAM (SB_RAM40_4K on iCE40, DP16KD on ECP5).
//
// Image checks (simulation, at time 0): `$readmemh` only warns about an image that does not fit - Verilator
// and Icarus then run on with X or zero words, or with words cut to DW bits - so this module reads the image
// itself first and stops the simulation ($fatal, non-zero exit) with a message naming the file when
//   - it cannot be opened (a relative path is relative to the simulator's working directory),
//   - it holds fewer or more than 2^AW words,
//   - a word has more hex digits than DW bits need, or a value that does not fit DW bits,
//   - a line is neither a word, a `//` comment nor blank (address lines `@...` are not supported).
//   - HEADER = 9 or 12: the first line is not specrom's header of ROM 9 / ROM 12, or it names other parameters
//     than H0..H4 (ROM 9: N_W, SCALE_W, SCALE_FRAC, DECODER_ROM, TSEL_W; ROM 12: TBL_AW, TSEL_W, TBL_FRAC, INTERP,
//     DELTA_W; -1: any value) - the parameters the image was made for, which specrom writes there;
//     with POW = 1 (pow mode's tables, docs/pow.md) ROM 9's line names ANG_FRAC, POW_K, POW_SEG_W, POW_IDX_W,
//     POW_VAL_W, POW_DLT_W, POW_SH_W, POW_XB (H0..H7) and ROM 12's TBL_AW, TBL_FRAC, INTERP, DELTA_W (H0..H3);
//     an image of the other mode (a pow image in a core with POW = 0, or the other way round) is named as such.
// Synthesis tools define SYNTHESIS and skip these checks; the project's synthesis flows run syn/rom_check.py
// on the images before Yosys reads them.
`timescale 1ns / 1ps
`default_nettype none
module spec_rom #(
    parameter AW = 10,
    parameter DW = 18,
    parameter INIT_FILE = "",
    parameter HEADER = 0,    // 0: no header line expected; 9, 12: specrom's header of ROM 9 / ROM 12
    parameter POW = 0,       // HEADER 9, 12: 1 for pow mode's images (the log table, the exp2 table)
    parameter H0 = -1,
    parameter H1 = -1,
    parameter H2 = -1,
    parameter H3 = -1,
    parameter H4 = -1,
    parameter H5 = -1,
    parameter H6 = -1,
    parameter H7 = -1
) (
    input  wire          clk,
    input  wire          en,
    input  wire [AW-1:0] addr,
    output reg  [DW-1:0] data
);
    reg [DW-1:0] mem[0:(1 << AW) - 1];

`ifndef SYNTHESIS
    // The image checks run once at time 0; their error branches run only on broken images (the ctests
    // config_check_* do that in separate simulations), so they are kept out of line coverage.
    /* verilator coverage_off */
    localparam DIGITS = (DW + 3) / 4;
    localparam LINE_CHARS = 48;   // a word line fits; longer (comment) lines are read in pieces
    localparam HEAD_CHARS = 256;
    integer fd, got, nf, kind_pow, kind_cos, rom_no, lineno, words, pos, digits, first, f0, f1, f2, f3, f4, f5, f6, f7;
    reg [8*HEAD_CHARS-1:0] hline, hword;   // hword: the other mode's line's first field (read, not used)
    wire unused_hword;
    assign unused_hword = &{1'b0, hword};
    reg [8*LINE_CHARS-1:0] line;
    reg [7:0] ch;
    reg [63:0] value;
    reg is_hex, done, piece, skip;
    initial begin
        fd = $fopen(INIT_FILE, "r");
        if (fd == 0) begin
            $display("spec_rom: cannot open ROM image '%0s' (INIT_FILE of %m; a relative path is relative to the",
                     INIT_FILE);
            $display("spec_rom: simulator's working directory: pass the ROM path parameters or include a header");
            $display("spec_rom: made by 'specrom --out DIR', docs/interface.md)");
            $fatal(1);
        end
        if (HEADER != 0) begin
            hline = {8 * HEAD_CHARS{1'b0}};
            got = $fgets(hline, fd);
            if (got > 0) hline = hline | ({HEAD_CHARS{8'h20}} << (8 * got));  // blanks, not NULs, above
            f5 = -1;
            f6 = -1;
            f7 = -1;
            if (HEADER == 9 && POW == 0) begin
                nf = 5;
                got = $sscanf(hline, " // specrom ROM 9: n_w=%d scale_w=%d scale_frac=%d decoder_rom=%d tsel_w=%d",
                              f0, f1, f2, f3, f4);
            end else if (HEADER == 12 && POW == 0) begin
                nf = 5;
                got = $sscanf(hline, " // specrom ROM 12: tbl_aw=%d tsel_w=%d tbl_frac=%d interp=%d delta_w=%d",
                              f0, f1, f2, f3, f4);
            end else if (HEADER == 9) begin
                nf = 8;
                got = $sscanf(hline,
                              " // specrom ROM 9 pow: ang_frac=%d half_pi=%d seg_w=%d idx_w=%d val_w=%d dlt_w=%d sh_w=%d xb=%d",
                              f0, f1, f2, f3, f4, f5, f6, f7);
            end else begin
                nf = 4;
                f4 = -1;
                got = $sscanf(hline, " // specrom ROM 12 pow: tbl_aw=%d tbl_frac=%d interp=%d delta_w=%d", f0, f1, f2, f3);
            end
            if (got != nf) begin
                // an image of the other mode: its ROM's line with (or without) "pow"
                kind_pow = $sscanf(hline, " // specrom ROM %d pow: %s", rom_no, hword);
                if (kind_pow != 2) kind_cos = $sscanf(hline, " // specrom ROM %d: %s", rom_no, hword);
                else kind_cos = 0;
                if (POW == 0 && kind_pow == 2 && rom_no == HEADER)
                    $display("spec_rom: ROM image '%0s' was made for pow mode (specrom --mode pow), but this core has POW = 0: pass POW = 1 and pow mode's parameters, or patent/tuned images (%m)",
                             INIT_FILE);
                else if (POW != 0 && kind_cos == 2 && rom_no == HEADER)
                    $display("spec_rom: ROM image '%0s' was made for patent or tuned mode, but this core has POW = 1: pass the images of specrom --mode pow (%m)",
                             INIT_FILE);
                else
                    $display("spec_rom: ROM image '%0s' does not start with specrom's ROM %0d line%0s: make it with specrom (%m)",
                             INIT_FILE, HEADER, (POW != 0) ? " of pow mode" : "");
                $fatal(1);
            end
            if ((H0 >= 0 && f0 != H0) || (H1 >= 0 && f1 != H1) || (H2 >= 0 && f2 != H2) || (H3 >= 0 && f3 != H3) ||
                (H4 >= 0 && f4 != H4) || (H5 >= 0 && f5 != H5) || (H6 >= 0 && f6 != H6) || (H7 >= 0 && f7 != H7)) begin
                $display("spec_rom: ROM image '%0s' was made for other parameters (%m):", INIT_FILE);
                if (HEADER == 9 && POW != 0) begin
                    $display("spec_rom:   image ANG_FRAC=%0d POW_K=%0d POW_SEG_W=%0d POW_IDX_W=%0d POW_VAL_W=%0d POW_DLT_W=%0d POW_SH_W=%0d POW_XB=%0d",
                             f0, f1, f2, f3, f4, f5, f6, f7);
                    $display("spec_rom:   core  ANG_FRAC=%0d POW_K=%0d POW_SEG_W=%0d POW_IDX_W=%0d POW_VAL_W=%0d POW_DLT_W=%0d POW_SH_W=%0d POW_XB=%0d",
                             H0, H1, H2, H3, H4, H5, H6, H7);
                end else if (POW != 0) begin
                    $display("spec_rom:   image TBL_AW=%0d TBL_FRAC=%0d INTERP=%0d DELTA_W=%0d", f0, f1, f2, f3);
                    $display("spec_rom:   core  TBL_AW=%0d TBL_FRAC=%0d INTERP=%0d DELTA_W=%0d", H0, H1, H2, H3);
                end else if (HEADER == 9) begin
                    $display("spec_rom:   image N_W=%0d SCALE_W=%0d SCALE_FRAC=%0d DECODER_ROM=%0d TSEL_W=%0d",
                             f0, f1, f2, f3, f4);
                    $display("spec_rom:   core  N_W=%0d SCALE_W=%0d SCALE_FRAC=%0d DECODER_ROM=%0d TSEL_W=%0d",
                             H0, H1, H2, H3, H4);
                end else begin
                    $display("spec_rom:   image TBL_AW=%0d TSEL_W=%0d TBL_FRAC=%0d INTERP=%0d DELTA_W=%0d",
                             f0, f1, f2, f3, f4);
                    $display("spec_rom:   core  TBL_AW=%0d TSEL_W=%0d TBL_FRAC=%0d INTERP=%0d DELTA_W=%0d",
                             H0, H1, H2, H3, H4);
                end
                $fatal(1);
            end
            $fclose(fd);
            fd = $fopen(INIT_FILE, "r");   // the words from the top (the header is a comment to them)
        end
        words = 0;
        lineno = 0;
        piece = 1'b0;   // the chunk read continues a line longer than LINE_CHARS
        skip = 1'b0;    // ... of a comment
        line = {8 * LINE_CHARS{1'b0}};
        got = $fgets(line, fd);
        while (got > 0) begin
            if (!piece) lineno = lineno + 1;
            // the chunk's characters are line[8*got-1:0], the first one on top; find the first non-blank one
            first = -1;
            pos = got - 1;
            done = 1'b0;
            while (pos >= 0 && !done) begin
                ch = line[8 * pos +: 8];
                if (ch == " " || ch == "\t" || ch == "\n" || ch == "\r") pos = pos - 1;
                else done = 1'b1;
            end
            first = pos;
            if (piece) begin
                if (!skip) begin
                    $display("spec_rom: ROM image '%0s' line %0d: longer than %0d characters (%m)", INIT_FILE,
                             lineno, LINE_CHARS - 1);
                    $fatal(1);
                end
                first = -1;     // the rest of a comment
            end else begin
                skip = 1'b0;
            end
            if (first >= 0) begin
                ch = line[8 * first +: 8];
                if (ch == "/") begin
                    if (first < 1 || line[8 * (first - 1) +: 8] != "/") begin
                        $display("spec_rom: ROM image '%0s' line %0d: not a word or a // comment (%m)", INIT_FILE,
                                 lineno);
                        $fatal(1);
                    end
                    skip = 1'b1;
                end else begin
                    // count the hex digits of the word; anything after them must be blank or a comment
                    digits = 0;
                    pos = first;
                    done = 1'b0;
                    while (pos >= 0 && !done) begin
                        ch = line[8 * pos +: 8];
                        is_hex = (ch >= "0" && ch <= "9") || (ch >= "a" && ch <= "f") || (ch >= "A" && ch <= "F");
                        if (is_hex) begin
                            digits = digits + 1;
                            pos = pos - 1;
                        end else begin
                            done = 1'b1;
                        end
                    end
                    if (digits == 0) begin
                        $display("spec_rom: ROM image '%0s' line %0d: not a hex word (address lines @... are not supported) (%m)",
                                 INIT_FILE, lineno);
                        $fatal(1);
                    end
                    if (digits > DIGITS) begin
                        $display("spec_rom: ROM image '%0s' line %0d: %0d hex digits, but the words are %0d bits (%0d digits): the image was made for other parameters (%m)",
                                 INIT_FILE, lineno, digits, DW, DIGITS);
                        $fatal(1);
                    end
                    // blanks above the characters read (Verilator's $sscanf does not skip NUL bytes)
                    line = line | ({LINE_CHARS{8'h20}} << (8 * got));
                    value = 64'd0;
                    got = $sscanf(line, "%h", value);
                    if (got != 1) begin
                        $display("spec_rom: ROM image '%0s' line %0d: not a hex word (%m)", INIT_FILE, lineno);
                        $fatal(1);
                    end
                    if ((value >> DW) != 64'd0) begin
                        $display("spec_rom: ROM image '%0s' line %0d: value %0h does not fit %0d bits: the image was made for other parameters (%m)",
                                 INIT_FILE, lineno, value, DW);
                        $fatal(1);
                    end
                    words = words + 1;
                end
            end
            // a chunk that does not end in a newline is continued by the next one
            piece = (line[7:0] != "\n");
            line = {8 * LINE_CHARS{1'b0}};
            got = $fgets(line, fd);
        end
        $fclose(fd);
        if (words != (1 << AW)) begin
            $display("spec_rom: ROM image '%0s' holds %0d words, but the ROM has %0d (2^%0d): the image was made for other parameters (%m)",
                     INIT_FILE, words, 1 << AW, AW);
            $fatal(1);
        end
        $readmemh(INIT_FILE, mem);
    end
    /* verilator coverage_on */
`else
    initial $readmemh(INIT_FILE, mem);
`endif

    always @(posedge clk) begin
        if (en) data <= mem[addr];
    end
endmodule
`default_nettype wire
