// SB_PLL40_PAD - simulation model of the iCE40 PLL (simple feedback only) for the board simulation.
// It measures the input clock's period over 4 cycles, then (after 17 more) raises LOCK and drives
// PLLOUTGLOBAL / PLLOUTCORE at F_in x (DIVF + 1) / ((DIVR + 1) x 2^DIVQ), rising with an input edge, every
// edge placed at an absolute time computed from the lock time (no drift from rounding).
// Times in ns (`timescale 1ns / 1ps: Verilator 5.006 scales a delay in a 1ps-unit file by the top's unit).
// Needs timing support (Verilator --timing, Icarus). Not for synthesis (Yosys has the real cell).
`timescale 1ns / 1ps
`default_nettype none
module SB_PLL40_PAD #(
    parameter FEEDBACK_PATH = "SIMPLE",
    parameter [3:0] DIVR = 4'd0,
    parameter [6:0] DIVF = 7'd0,
    parameter [2:0] DIVQ = 3'd0,
    parameter [2:0] FILTER_RANGE = 3'd0
) (
    input  wire PACKAGEPIN,
    output wire PLLOUTCORE,
    output wire PLLOUTGLOBAL,
    input  wire RESETB,
    input  wire BYPASS,
    output reg  LOCK
);
    reg out;
    assign PLLOUTCORE = out;
    assign PLLOUTGLOBAL = out;
    real t_first, t_lock, half;
    integer n_in, k;
    initial begin
        if (FEEDBACK_PATH != "SIMPLE") begin
            $display("SB_PLL40_PAD model: only FEEDBACK_PATH = \"SIMPLE\" (%m)");
            $finish;
        end
        out = 1'b0;
        LOCK = 1'b0;
        n_in = 0;
    end
    always @(posedge PACKAGEPIN) begin
        if (n_in == 0) t_first <= $realtime;
        if (n_in == 4) half <= ($realtime - t_first) / 4.0 * (DIVR + 1) * (1 << DIVQ) / (DIVF + 1) / 2.0;
        n_in <= n_in + 1;
    end
    initial begin
        wait (n_in > 20);
        t_lock = $realtime;
        LOCK = 1'b1;
        k = 0;
        forever begin
            out = ~out;
            k = k + 1;
            #(t_lock + k * half - $realtime);
        end
    end
    wire unused = &{1'b0, RESETB, BYPASS, FILTER_RANGE};
endmodule
`default_nettype wire
