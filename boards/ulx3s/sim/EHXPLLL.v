// EHXPLLL - simulation model of the ECP5 PLL for the board simulation: feedback from CLKOP only, outputs
// CLKOP and CLKOS (CLKOS2/3 held low). It measures CLKI's period over 4 cycles, then (after 17 more) raises
// LOCK and drives CLKOP at F_in x CLKFB_DIV / CLKI_DIV and CLKOS at CLKOP x CLKOP_DIV / CLKOS_DIV, both
// rising together at lock; every edge is placed at an absolute time computed from the lock time, so the
// outputs keep their exact ratio (the TMDS serializer relies on it, as on the chip). Phase parameters are
// not modelled. Times in ns (`timescale 1ns / 1ps: Verilator 5.006 scales a delay in a 1ps-unit file by the
// top's unit). Needs timing support (Verilator --timing, Icarus). Not for synthesis.
`timescale 1ns / 1ps
`default_nettype none
// The cell's full parameter list is declared so that the design's instance elaborates unchanged; most
// parameters are not modelled (phase, wake-up, divider multiplexers).
/* verilator lint_off UNUSEDPARAM */
module EHXPLLL #(
    parameter PLLRST_ENA = "DISABLED",
    parameter INTFB_WAKE = "DISABLED",
    parameter STDBY_ENABLE = "DISABLED",
    parameter DPHASE_SOURCE = "DISABLED",
    parameter OUTDIVIDER_MUXA = "DIVA",
    parameter OUTDIVIDER_MUXB = "DIVB",
    parameter OUTDIVIDER_MUXC = "DIVC",
    parameter OUTDIVIDER_MUXD = "DIVD",
    parameter integer CLKI_DIV = 1,
    parameter CLKOP_ENABLE = "ENABLED",
    parameter integer CLKOP_DIV = 8,
    parameter integer CLKOP_CPHASE = 0,
    parameter integer CLKOP_FPHASE = 0,
    parameter CLKOS_ENABLE = "DISABLED",
    parameter integer CLKOS_DIV = 8,
    parameter integer CLKOS_CPHASE = 0,
    parameter integer CLKOS_FPHASE = 0,
    parameter FEEDBK_PATH = "CLKOP",
    parameter integer CLKFB_DIV = 1
) (
    /* verilator lint_on UNUSEDPARAM */
    input  wire RST,
    input  wire STDBY,
    input  wire CLKI,
    output reg  CLKOP,
    output reg  CLKOS,
    input  wire CLKFB,
    output wire CLKINTFB,
    input  wire PHASESEL0,
    input  wire PHASESEL1,
    input  wire PHASEDIR,
    input  wire PHASESTEP,
    input  wire PHASELOADREG,
    input  wire PLLWAKESYNC,
    input  wire ENCLKOP,
    output reg  LOCK
);
    assign CLKINTFB = 1'b0;
    real t_first, t_lock, half_op, half_os;
    integer n_in, k_op, k_os;
    initial begin
        if (FEEDBK_PATH != "CLKOP") begin
            $display("EHXPLLL model: only FEEDBK_PATH = \"CLKOP\" (%m)");
            $finish;
        end
        CLKOP = 1'b0;
        CLKOS = 1'b0;
        LOCK = 1'b0;
        n_in = 0;
    end
    always @(posedge CLKI) begin
        if (n_in == 0) t_first <= $realtime;
        if (n_in == 4) begin
            half_op <= ($realtime - t_first) / 4.0 * CLKI_DIV / CLKFB_DIV / 2.0;
            half_os <= ($realtime - t_first) / 4.0 * CLKI_DIV / CLKFB_DIV * CLKOS_DIV / CLKOP_DIV / 2.0;
        end
        n_in <= n_in + 1;
    end
    initial begin
        wait (n_in > 20);
        t_lock = $realtime;
        LOCK = 1'b1;
        k_op = 0;
        forever begin
            CLKOP = ~CLKOP;
            k_op = k_op + 1;
            #(t_lock + k_op * half_op - $realtime);
        end
    end
    initial begin
        wait (LOCK);
        k_os = 0;
        forever begin
            if (CLKOS_ENABLE == "ENABLED") CLKOS = ~CLKOS;
            k_os = k_os + 1;
            #(t_lock + k_os * half_os - $realtime);
        end
    end
    wire unused = &{1'b0, RST, STDBY, CLKFB, PHASESEL0, PHASESEL1, PHASEDIR, PHASESTEP, PHASELOADREG,
                    PLLWAKESYNC, ENCLKOP};
endmodule
`default_nettype wire
