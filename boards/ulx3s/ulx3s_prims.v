// ulx3s_prims - every ECP5-specific primitive of the ULX3S reference design, so that the rest
// (boards/common/) is plain Verilog: the PLL and the double-data-rate output registers of the GPDI pins.
// Synthesis uses the ECP5 cells (Lattice FPGA Libraries Reference Guide: EHXPLLL, ODDRX1F); simulation uses
// the models in boards/ulx3s/sim/.
`timescale 1ns / 1ps
`default_nettype none
// One file holds the board's primitive wrappers (the issue's rule: every primitive in one board-specific file),
// so the file name cannot match each module's: the one waiver of that rule.
/* verilator lint_off DECLFILENAME */

// ulx3s_pll - 25 MHz from the board's oscillator to the TMDS bit clock (half the bit rate: the DDR outputs
// send two bits per clock) and the design clock, phase-locked (the serializer relies on it).
// EHXPLLL with feedback from CLKOP: CLKOP = 25 MHz x CLKFB_DIV / CLKI_DIV, VCO = CLKOP x CLKOP_DIV
// (400..800 MHz), CLKOS = VCO / CLKOS_DIV, phase detector input 25 MHz / CLKI_DIV.
//   640 x 480 (MODE720 = 0): CLKI_DIV 1, CLKFB_DIV 5: CLKOP 125 MHz, CLKOP_DIV 4 (VCO 500 MHz),
//                            CLKOS_DIV 10: design clock 50 MHz, twice the pixel clock of 25.000 MHz
//                            (VESA: 25.175 MHz, -0.7 %, 59.5 Hz)
//   1280 x 720 (MODE720 = 1): CLKI_DIV 7, CLKFB_DIV 104: CLKOP 371.43 MHz, CLKOP_DIV 2 (VCO 742.9 MHz),
//                            CLKOS_DIV 10: design clock = pixel clock 74.286 MHz (CTA-861: 74.25 MHz, +0.05 %)
module ulx3s_pll #(
    parameter MODE720 = 0
) (
    input  wire clk_25mhz,
    output wire clk_bit,
    output wire clk_core,
    output wire locked
);
    localparam CLKI_DIV = MODE720 ? 7 : 1;
    localparam CLKFB_DIV = MODE720 ? 104 : 5;
    localparam CLKOP_DIV = MODE720 ? 2 : 4;
    localparam CLKOS_DIV = 10;
    wire clkop, clkintfb_unused;
    (* FREQUENCY_PIN_CLKI = "25" *)
    EHXPLLL #(
        .PLLRST_ENA("DISABLED"),
        .INTFB_WAKE("DISABLED"),
        .STDBY_ENABLE("DISABLED"),
        .DPHASE_SOURCE("DISABLED"),
        .OUTDIVIDER_MUXA("DIVA"),
        .OUTDIVIDER_MUXB("DIVB"),
        .OUTDIVIDER_MUXC("DIVC"),
        .OUTDIVIDER_MUXD("DIVD"),
        .CLKI_DIV(CLKI_DIV),
        .CLKOP_ENABLE("ENABLED"),
        .CLKOP_DIV(CLKOP_DIV),
        .CLKOP_CPHASE(CLKOP_DIV - 1),
        .CLKOP_FPHASE(0),
        .CLKOS_ENABLE("ENABLED"),
        .CLKOS_DIV(CLKOS_DIV),
        .CLKOS_CPHASE(CLKOS_DIV - 1),
        .CLKOS_FPHASE(0),
        .FEEDBK_PATH("CLKOP"),
        .CLKFB_DIV(CLKFB_DIV)
    ) u_pll (
        .RST(1'b0),
        .STDBY(1'b0),
        .CLKI(clk_25mhz),
        .CLKOP(clkop),
        .CLKOS(clk_core),
        .CLKFB(clkop),
        .CLKINTFB(clkintfb_unused),
        .PHASESEL0(1'b0),
        .PHASESEL1(1'b0),
        .PHASEDIR(1'b1),
        .PHASESTEP(1'b1),
        .PHASELOADREG(1'b1),
        .PLLWAKESYNC(1'b0),
        .ENCLKOP(1'b0),
        .LOCK(locked)
    );
    assign clk_bit = clkop;
endmodule

// ulx3s_gpdi_pins - the four TMDS channels on the GPDI connector, each from a DDR output register
// (ODDRX1F: d0 leaves first, in the first half of the clock period, d1 in the second). The pins are
// LVCMOS33D (the LPF): the complementary pad of each pair is driven inverted by the I/O bank.
module ulx3s_gpdi_pins (
    input  wire       clk_bit,
    input  wire [7:0] pairs,       // {lane3, lane2, lane1, lane0}, bits (d1, d0) per lane
    output wire [3:0] gpdi_dp
);
    genvar i;
    generate
        for (i = 0; i < 4; i = i + 1) begin : g_lane
            ODDRX1F u_ddr (.SCLK(clk_bit), .RST(1'b0), .D0(pairs[2 * i]), .D1(pairs[2 * i + 1]), .Q(gpdi_dp[i]));
        end
    endgenerate
endmodule
/* verilator lint_on DECLFILENAME */
`default_nettype wire
