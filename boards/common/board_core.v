// board_core - everything of a reference design that is not board-specific (docs/boards.md): the raster,
// the per-frame light, the renderer that races the beam one line ahead, and the scanout from two line
// buffers. Out come registered colour, sync and data-enable signals at the pixel rate, for the board's
// output stage (a DVI transmitter chip on the iCEBreaker's Pmod, TMDS encoders on the ULX3S).
//
// One clock domain. pix_ce marks the pixel clock's cycles: tie it high when clk is the pixel clock (the ULX3S
// at 1280 x 720), or give it every other cycle when clk runs at twice the pixel rate (the renderer gets two
// clocks per pixel). Per line (H_TOTAL pixels): at the line's first pixel the renderer starts on the next line
// (v + 1, or line 0 during the last blanking line), into one bank; at the line's last pixel the banks swap,
// so that the scanout reads the freshly rendered line from the next line's first pixel on. Per frame: at the first blanking line the frame number f advances and light_gen
// computes the frame's light (L, H), used from line 0 on.
// Outputs: rgb/hsync/vsync/de belong together, one pixel (pix_ce cycle) after the raster's counters.
// late: sticky, set when a line's rendering had not finished when the line was due (the line then shows a
// partly rendered line; the design is sized so that it does not happen: docs/boards.md, "Time per line").
// Reset: rst_n is synchronous, active low: raster at the first line of the vertical front porch, frame
// counter such that the first frame shown is frame 0, late cleared.
`timescale 1ns / 1ps
`default_nettype none
module board_core #(
    // raster (video_timing)
    parameter H_ACTIVE = 640,
    parameter H_FP = 16,
    parameter H_SYNC = 96,
    parameter H_BP = 48,
    parameter V_ACTIVE = 480,
    parameter V_FP = 10,
    parameter V_SYNC = 2,
    parameter V_BP = 33,
    parameter H_POL = 0,
    parameter V_POL = 0,
    // pixels
    parameter OUT_BITS = 8,            // bits per channel in the line buffer and at the output
    parameter [3*OUT_BITS-1:0] BG_RGB = 0,
    // scene (boardgen's tables, boards/common/gen/)
    parameter N_OBJ = 5,
    parameter SPLIT_K = 16,
    parameter SCENE_FILE = "",
    parameter SPLIT_FILE = "",
    parameter OBJ_FILE = "",
    parameter SHADE_FILE = "",
    parameter LIGHT_FILE = "",
    parameter LIGHT_BRAM = 1,          // light_gen's TABLE_BRAM: its table in a block RAM, or in logic
    parameter COS_E = 12551,
    parameter COS_HALF_E = 15396,
    // renderer
    parameter MUL_STEPS = 1,
    parameter SQRT_STEPS = 1,
    parameter SHADERS = 1,             // 1: both passes through one shader; 2: one shader per pass
    parameter SHADER_SMALL = 1,        // spec_shader's configuration: 1 = up5k (the small CORDIC setup), 0 = ecp5 (the multiplier setup)
    parameter SHADER_BACKEND = 0,      // spec_shader's back end: 0 = spec_stream, 1 = spec_stream_seq
    parameter ROM9_FILE = "",
    parameter ROM12_FILE = "",
    parameter SETUP_DIR = "rom"        // the setups' tables and microcode (rom/setup_*.hex)
) (
    input  wire                  clk,
    input  wire                  rst_n,
    input  wire                  pix_ce,
    output reg  [3*OUT_BITS-1:0] rgb,
    output reg                   hsync,
    output reg                   vsync,
    output reg                   de,
    output reg                   late,
    output reg  [7:0]            frame
);
    localparam X_W = 11;
    localparam Y_W = 10;
    localparam OBJ_W = 3;
    localparam H_TOTAL = H_ACTIVE + H_FP + H_SYNC + H_BP;
    localparam V_TOTAL = V_ACTIVE + V_FP + V_SYNC + V_BP;
    localparam LB_AW = (H_ACTIVE > 1024) ? 11 : 10;

    // ---- raster ------------------------------------------------------------------------------------------
    wire [X_W-1:0] h;
    wire [Y_W-1:0] v;
    wire t_hs, t_vs, t_de;
    video_timing #(
        .H_ACTIVE(H_ACTIVE), .H_FP(H_FP), .H_SYNC(H_SYNC), .H_BP(H_BP), .V_ACTIVE(V_ACTIVE), .V_FP(V_FP),
        .V_SYNC(V_SYNC), .V_BP(V_BP), .H_POL(H_POL), .V_POL(V_POL), .X_W(X_W), .Y_W(Y_W)
    ) u_timing (
        .clk(clk), .rst_n(rst_n), .ce(pix_ce), .h(h), .v(v), .hsync(t_hs), .vsync(t_vs), .de(t_de)
    );
    wire line_ev = pix_ce && (h == {X_W{1'b0}});                       // a line begins
    wire swap_ev = pix_ce && (h == H_TOTAL[X_W-1:0] - 1'b1);           // a line ends: the banks swap
    wire frame_ev = line_ev && (v == V_ACTIVE[Y_W-1:0]);
    // which line to render during line v: prepared during the line before (from the stable v, for the line
    // v + 1 that follows), taken over as the line ends; after reset, line V_ACTIVE renders nothing
    localparam [Y_W-1:0] V_ACT_M2 = V_ACTIVE - 2;
    localparam [Y_W-1:0] V_TOT_M2 = V_TOTAL - 2;
    localparam [Y_W-1:0] V_TOT_M1 = V_TOTAL - 1;
    reg nxt_this, render_this;
    reg [Y_W-1:0] nxt_y, render_y;
    always @(posedge clk) begin
        nxt_this <= (v < V_ACT_M2) || (v >= V_TOT_M2);
        nxt_y <= (v == V_TOT_M2) ? {Y_W{1'b0}} : (v == V_TOT_M1) ? {{(Y_W - 1) {1'b0}}, 1'b1} :
                 v + {{(Y_W - 2) {1'b0}}, 2'd2};
        if (!rst_n) render_this <= 1'b0;
        else if (swap_ev) render_this <= nxt_this;
        if (swap_ev) render_y <= nxt_y;
    end
    wire render_ev = line_ev && render_this;

    reg render_bank;
    always @(posedge clk) begin
        if (!rst_n) render_bank <= 1'b0;
        else if (swap_ev) render_bank <= ~render_bank;
    end

    // ---- the frame's light -------------------------------------------------------------------------------
    wire signed [15:0] l_x, l_y, l_z, h_x, h_y, h_z;
    wire light_busy;
    always @(posedge clk) begin
        if (!rst_n) frame <= 8'hff;
        else if (frame_ev) frame <= frame + 8'd1;
    end
    reg light_go;
    always @(posedge clk) light_go <= rst_n & frame_ev;
    light_gen #(
        .COS_E(COS_E), .COS_HALF_E(COS_HALF_E), .LIGHT_FILE(LIGHT_FILE), .TABLE_BRAM(LIGHT_BRAM)
    ) u_light (
        .clk(clk), .rst_n(rst_n), .start(light_go), .f(frame), .busy(light_busy),
        .l_x(l_x), .l_y(l_y), .l_z(l_z), .h_x(h_x), .h_y(h_y), .h_z(h_z)
    );

    // ---- renderer: spans -> shader passes -> colour -> line buffer -----------------------------------------
    wire sp_busy, sp_valid, sp_ready;
    wire [OBJ_W-1:0] sp_obj;
    wire [X_W-1:0] sp_x0;
    wire [9:0] sp_l;
    wire [47:0] sp_n1, sp_n2;
    sphere_spans #(
        .N_OBJ(N_OBJ), .OBJ_W(OBJ_W), .K(SPLIT_K), .ZF(5), .X_W(X_W), .Y_W(Y_W), .MUL_STEPS(MUL_STEPS),
        .SQRT_STEPS(SQRT_STEPS), .SCENE_FILE(SCENE_FILE), .SPLIT_FILE(SPLIT_FILE)
    ) u_spans (
        .clk(clk), .rst_n(rst_n), .start(render_ev), .y(render_y), .busy(sp_busy), .m_valid(sp_valid),
        .m_ready(sp_ready), .m_obj(sp_obj), .m_x0(sp_x0), .m_l(sp_l), .m_n1(sp_n1), .m_n2(sp_n2)
    );

    wire px_valid, px_last;
    wire [OBJ_W-1:0] px_obj;
    wire [X_W-1:0] px_x;
    wire [15:0] px_dif, px_spc;
    shade_passes #(
        .N_OBJ(N_OBJ), .OBJ_W(OBJ_W), .X_W(X_W), .SHADERS(SHADERS), .SMALL(SHADER_SMALL),
        .BACKEND(SHADER_BACKEND),
        .SHADE_FILE(SHADE_FILE), .ROM9_FILE(ROM9_FILE), .ROM12_FILE(ROM12_FILE), .SETUP_DIR(SETUP_DIR)
    ) u_shade (
        .clk(clk), .rst_n(rst_n),
        .s_valid(sp_valid), .s_ready(sp_ready), .s_obj(sp_obj), .s_x0(sp_x0), .s_l(sp_l), .s_n1(sp_n1),
        .s_n2(sp_n2), .l_x(l_x), .l_y(l_y), .l_z(l_z), .h_x(h_x), .h_y(h_y), .h_z(h_z),
        .m_valid(px_valid), .m_obj(px_obj), .m_x(px_x), .m_dif(px_dif), .m_spc(px_spc), .m_last(px_last)
    );

    wire wr_valid, wr_last;
    wire [X_W-1:0] wr_x;
    wire [3*OUT_BITS-1:0] wr_rgb;
    compose #(.N_OBJ(N_OBJ), .OBJ_W(OBJ_W), .X_W(X_W), .OUT_BITS(OUT_BITS), .OBJ_FILE(OBJ_FILE)) u_compose (
        .clk(clk), .rst_n(rst_n), .in_valid(px_valid), .in_obj(px_obj), .in_x(px_x), .in_dif(px_dif),
        .in_spc(px_spc), .in_last(px_last), .out_valid(wr_valid), .out_last(wr_last), .out_x(wr_x),
        .out_rgb(wr_rgb)
    );

    // sub-spans accepted by the shader but not yet written: the line is done when none is left
    reg [9:0] outstanding;
    wire span_in = sp_valid & sp_ready;
    wire span_out = wr_valid & wr_last;
    always @(posedge clk) begin
        if (!rst_n) outstanding <= 10'd0;
        else outstanding <= outstanding + {9'd0, span_in} - {9'd0, span_out};
    end
    wire rendering = sp_busy | (outstanding != 10'd0) | span_in;
    always @(posedge clk) begin
        if (!rst_n) late <= 1'b0;
        else if (swap_ev && rendering) late <= 1'b1;
    end
    // for the board simulation's report (docs/boards.md, "Time per line"): the longest time a line took, in
    // clocks from its start to its last pixel written (not connected to pins: synthesis removes it)
    reg [12:0] render_clocks;
    reg [12:0] render_clocks_max /*verilator public_flat_rd*/;
    always @(posedge clk) begin
        if (!rst_n) begin
            render_clocks <= 13'd0;
            render_clocks_max <= 13'd0;
        end else begin
            if (render_ev) render_clocks <= 13'd1;
            else if (rendering && render_clocks != 13'h1fff) render_clocks <= render_clocks + 13'd1;
            if (!rendering && render_clocks > render_clocks_max) render_clocks_max <= render_clocks;
        end
    end

    // ---- line buffers and scanout ------------------------------------------------------------------------
    reg rd_q;                          // a pixel was read at the last pix_ce
    reg [LB_AW-1:0] rd_addr_q;
    wire rd_en = pix_ce && (h < H_ACTIVE[X_W-1:0]);
    wire [3*OUT_BITS-1:0] rd_data;
    line_buffer #(.W(3 * OUT_BITS), .DEPTH(H_ACTIVE), .AW(LB_AW)) u_lines (
        .clk(clk), .render_bank(render_bank), .wr_en(wr_valid), .wr_addr(wr_x[LB_AW-1:0]), .wr_data(wr_rgb),
        .rd_en(rd_en), .rd_addr(h[LB_AW-1:0]), .rd_data(rd_data),
        .clr_en(pix_ce & rd_q), .clr_addr(rd_addr_q), .clr_data(BG_RGB)
    );
    reg hs_q, vs_q, de_q;
    always @(posedge clk) begin
        if (!rst_n) begin
            rd_q <= 1'b0;
            hs_q <= (H_POL == 0);
            vs_q <= (V_POL == 0);
            de_q <= 1'b0;
            hsync <= (H_POL == 0);
            vsync <= (V_POL == 0);
            de <= 1'b0;
            rgb <= {(3 * OUT_BITS) {1'b0}};
        end else if (pix_ce) begin
            rd_q <= rd_en;
            rd_addr_q <= h[LB_AW-1:0];
            hs_q <= t_hs;
            vs_q <= t_vs;
            de_q <= t_de;
            hsync <= hs_q;
            vsync <= vs_q;
            de <= de_q;
            rgb <= de_q ? rd_data : {(3 * OUT_BITS) {1'b0}};
        end
    end
    wire unused;
    generate
        if (LB_AW < X_W) begin : g_wr_x_high                           // the line buffer's address is narrower
            assign unused = &{1'b0, light_busy, wr_x[X_W-1:LB_AW]};
        end else begin : g_wr_x_all                                    // 1280 wide: every bit addresses the buffer
            assign unused = &{1'b0, light_busy};
        end
    endgenerate
endmodule
`default_nettype wire
