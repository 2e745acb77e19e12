// icebreaker_top - the iCEBreaker reference design (docs/boards.md): the lit, animated sphere scene at
// 640 x 480, 60 Hz through the 12-bit DVI Pmod (TFP410 transmitter) on PMOD 1A + 1B, drawn into a 320 x 240
// frame buffer in the UP5K's SPRAM by spec_shader's small configuration and shown pixel-doubled
// (board_core_fb: the small setup takes one span at a time, too slow to race the beam). The shader's back end
// is the compact spec_stream_seq (one span at a time too): spec_stream's flip-flops do not fit the UP5K.
//
// Clocks: one domain, clk = 25.125 MHz from the PLL (icebreaker_prims.v), the pixel clock: a pixel every
// cycle (pix_ce = 1), the renderer runs at the same clock. The data pins change at clk's rising edges; the
// Pmod's pixel clock is the inverse of clk from a DDR I/O cell, rising in the middle of each pixel, where the
// transmitter samples (half a pixel of setup and of hold, 19.9 ns).
// Reset: the PLL's lock and the user button (BTN_N, low while pressed) through a two-flop synchronizer.
// LEDs (active low): red = the frame buffer's write queue overflowed (sticky; board_core_fb's error), green
// changes with every rendered frame.
`timescale 1ns / 1ps
`default_nettype none
`include "board_params.vh"
module icebreaker_top #(
    parameter TEST = 0,      // 1: the 128 x 96 test raster (64 x 48 buffer) of the quick board simulation
    // boardgen's tables and the core's ROM images (up5k configuration); the flows pass absolute paths
    parameter SCENE_FILE = "boards/common/gen/scene_320x240.hex",
    parameter SPLIT_K = 8,
    parameter SPLIT_FILE = "boards/common/gen/split_8.hex",
    parameter OBJ_FILE = "boards/common/gen/objects_320x240.hex",
    parameter SHADE_FILE = "boards/common/gen/shade_320x240.hex",
    parameter LIGHT_FILE = "boards/common/gen/light_xy.hex",
    parameter ROM9_FILE = "build/rom_up5k/rom9_scale.hex",
    parameter ROM12_FILE = "build/rom_up5k/rom12_cosk.hex",
    parameter SETUP_DIR = "rom"        // the setups' tables and microcode (rom/setup_*.hex)
) (
    input  wire       CLK,        // 12 MHz
    input  wire       BTN_N,
    output wire       LEDR_N,
    output wire       LEDG_N,
    output wire [3:0] dvi_r,
    output wire [3:0] dvi_g,
    output wire [3:0] dvi_b,
    output wire       dvi_hs,
    output wire       dvi_vs,
    output wire       dvi_de,
    output wire       dvi_clk
);
    wire clk, locked;
    icebreaker_pll u_pll (.pin_12mhz(CLK), .clk(clk), .locked(locked));

    wire rst_n;
    cdc_sync #(.STAGES(2)) u_rst (.clk(clk), .rst_n(locked), .d(BTN_N), .q(rst_n));

    wire pix_ce = 1'b1;                  // a pixel every cycle

    localparam H_ACTIVE = TEST ? `BOARD128_H_ACTIVE : `BOARD640_H_ACTIVE;
    localparam H_FP = TEST ? `BOARD128_H_FP : `BOARD640_H_FP;
    localparam H_SYNC = TEST ? `BOARD128_H_SYNC : `BOARD640_H_SYNC;
    localparam H_BP = TEST ? `BOARD128_H_BP : `BOARD640_H_BP;
    localparam V_ACTIVE = TEST ? `BOARD128_V_ACTIVE : `BOARD640_V_ACTIVE;
    localparam V_FP = TEST ? `BOARD128_V_FP : `BOARD640_V_FP;
    localparam V_SYNC = TEST ? `BOARD128_V_SYNC : `BOARD640_V_SYNC;
    localparam V_BP = TEST ? `BOARD128_V_BP : `BOARD640_V_BP;
    localparam H_POL = TEST ? `BOARD128_H_POL : `BOARD640_H_POL;
    localparam V_POL = TEST ? `BOARD128_V_POL : `BOARD640_V_POL;

    wire [11:0] rgb;
    wire hs, vs, de, error;
    wire [7:0] frame;
    board_core_fb #(
        .H_ACTIVE(H_ACTIVE), .H_FP(H_FP), .H_SYNC(H_SYNC), .H_BP(H_BP), .V_ACTIVE(V_ACTIVE), .V_FP(V_FP),
        .V_SYNC(V_SYNC), .V_BP(V_BP), .H_POL(H_POL), .V_POL(V_POL), .BG_RGB(`BOARD_BG_RGB4),
        .N_OBJ(`BOARD_N_OBJ), .SPLIT_K(SPLIT_K), .SCENE_FILE(SCENE_FILE), .SPLIT_FILE(SPLIT_FILE),
        .OBJ_FILE(OBJ_FILE), .SHADE_FILE(SHADE_FILE), .LIGHT_FILE(LIGHT_FILE),
        .COS_E(`BOARD_COS_E), .COS_HALF_E(`BOARD_COS_HALF_E),
        .MUL_STEPS(1), .SQRT_STEPS(1), .SPANS_SERIAL(1), .SHADER_SMALL(1), .SHADER_BACKEND(1), .FIFO_QUEUE(0), .META_AW(1), .COMPOSE_STEPS(1),
        .COMPOSE_HOLD(1), .PASSES_OUT_REG(0),
        .ROM9_FILE(ROM9_FILE), .ROM12_FILE(ROM12_FILE), .SETUP_DIR(SETUP_DIR)
    ) u_core (
        .clk(clk), .rst_n(rst_n), .pix_ce(pix_ce), .rgb(rgb), .hsync(hs), .vsync(vs), .de(de), .error(error),
        .frame(frame)
    );

    wire [14:0] pins;
    icebreaker_dvi_pins u_pins (
        .clk(clk), .data({rgb, hs, vs, de}), .pins(pins), .pin_clk(dvi_clk)
    );
    assign {dvi_r, dvi_g, dvi_b, dvi_hs, dvi_vs, dvi_de} = pins;
    assign LEDR_N = ~error;
    assign LEDG_N = ~frame[0];
    wire unused_frame;
    assign unused_frame = &{1'b0, frame[7:1]};
endmodule
`default_nettype wire
