// ulx3s_top - the ULX3S reference design (docs/boards.md): the lit, animated sphere scene on the GPDI
// (HDMI-shaped, DVI-signalled) connector, 640 x 480 at 60 Hz (MODE = 0) or 1280 x 720 at 60 Hz (MODE = 1),
// TMDS-encoded in the FPGA; MODE = 2 is the 128 x 96 test raster of the quick board simulation (make test),
// MODE = 3 the same raster racing the beam (MODE = 1's architecture).
//
// Two architectures (docs/boards.md, "ULX3S"):
//   MODE 0, 2: board_core_fb, the iCEBreaker's: spec_shader's small configuration (one span at a time, the
//            size of an ECP5-25F) renders at half the size into a frame buffer in block RAM
//            (frame_store_packed: 320 x 240 RGB444 in 50 of the 56 DP16KD) shown pixel-doubled; the colour's
//            4 bits a channel go out as 8 (x 17); the light moves with every rendered frame; the light's
//            table in logic (LIGHT_BRAM = 0: the buffer and the shader take every DP16KD);
//   MODE 1, 3: board_core, racing the beam: each line rendered during the line before by two
//            ecp5 spec_shaders (the multiplier setup, a span every 28 clocks; one per pass, K = 8), which do not
//            fit an ECP5-25F (simulation only; docs/boards.md).
//
// Clock domains (both from one PLL, phase-locked; ulx3s_prims.v):
//   clk_core the design clock: the whole of the core and the three TMDS encoders; twice the pixel clock at
//            640 x 480 (pix_ce every other cycle), the pixel clock itself at 1280 x 720;
//   clk_bit  5 x the pixel clock: the serializer and the DDR output registers (10 bits per pixel).
// Crossings (docs/boards.md, "Clock domains"): the encoders' characters and a toggle, core -> bit domain,
// through tmds_serializer (toggle synchronizer, characters sampled at a fixed phase while stable); the reset,
// core -> bit domain, through cdc_sync. Nothing crosses back but a status LED.
// Reset: the PLL's lock and the power button (btn[0], low while pressed), synchronized.
// LEDs: led[0] = a line was not rendered in time (racing) or the write queue overflowed (frame buffer)
// (sticky), led[1] = the serializer lost step with the pixel clock (sticky), led[7] changes with every
// rendered frame (frame buffer) or blinks with the frame counter (racing).
`timescale 1ns / 1ps
`default_nettype none
`include "board_params.vh"
module ulx3s_top #(
    parameter MODE = 0,
    parameter SPLIT_K = 8,
    // boardgen's tables and the core's ROM images (up5k configuration); the flows pass absolute paths
    parameter SCENE_FILE = "boards/common/gen/scene_640x480.hex",
    parameter SPLIT_FILE = "boards/common/gen/split_8.hex",
    parameter OBJ_FILE = "boards/common/gen/objects_640x480.hex",
    parameter SHADE_FILE = "boards/common/gen/shade_640x480.hex",
    parameter LIGHT_FILE = "boards/common/gen/light_xy.hex",
    parameter ROM9_FILE = "build/rom_up5k/rom9_scale.hex",
    parameter ROM12_FILE = "build/rom_up5k/rom12_cosk.hex",
    parameter SETUP_DIR = "rom"        // the setups' tables and microcode (rom/setup_*.hex)
) (
    input  wire       clk_25mhz,
    input  wire [6:0] btn,
    output wire [7:0] led,
    output wire [3:0] gpdi_dp
);
    // the two rasters (VESA DMT 640x480@60, CTA-861 VIC 4 1280x720@60), from boardgen
    localparam H_ACTIVE = (MODE == 1) ? `BOARD1280_H_ACTIVE : (MODE >= 2) ? `BOARD128_H_ACTIVE : `BOARD640_H_ACTIVE;
    localparam H_FP = (MODE == 1) ? `BOARD1280_H_FP : (MODE >= 2) ? `BOARD128_H_FP : `BOARD640_H_FP;
    localparam H_SYNC = (MODE == 1) ? `BOARD1280_H_SYNC : (MODE >= 2) ? `BOARD128_H_SYNC : `BOARD640_H_SYNC;
    localparam H_BP = (MODE == 1) ? `BOARD1280_H_BP : (MODE >= 2) ? `BOARD128_H_BP : `BOARD640_H_BP;
    localparam V_ACTIVE = (MODE == 1) ? `BOARD1280_V_ACTIVE : (MODE >= 2) ? `BOARD128_V_ACTIVE : `BOARD640_V_ACTIVE;
    localparam V_FP = (MODE == 1) ? `BOARD1280_V_FP : (MODE >= 2) ? `BOARD128_V_FP : `BOARD640_V_FP;
    localparam V_SYNC = (MODE == 1) ? `BOARD1280_V_SYNC : (MODE >= 2) ? `BOARD128_V_SYNC : `BOARD640_V_SYNC;
    localparam V_BP = (MODE == 1) ? `BOARD1280_V_BP : (MODE >= 2) ? `BOARD128_V_BP : `BOARD640_V_BP;
    localparam H_POL = (MODE == 1) ? `BOARD1280_H_POL : (MODE >= 2) ? `BOARD128_H_POL : `BOARD640_H_POL;
    localparam V_POL = (MODE == 1) ? `BOARD1280_V_POL : (MODE >= 2) ? `BOARD128_V_POL : `BOARD640_V_POL;

    wire clk_bit, clk_core, locked;
    ulx3s_pll #(.MODE720(MODE == 1)) u_pll (.clk_25mhz(clk_25mhz), .clk_bit(clk_bit), .clk_core(clk_core),
                                          .locked(locked));
    wire rst_n, rst_bit_n;
    cdc_sync #(.STAGES(2)) u_rst (.clk(clk_core), .rst_n(locked), .d(btn[0]), .q(rst_n));

    // the pixel clock enable: every other cycle at 640 x 480, every cycle at 1280 x 720
    reg pix_half;
    always @(posedge clk_core) begin
        if (!rst_n) pix_half <= 1'b0;
        else pix_half <= ~pix_half;
    end
    wire pix_ce = (MODE == 1) ? 1'b1 : pix_half;
    cdc_sync #(.STAGES(2)) u_rst_bit (.clk(clk_bit), .rst_n(locked), .d(rst_n), .q(rst_bit_n));

    wire [23:0] rgb;
    wire hs, vs, de, late;
    wire [7:0] frame;
    generate
        if (MODE == 0 || MODE == 2) begin : g_fb
            wire [11:0] rgb4;
            board_core_fb #(
                .H_ACTIVE(H_ACTIVE), .H_FP(H_FP), .H_SYNC(H_SYNC), .H_BP(H_BP), .V_ACTIVE(V_ACTIVE),
                .V_FP(V_FP), .V_SYNC(V_SYNC), .V_BP(V_BP), .H_POL(H_POL), .V_POL(V_POL),
                .BG_RGB(`BOARD_BG_RGB4), .N_OBJ(`BOARD_N_OBJ), .SPLIT_K(SPLIT_K), .SCENE_FILE(SCENE_FILE),
                .SPLIT_FILE(SPLIT_FILE), .OBJ_FILE(OBJ_FILE), .SHADE_FILE(SHADE_FILE), .LIGHT_FILE(LIGHT_FILE),
                .COS_E(`BOARD_COS_E), .COS_HALF_E(`BOARD_COS_HALF_E), .MUL_STEPS(1), .SQRT_STEPS(1), .SHADER_SMALL(1),
                .SHADER_BACKEND(1),
                .ROM9_FILE(ROM9_FILE), .ROM12_FILE(ROM12_FILE), .SETUP_DIR(SETUP_DIR),
                .STORE_PACKED(1), .FIFO_LUTRAM(1), .LIGHT_BRAM(0)
            ) u_core (
                .clk(clk_core), .rst_n(rst_n), .pix_ce(pix_ce), .rgb(rgb4), .hsync(hs), .vsync(vs), .de(de),
                .error(late), .frame(frame)
            );
            // 4 bits a channel to 8: x 17 (the nibble twice)
            assign rgb = {rgb4[11:8], rgb4[11:8], rgb4[7:4], rgb4[7:4], rgb4[3:0], rgb4[3:0]};
        end else begin : g_race
            board_core #(
                .H_ACTIVE(H_ACTIVE), .H_FP(H_FP), .H_SYNC(H_SYNC), .H_BP(H_BP), .V_ACTIVE(V_ACTIVE),
                .V_FP(V_FP), .V_SYNC(V_SYNC), .V_BP(V_BP), .H_POL(H_POL), .V_POL(V_POL),
                .OUT_BITS(8), .BG_RGB(`BOARD_BG_RGB8),
                .N_OBJ(`BOARD_N_OBJ), .SPLIT_K(SPLIT_K), .SCENE_FILE(SCENE_FILE), .SPLIT_FILE(SPLIT_FILE),
                .OBJ_FILE(OBJ_FILE), .SHADE_FILE(SHADE_FILE), .LIGHT_FILE(LIGHT_FILE),
                .COS_E(`BOARD_COS_E), .COS_HALF_E(`BOARD_COS_HALF_E),
                .MUL_STEPS(9), .SQRT_STEPS((MODE == 1) ? 2 : 7), .SHADERS(2),
                .SHADER_SMALL(0), .ROM9_FILE(ROM9_FILE), .ROM12_FILE(ROM12_FILE), .SETUP_DIR(SETUP_DIR)
            ) u_core (
                .clk(clk_core), .rst_n(rst_n), .pix_ce(pix_ce), .rgb(rgb), .hsync(hs), .vsync(vs), .de(de),
                .late(late), .frame(frame)
            );
        end
    endgenerate

    // TMDS: blue carries the syncs in its control characters (DVI 1.0)
    wire [9:0] q_r, q_g, q_b;
    tmds_encoder u_enc_b (.clk(clk_core), .rst_n(rst_n), .ce(pix_ce), .de(de), .c({vs, hs}), .d(rgb[7:0]), .q(q_b));
    tmds_encoder u_enc_g (.clk(clk_core), .rst_n(rst_n), .ce(pix_ce), .de(de), .c(2'b00), .d(rgb[15:8]), .q(q_g));
    tmds_encoder u_enc_r (.clk(clk_core), .rst_n(rst_n), .ce(pix_ce), .de(de), .c(2'b00), .d(rgb[23:16]), .q(q_r));
    // toggles with each new character triple (the encoders load in pix_ce cycles)
    reg tgl;
    always @(posedge clk_core) begin
        if (!rst_n) tgl <= 1'b0;
        else if (pix_ce) tgl <= ~tgl;
    end

    wire [7:0] pairs;
    wire out_of_step;
    tmds_serializer u_ser (
        .clk(clk_bit), .rst_n(rst_bit_n), .chars({q_r, q_g, q_b}), .load_tgl(tgl), .pairs(pairs),
        .out_of_step(out_of_step)
    );
    ulx3s_gpdi_pins u_pins (.clk_bit(clk_bit), .pairs(pairs), .gpdi_dp(gpdi_dp));

    wire blink = (MODE == 0 || MODE == 2) ? frame[0] : frame[5];
    assign led = {blink, 5'd0, out_of_step, late};
    wire unused_btn;
    assign unused_btn = &{1'b0, btn[6:1], frame};
endmodule
`default_nettype wire
