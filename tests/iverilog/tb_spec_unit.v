// tb_spec_unit - self-checking Icarus Verilog testbench for spec_unit.
// Reads +vectors=FILE (written by `specsim vectors` from the bit-exact C++ model): the span count, then per
// span C, dzeta, zeta0, n, l and the l + 1 expected pixels. Each span is written through the ports, started,
// and every valid_o pixel compared; a mismatch, a missing or extra pixel, or a hang ends with $fatal (exit 1).
// Widths come from the configuration's spec_params.vh (the include path picks it); ROM9_FILE/ROM12_FILE can be
// set with iverilog -P (tests/icarus.cmake runs the simulation outside the repository with absolute paths).
// 4-state: init_n is low for exactly one clock at the start, and from then on every output must be 0 or 1
// in every cycle (docs/interface.md: one init_n pulse is the reset the core needs).
`timescale 1ns / 1ps
`default_nettype none
`include "spec_params.vh"
module tb_spec_unit #(
    parameter ROM9_FILE = `SPEC_ROM9_FILE,
    parameter ROM12_FILE = `SPEC_ROM12_FILE
);
    localparam VMAX = 65536;
    localparam C_W = `SPEC_C_W, ANG_W = `SPEC_ANG_W, N_W = `SPEC_N_W, L_W = `SPEC_L_W, OUT_W = `SPEC_OUT_W;
    reg clk = 1'b0;
    always #5 clk = ~clk;

    reg init_n = 1'b0, start = 1'b0;
    reg [C_W-1:0] c_i = {C_W{1'b0}};
    reg c_we = 1'b0;
    reg [ANG_W-1:0] dzeta_i = {ANG_W{1'b0}}, zeta0_i = {ANG_W{1'b0}};
    reg dzeta_we = 1'b0, zeta0_we = 1'b0;
    reg [N_W-1:0] n_i = {N_W{1'b0}};
    reg n_we = 1'b0;
    reg [L_W-1:0] len_i = {L_W{1'b0}};
    reg len_load_n = 1'b1;
    wire [OUT_W-1:0] intensity_o;
    wire busy_o, valid_o;

    spec_unit #(.ROM9_FILE(ROM9_FILE), .ROM12_FILE(ROM12_FILE)) dut (
        .clk(clk), .init_n(init_n), .start(start),
        .c_i(c_i), .c_we(c_we), .dzeta_i(dzeta_i), .dzeta_we(dzeta_we),
        .zeta0_i(zeta0_i), .zeta0_we(zeta0_we), .n_i(n_i), .n_we(n_we),
        .len_i(len_i), .len_load_n(len_load_n),
        .intensity_o(intensity_o), .busy_o(busy_o), .valid_o(valid_o)
    );

    // after the one init_n pulse, no output is ever X or Z
    reg reset_done = 1'b0;
    always @(negedge clk) begin
        if (reset_done && ^{intensity_o, busy_o, valid_o} === 1'bx) begin
            $display("tb_spec_unit: an output is X or Z after reset at %0t: intensity %b busy %b valid %b", $time,
                     intensity_o, busy_o, valid_o);
            $fatal(1);
        end
    end

    reg [31:0] vec[0:VMAX-1];
    reg [1023:0] path;
    integer p, s, nspans, i, got, errors, cycles, pixels, len;

    initial begin
        if (!$value$plusargs("vectors=%s", path)) begin
            $display("tb_spec_unit: +vectors=FILE missing");
            $fatal(1);
        end
        for (i = 0; i < VMAX; i = i + 1) vec[i] = 32'hxxxxxxxx;
        $readmemh(path, vec);
        if (^vec[0] === 1'bx) begin
            $display("tb_spec_unit: cannot read vectors from %0s", path);
            $fatal(1);
        end
        nspans = vec[0];
        p = 1;
        errors = 0;
        pixels = 0;
        @(posedge clk);          // the one reset edge
        init_n <= 1'b1;
        reset_done <= 1'b1;
        @(posedge clk);
        for (s = 0; s < nspans; s = s + 1) begin
            len = vec[p + 4];
            c_i <= vec[p][C_W-1:0];           c_we <= 1'b1;
            dzeta_i <= vec[p + 1][ANG_W-1:0]; dzeta_we <= 1'b1;
            zeta0_i <= vec[p + 2][ANG_W-1:0]; zeta0_we <= 1'b1;
            n_i <= vec[p + 3][N_W-1:0];       n_we <= 1'b1;
            len_i <= vec[p + 4][L_W-1:0];     len_load_n <= 1'b0;
            @(posedge clk);
            c_we <= 1'b0; dzeta_we <= 1'b0; zeta0_we <= 1'b0; n_we <= 1'b0; len_load_n <= 1'b1;
            start <= 1'b1;
            @(posedge clk);
            start <= 1'b0;
            got = 0;
            cycles = 0;
            #1;
            while (busy_o) begin
                if (valid_o) begin
                    if (got > len) begin
                        $display("span %0d: more than %0d pixels", s, len + 1);
                        $fatal(1);
                    end
                    if (intensity_o !== vec[p + 5 + got][OUT_W-1:0]) begin
                        $display("span %0d (n=%0d, len=%0d) pixel %0d: got %h, model %h", s, vec[p + 3], len,
                                 got, intensity_o, vec[p + 5 + got][OUT_W-1:0]);
                        errors = errors + 1;
                    end
                    got = got + 1;
                end
                @(posedge clk);
                #1;
                cycles = cycles + 1;
                if (cycles > 4 * (len + 8)) begin
                    $display("span %0d: busy_o did not fall", s);
                    $fatal(1);
                end
            end
            if (got != len + 1) begin
                $display("span %0d: %0d pixels, expected %0d", s, got, len + 1);
                $fatal(1);
            end
            pixels = pixels + got;
            p = p + 5 + len + 1;
            if (errors > 0) $fatal(1);
        end
        $display("PASS: %0d spans, %0d pixels equal to the bit-exact model", nspans, pixels);
        $finish;
    end
endmodule
`default_nettype wire
