// SB_IO - simulation model of the iCE40 I/O cell, output side only, for the PIN_TYPE values the board design
// uses: 0101_01 (registered output: D_OUT_0 loaded at the rising OUTPUT_CLK edge when CLOCK_ENABLE = 1),
// 0100_01 (DDR output: D_OUT_0 loaded at the rising edge, D_OUT_1 at the falling edge; the pad shows the
// rising edge's register while OUTPUT_CLK is high, the falling edge's while it is low) and 0110_01 (simple
// output: the pad follows D_OUT_0). Other values stop the simulation. CLOCK_ENABLE gates both registers
// directly (the design ties it to 1; the vendor's model latches it at the rising edge for the falling one).
`timescale 1ns / 1ps
`default_nettype none
module SB_IO #(
    parameter [5:0] PIN_TYPE = 6'b0101_01
) (
    inout  wire PACKAGE_PIN,
    input  wire CLOCK_ENABLE,
    input  wire OUTPUT_CLK,
    input  wire D_OUT_0,
    input  wire D_OUT_1
);
    initial begin
        if (PIN_TYPE != 6'b0101_01 && PIN_TYPE != 6'b0100_01 && PIN_TYPE != 6'b0110_01) begin
            $display("SB_IO model: PIN_TYPE %b is not modelled (%m)", PIN_TYPE);
            $finish;
        end
    end
    reg q = 1'b0, q1 = 1'b0;
    always @(posedge OUTPUT_CLK) if (CLOCK_ENABLE) q <= D_OUT_0;
    always @(negedge OUTPUT_CLK) if (CLOCK_ENABLE) q1 <= D_OUT_1;
    assign PACKAGE_PIN = (PIN_TYPE == 6'b0110_01) ? D_OUT_0 : (PIN_TYPE == 6'b0100_01 && !OUTPUT_CLK) ? q1 : q;
endmodule
`default_nettype wire
