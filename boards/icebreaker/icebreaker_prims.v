// icebreaker_prims - every iCE40-specific primitive of the iCEBreaker reference design, so that the rest
// (boards/common/) is plain Verilog: the PLL and the registered I/O cells of the DVI Pmod's pins.
// Synthesis uses the iCE40 cells (Lattice iCE40 Technology Library: SB_PLL40_PAD, SB_IO); simulation uses
// the models in boards/icebreaker/sim/.
`timescale 1ns / 1ps
`default_nettype none
// One file holds the board's primitive wrappers (the issue's rule: every primitive in one board-specific file),
// so the file name cannot match each module's: the one waiver of that rule.
/* verilator lint_off DECLFILENAME */

// icebreaker_pll - 12 MHz from the board's oscillator (pin 35, the PLL's input pad) to the design clock.
// SB_PLL40_PAD, simple feedback: F_out = 12 MHz x (DIVF + 1) / ((DIVR + 1) x 2^DIVQ) with the VCO
// (12 MHz x (DIVF + 1) / (DIVR + 1)) within 533..1066 MHz: DIVR = 0, DIVF = 66, DIVQ = 5 give
// 12 x 67 / 32 = 25.125 MHz (VCO 804 MHz), the pixel clock (VESA 640 x 480 at 60 Hz: 25.175 MHz, -0.2 %).
// FILTER_RANGE = 1 for the 12 MHz phase detector input.
module icebreaker_pll (
    input  wire pin_12mhz,
    output wire clk,
    output wire locked
);
    wire pll_core_unused;
    SB_PLL40_PAD #(
        .FEEDBACK_PATH("SIMPLE"),
        .DIVR(4'd0),
        .DIVF(7'd66),
        .DIVQ(3'd5),
        .FILTER_RANGE(3'd1)
    ) u_pll (
        .PACKAGEPIN(pin_12mhz),
        .PLLOUTCORE(pll_core_unused),
        .PLLOUTGLOBAL(clk),
        .RESETB(1'b1),
        .BYPASS(1'b0),
        .LOCK(locked)
    );
endmodule

// icebreaker_dvi_pins - the 16 pins of the 12-bit DVI Pmod at one pixel a clock. The 15 data pins are driven
// from the output flip-flops of their I/O cells (SB_IO, PIN_TYPE 0101_01: registered output, no output
// enable), loaded every rising edge of clk with data = {r[3:0], g[3:0], b[3:0], hsync, vsync, de} (fabric
// registers), so that all pins switch together at the pad, one clock after data. The pixel clock pin is a
// DDR output (PIN_TYPE 0100_01: D_OUT_0 shown from the rising edge, D_OUT_1 from the falling edge) of 0 and
// 1: the inverse of clk, rising at clk's falling edge, in the middle of each pixel, where the Pmod's TFP410
// samples (half a pixel, 19.9 ns, of setup and of hold).
module icebreaker_dvi_pins (
    input  wire        clk,
    input  wire [14:0] data,
    output wire [14:0] pins,
    output wire        pin_clk
);
    genvar i;
    generate
        for (i = 0; i < 15; i = i + 1) begin : g_pin
            SB_IO #(.PIN_TYPE(6'b0101_01)) u_io (
                .PACKAGE_PIN(pins[i]), .CLOCK_ENABLE(1'b1), .OUTPUT_CLK(clk), .D_OUT_0(data[i]), .D_OUT_1(1'b0)
            );
        end
    endgenerate
    SB_IO #(.PIN_TYPE(6'b0100_01)) u_clk (
        .PACKAGE_PIN(pin_clk), .CLOCK_ENABLE(1'b1), .OUTPUT_CLK(clk), .D_OUT_0(1'b0), .D_OUT_1(1'b1)
    );
endmodule
/* verilator lint_on DECLFILENAME */
`default_nettype wire
