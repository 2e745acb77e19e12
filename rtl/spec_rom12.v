// spec_rom12 - ROM 12 ("first ROM") of UA 71489 Fig. 1: the four tables cos^k(x), k = 1, 2, 4, 16,
// x = i * (pi/2) / 2^TBL_AW. Address = {table_sel (decoder 10), index (multiplier 11)}; the patent drives
// the top address bits with the four one-hot lines 30..33, of which only 4 of 16 codes occur - the 2-bit
// code addresses the same four tables without the unused space. Other table sets (docs/tuned.md): up to
// 2^TSEL_W tables, whatever powers k the image holds (the generator's --tables).
// Words UQ1.TBL_FRAC (TBL_FRAC + 1 bits): 1.0 exact; with interpolation (INTERP = 1, not in the patent) each
// word also carries the step to the next position in DELTA_W bits above the value.
// The image's first line (written by specrom) names the parameters it was made for; a simulation whose
// parameters differ stops at time 0 with a message naming the file and the field (spec_rom checks the rest).
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
        .INIT_FILE(INIT_FILE)
    ) u_mem (
        .clk (clk),
        .en  (en),
        .addr({table_sel, index}),
        .data(value)
    );

`ifndef SYNTHESIS
    integer fd, got, f_tbl_aw, f_tsel_w, f_tbl_frac, f_interp, f_delta_w;
    reg [8*256-1:0] line;
    initial begin
        fd = $fopen(INIT_FILE, "r");
        if (fd != 0) begin   // spec_rom reports a file that cannot be opened
            line = 0;
            got = $fgets(line, fd);
            $fclose(fd);
            // blanks above the characters read (Verilator's $sscanf does not skip the NUL bytes there)
            if (got > 0) line = line | ({256{8'h20}} << (8 * got));
            got = $sscanf(line, " // specrom ROM 12: tbl_aw=%d tsel_w=%d tbl_frac=%d interp=%d delta_w=%d",
                          f_tbl_aw, f_tsel_w, f_tbl_frac, f_interp, f_delta_w);
            if (got != 5) begin
                $display("spec_rom12: ROM image '%0s' does not start with specrom's ROM 12 line (%m); make it with specrom",
                         INIT_FILE);
                $fatal(1);
            end
            if (f_tbl_aw != TBL_AW || f_tsel_w != TSEL_W || f_tbl_frac != TBL_FRAC || f_interp != ((INTERP != 0) ? 1 : 0) ||
                (INTERP != 0 && f_delta_w != DELTA_W)) begin
                $display("spec_rom12: ROM image '%0s' was made for other parameters (%m):", INIT_FILE);
                $display("spec_rom12:   image: TBL_AW=%0d TSEL_W=%0d TBL_FRAC=%0d INTERP=%0d DELTA_W=%0d",
                         f_tbl_aw, f_tsel_w, f_tbl_frac, f_interp, f_delta_w);
                $display("spec_rom12:   core:  TBL_AW=%0d TSEL_W=%0d TBL_FRAC=%0d INTERP=%0d DELTA_W=%0d",
                         TBL_AW, TSEL_W, TBL_FRAC, INTERP, DELTA_W);
                $fatal(1);
            end
        end
    end
`endif
endmodule
`default_nettype wire
