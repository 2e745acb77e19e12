// board_core_fb - the reference design around a frame buffer (docs/boards.md, "iCEBreaker"): the renderer
// draws the scene at half the display's size (FB_W x FB_H) into frame_store as fast as the shader allows (the
// UP5K's small spec_setup takes one span at a time, far too slow to race the beam), and the scanout shows the
// buffer pixel-doubled at the display's rate. The same raster, span finder, shader passes, light and colour
// as board_core, except that the colour is made after the write queue by compose_seq (one channel at a time, no
// multiplier: the UP5K's DSPs are the shader's); the light moves with every *rendered* frame.
//
// One clock domain; pix_ce marks the pixel clock's cycles: every cycle (the iCEBreaker: clk is the pixel
// clock) or every other cycle (the ULX3S at 640 x 480: clk at twice the pixel rate). The scanout shows a group
// of 4 buffer pixels (3 words) for 8 pixels: 8 or 16 clocks, against a fetch's 5 (frame_store) or 5
// (frame_store_packed) clocks. Rendering frame r: light_gen computes frame r's light; at the start of the next displayed frame the
// renderer starts at buffer line 0 and, while that displayed frame is still being scanned, rewrites buffer
// line y only after the beam has shown it (display line 2y + 1): that displayed frame shows frame r - 1
// whole. Each line is cleared to the background first (one command), then its sub-spans' pixels are written.
// Later displayed frames show the lines done so far from frame r and the rest from r - 1 (one buffer, no
// second one fits: docs/boards.md). frame counts rendered frames (its bit 0 changes as a frame starts).
// error: sticky, the write queue overflowed (the design is sized so that it does not).
// Reset: rst_n synchronous, active low: raster in the vertical front porch, frame 0 next, error cleared.
`timescale 1ns / 1ps
`default_nettype none
module board_core_fb #(
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
    parameter [11:0] BG_RGB = 12'h111,
    parameter N_OBJ = 5,
    parameter SPLIT_K = 8,
    parameter SCENE_FILE = "",         // the frame buffer's scene (half the display's size)
    parameter SPLIT_FILE = "",
    parameter OBJ_FILE = "",
    parameter SHADE_FILE = "",
    parameter LIGHT_FILE = "",
    parameter LIGHT_BRAM = 1,          // light_gen's TABLE_BRAM: its table in a block RAM, or in logic
    parameter COS_E = 12551,
    parameter COS_HALF_E = 15396,
    parameter MUL_STEPS = 1,
    parameter SQRT_STEPS = 1,
    parameter SPANS_SERIAL = 0,        // sphere_spans' SERIAL: 1 = one token in its stages at a time (fewer cells)
    parameter SHADER_SMALL = 1,
    parameter SHADER_BACKEND = 0,      // spec_shader's back end: 0 = spec_stream, 1 = spec_stream_seq
    parameter ROM9_FILE = "",
    parameter ROM12_FILE = "",
    parameter SETUP_DIR = "rom",       // the setups' tables and microcode (rom/setup_*.hex)
    // the frame store: 0 = frame_store (16-bit words, nibble write enables: the UP5K's SPRAM), 1 =
    // frame_store_packed (36-bit words of three pixels: the ECP5's block RAM); FIFO_LUTRAM: the queues in
    // distributed RAM (the ECP5-25F's block RAM is the frame store's)
    parameter STORE_PACKED = 0,
    parameter FIFO_LUTRAM = 0,
    parameter FIFO_QUEUE = 3,          // sync_fifo's QUEUE: 1 or 0 save the queues' output registers (0: the iCEBreaker)
    parameter META_AW = 8,             // shade_passes' sub-span queue: 1 keeps its 2 words in flip-flops, not a
                                       // block RAM (the shader holds a few sub-spans at a time)
    parameter PASSES_OUT_REG = 1,      // shade_passes' OUT_REG: 0 = its pixels straight into the write queue
    parameter COMPOSE_STEPS = 3,       // compose_seq's multiplier bits a clock (1, 3 or 9): 1 is the smallest
    parameter COMPOSE_HOLD = 0         // compose_seq's HOLD: 1 reads the write queue's head in place (no copy)
) (
    input  wire        clk,
    input  wire        rst_n,
    input  wire        pix_ce,
    output reg  [11:0] rgb,
    output reg         hsync,
    output reg         vsync,
    output reg         de,
    output reg         error,
    output reg  [7:0]  frame
);
    localparam X_W = 11;
    localparam Y_W = 10;
    localparam OBJ_W = 3;
    localparam FB_W = H_ACTIVE / 2;
    localparam FB_H = V_ACTIVE / 2;
    localparam H_TOTAL = H_ACTIVE + H_FP + H_SYNC + H_BP;
    localparam V_TOTAL = V_ACTIVE + V_FP + V_SYNC + V_BP;
    localparam P_W = $clog2(FB_W * FB_H);
    localparam integer GW = FB_W / 4;
    localparam integer LAST_Y = FB_H - 1;

    // ---- raster --------------------------------------------------------------------------------------------
    wire [X_W-1:0] h;
    wire [Y_W-1:0] v;
    wire t_hs, t_vs, t_de;
    video_timing #(
        .H_ACTIVE(H_ACTIVE), .H_FP(H_FP), .H_SYNC(H_SYNC), .H_BP(H_BP), .V_ACTIVE(V_ACTIVE), .V_FP(V_FP),
        .V_SYNC(V_SYNC), .V_BP(V_BP), .H_POL(H_POL), .V_POL(V_POL), .X_W(X_W), .Y_W(Y_W)
    ) u_timing (
        .clk(clk), .rst_n(rst_n), .ce(pix_ce), .h(h), .v(v), .hsync(t_hs), .vsync(t_vs), .de(t_de)
    );
    wire line_ev = pix_ce && (h == {X_W{1'b0}});

    // ---- renderer ------------------------------------------------------------------------------------------
    wire signed [15:0] l_x, l_y, l_z, h_x, h_y, h_z;
    wire light_busy;
    reg light_go;
    light_gen #(
        .COS_E(COS_E), .COS_HALF_E(COS_HALF_E), .LIGHT_FILE(LIGHT_FILE), .TABLE_BRAM(LIGHT_BRAM)
    ) u_light (
        .clk(clk), .rst_n(rst_n), .start(light_go), .f(frame), .busy(light_busy),
        .l_x(l_x), .l_y(l_y), .l_z(l_z), .h_x(h_x), .h_y(h_y), .h_z(h_z)
    );

    localparam R_LIGHT = 3'd0, R_LIGHT_W = 3'd1, R_WAITF = 3'd2, R_LINE = 3'd3, R_SPANS = 3'd4, R_NEXT = 3'd5;
    reg [2:0] rs;
    reg [Y_W-1:0] y;                   // buffer line being rendered
    reg [Y_W:0] y2p2;                  // 2y + 2: the display line the beam must have reached
    reg in_start;                      // still in the displayed frame this rendered frame began in
    reg sp_start;
    wire sp_busy, sp_valid, sp_ready;
    wire [OBJ_W-1:0] sp_obj;
    wire [X_W-1:0] sp_x0;
    wire [9:0] sp_l;
    wire [47:0] sp_n1, sp_n2;
    reg [9:0] outstanding;             // sub-spans taken by the shader whose last pixel is not yet queued
    wire cmd_ready, cmd_ready_fs;
    reg clr_push;
    wire beam_past = !in_start || ({1'b0, v} >= y2p2);

    always @(posedge clk) begin
        light_go <= 1'b0;
        sp_start <= 1'b0;
        clr_push <= 1'b0;
        if (line_ev && v == V_ACTIVE[Y_W-1:0]) in_start <= 1'b0;
        if (!rst_n) begin
            rs <= R_LIGHT;
            frame <= 8'd0;
            in_start <= 1'b0;
        end else begin
            case (rs)
                R_LIGHT: begin
                    light_go <= 1'b1;
                    rs <= R_LIGHT_W;
                end
                R_LIGHT_W: if (!light_go && !light_busy) rs <= R_WAITF;
                R_WAITF: if (line_ev && v == {Y_W{1'b0}}) begin
                    in_start <= 1'b1;
                    y <= {Y_W{1'b0}};
                    y2p2 <= {{(Y_W - 1) {1'b0}}, 2'd2};
                    rs <= R_LINE;
                end
                R_LINE: if (beam_past && cmd_ready && !clr_push) begin
                    clr_push <= 1'b1;          // clear the line, then find its spans
                    sp_start <= 1'b1;
                    rs <= R_SPANS;
                end
                R_SPANS: if (!sp_start && !sp_busy && outstanding == 10'd0 && !sp_valid) rs <= R_NEXT;
                R_NEXT: begin
                    if (y == LAST_Y[Y_W-1:0]) begin
                        frame <= frame + 8'd1;
                        rs <= R_LIGHT;
                    end else begin
                        y <= y + {{(Y_W - 1) {1'b0}}, 1'b1};
                        y2p2 <= y2p2 + {{(Y_W - 1) {1'b0}}, 2'd2};
                        rs <= R_LINE;
                    end
                end
                default: rs <= R_LIGHT;
            endcase
        end
    end

    sphere_spans #(
        .N_OBJ(N_OBJ), .OBJ_W(OBJ_W), .K(SPLIT_K), .ZF(5), .X_W(X_W), .Y_W(Y_W), .MUL_STEPS(MUL_STEPS),
        .SQRT_STEPS(SQRT_STEPS), .SERIAL(SPANS_SERIAL), .SCENE_FILE(SCENE_FILE), .SPLIT_FILE(SPLIT_FILE)
    ) u_spans (
        .clk(clk), .rst_n(rst_n), .start(sp_start), .y(y), .busy(sp_busy), .m_valid(sp_valid),
        .m_ready(sp_ready), .m_obj(sp_obj), .m_x0(sp_x0), .m_l(sp_l), .m_n1(sp_n1), .m_n2(sp_n2)
    );
    wire px_valid, px_last;
    wire [OBJ_W-1:0] px_obj;
    wire [X_W-1:0] px_x;
    wire [15:0] px_dif, px_spc;
    shade_passes #(
        .N_OBJ(N_OBJ), .OBJ_W(OBJ_W), .X_W(X_W), .SHADERS(1), .SMALL(SHADER_SMALL), .BACKEND(SHADER_BACKEND), .SHADE_FILE(SHADE_FILE), .FIFO_LUTRAM(FIFO_LUTRAM), .FIFO_QUEUE(FIFO_QUEUE), .META_AW(META_AW),
        .OUT_REG(PASSES_OUT_REG), .ROM9_FILE(ROM9_FILE), .ROM12_FILE(ROM12_FILE), .SETUP_DIR(SETUP_DIR)
    ) u_shade (
        .clk(clk), .rst_n(rst_n),
        .s_valid(sp_valid), .s_ready(sp_ready), .s_obj(sp_obj), .s_x0(sp_x0), .s_l(sp_l), .s_n1(sp_n1),
        .s_n2(sp_n2), .l_x(l_x), .l_y(l_y), .l_z(l_z), .h_x(h_x), .h_y(h_y), .h_z(h_z),
        .m_valid(px_valid), .m_obj(px_obj), .m_x(px_x), .m_dif(px_dif), .m_spc(px_spc), .m_last(px_last)
    );
    // the colour is made after the write queue, one channel at a time (compose_seq: no multiplier), at the
    // frame store's pace; the queue holds the shader's pixels
    // for the board simulation's report: the longest time a frame took to render, in clocks (synthesis
    // removes it: nothing reads it)
    reg [25:0] frame_clocks, frame_clocks_max /*verilator public_flat_rd*/;
    always @(posedge clk) begin
        if (!rst_n) begin
            frame_clocks <= 26'd0;
            frame_clocks_max <= 26'd0;
        end else if (rs == R_WAITF && line_ev && v == {Y_W{1'b0}}) begin
            frame_clocks <= 26'd1;
        end else if (rs == R_NEXT && y == LAST_Y[Y_W-1:0]) begin
            if (frame_clocks > frame_clocks_max) frame_clocks_max <= frame_clocks;
        end else if (frame_clocks != 26'd0 && frame_clocks != 26'h3ffffff) begin
            frame_clocks <= frame_clocks + 26'd1;
        end
    end
    always @(posedge clk) begin
        if (!rst_n) outstanding <= 10'd0;
        else outstanding <= outstanding + {9'd0, sp_valid & sp_ready} - {9'd0, px_valid & px_last};
    end

    // ---- write queue: the line's clear, then its pixels, in order; the colour; the frame store ----------------
    // A command carries the buffer line (clear) or the pixel's x (write), not the pixel's index: the frame
    // store's index is made after the queue, from the line of the last clear (a line's pixels follow its
    // clear, and the next clear waits for them: R_SPANS), so the queue is P_W - T_W bits narrower.
    localparam XB_W = $clog2(FB_W), YB_W = $clog2(FB_H);
    localparam T_W = (XB_W > YB_W) ? XB_W : YB_W;
    localparam CMD_W = 1 + T_W + OBJ_W + 32;
    wire q_ready, c_valid, c_ready, w_valid, w_clear;
    wire [CMD_W-1:0] c_data;
    wire [T_W-1:0] w_tag;
    wire [11:0] w_rgb;
    wire q_push = clr_push | px_valid;
    sync_fifo #(.W(CMD_W), .AW(8), .LUTRAM(FIFO_LUTRAM), .QUEUE(FIFO_QUEUE)) u_queue (
        .clk(clk), .rst_n(rst_n), .s_valid(q_push), .s_ready(q_ready),
        .s_data(clr_push ? {1'b1, y[T_W-1:0], {(OBJ_W + 32) {1'b0}}}      // y < FB_H, px_x < FB_W: the
                         : {1'b0, px_x[T_W-1:0], px_obj, px_dif, px_spc}),   // bits above T_W are 0
        .m_valid(c_valid), .m_ready(c_ready), .m_data(c_data)
    );
    always @(posedge clk) begin
        if (!rst_n) error <= 1'b0;
        else if (q_push && !q_ready) error <= 1'b1;
    end
    assign cmd_ready = q_ready;
    compose_seq #(.N_OBJ(N_OBJ), .OBJ_W(OBJ_W), .OUT_BITS(4), .TAG_W(T_W), .MUL_STEPS(COMPOSE_STEPS), .HOLD(COMPOSE_HOLD),
                  .OBJ_FILE(OBJ_FILE))
    u_compose (
        .clk(clk), .rst_n(rst_n), .s_valid(c_valid), .s_ready(c_ready), .s_bypass(c_data[CMD_W-1]),
        .s_tag(c_data[OBJ_W + 32 +: T_W]), .s_obj(c_data[32 +: OBJ_W]), .s_dif(c_data[31:16]),
        .s_spc(c_data[15:0]), .m_valid(w_valid), .m_ready(cmd_ready_fs), .m_bypass(w_clear), .m_tag(w_tag),
        .m_rgb(w_rgb)
    );

    // the store's argument: the line for a clear; y * FB_W + x for a write, y from the last clear taken
    function [P_W-1:0] times_fbw;      // line * FB_W by shifts and adds (a constant: no multiplier)
        input [T_W-1:0] line;
        integer b;
        begin
            times_fbw = {P_W{1'b0}};
            for (b = 0; b < P_W; b = b + 1)
                if (FB_W[b]) times_fbw = times_fbw + ({{(P_W - T_W) {1'b0}}, line} << b);
        end
    endfunction
    reg [P_W-1:0] store_base;          // the line of the last clear the store took, times FB_W
    always @(posedge clk) begin
        if (w_valid && cmd_ready_fs && w_clear) store_base <= times_fbw(w_tag);
    end
    wire [P_W-1:0] w_arg = w_clear ? {{(P_W - T_W) {1'b0}}, w_tag}
                                   : store_base + {{(P_W - T_W) {1'b0}}, w_tag};

    // ---- frame store and scanout ---------------------------------------------------------------------------
    reg fetch;
    reg [P_W-3:0] fetch_group;
    wire fetch_busy, group_valid;
    wire [47:0] group;
    generate
        if (STORE_PACKED != 0) begin : g_packed
            frame_store_packed #(.FB_W(FB_W), .FB_H(FB_H), .P_W(P_W), .BG_RGB(BG_RGB)) u_store (
                .clk(clk), .rst_n(rst_n), .cmd_valid(w_valid), .cmd_ready(cmd_ready_fs), .cmd_clear(w_clear),
                .cmd_arg(w_arg), .cmd_rgb(w_rgb), .fetch(fetch), .fetch_group(fetch_group),
                .fetch_busy(fetch_busy), .group(group), .group_valid(group_valid)
            );
        end else begin : g_nibbles
            frame_store #(.FB_W(FB_W), .FB_H(FB_H), .P_W(P_W), .BG_RGB(BG_RGB)) u_store (
                .clk(clk), .rst_n(rst_n), .cmd_valid(w_valid), .cmd_ready(cmd_ready_fs), .cmd_clear(w_clear),
                .cmd_arg(w_arg), .cmd_rgb(w_rgb), .fetch(fetch), .fetch_group(fetch_group),
                .fetch_busy(fetch_busy), .group(group), .group_valid(group_valid)
            );
        end
    endgenerate
    // the next display line's buffer line, as a word offset (registered in two steps from v, which is stable
    // through a line). A display line's groups are fetched in order, base + 0 and base + 1 at the end of the line
    // before, base + 2 .. GW - 1 during it, so every fetch after the first is the last one's group + 1.
    reg [Y_W-1:0] next_line;
    reg [P_W-3:0] base_next;
    // line * GW by shifts and adds over GW's set bits (a constant: no multiplier, no DSP)
    function [P_W-3:0] times_gw;
        input [Y_W-1:0] line;
        integer b;
        begin
            times_gw = {(P_W - 2) {1'b0}};
            for (b = 0; b < P_W - 2; b = b + 1)
                if (GW[b]) times_gw = times_gw + ({{(P_W - 2 - Y_W) {1'b0}}, line} << b);
        end
    endfunction
    reg next_active;                   // the next display line shows the buffer
    always @(posedge clk) begin
        next_line <= (v >= V_ACTIVE[Y_W-1:0] - 1'b1) ? {Y_W{1'b0}} : (v + 1'b1) >> 1;
        base_next <= times_gw(next_line);
        next_active <= (v < V_ACTIVE[Y_W-1:0] - 1'b1) || (v == V_TOTAL[Y_W-1:0] - 1'b1);
    end
    // cur: the group being shown. The next group is the store's own group register: a fetch is issued at a group
    // boundary, its words land in group well before the next boundary (reads go first), and group holds them
    // until the fetch issued there writes it again, a few clocks after cur took it (no copy in between)
    reg [47:0] cur;
    wire [X_W-4:0] g_here = h[X_W-1:3];
    wire [X_W-4:0] g_fetch = g_here + {{(X_W - 5) {1'b0}}, 2'd2};   // the group two ahead
    localparam [X_W-4:0] GW_G = GW[X_W-4:0];
    always @(posedge clk) begin
        fetch <= 1'b0;
        if (pix_ce) begin
            if (h == H_ACTIVE[X_W-1:0] && next_active) begin
                fetch <= 1'b1;
                fetch_group <= base_next;
            end
            if (h == H_TOTAL[X_W-1:0] - 1'b1) begin
                cur <= group;
                if (next_active) begin
                    fetch <= 1'b1;
                    fetch_group <= fetch_group + 1'b1;
                end
            end
            if (h < H_ACTIVE[X_W-1:0] && h[2:0] == 3'd7) begin
                cur <= group;
                if (v < V_ACTIVE[Y_W-1:0] && g_fetch < GW_G) begin
                    fetch <= 1'b1;
                    fetch_group <= fetch_group + 1'b1;
                end
            end
        end
    end
    wire [1:0] k = h[2:1];
    always @(posedge clk) begin
        if (!rst_n) begin
            hsync <= (H_POL == 0);
            vsync <= (V_POL == 0);
            de <= 1'b0;
            rgb <= 12'd0;
        end else if (pix_ce) begin
            hsync <= t_hs;
            vsync <= t_vs;
            de <= t_de;
            rgb <= t_de ? {cur[4 * k +: 4], cur[16 + 4 * k +: 4], cur[32 + 4 * k +: 4]} : 12'd0;
        end
    end
    wire unused;
    assign unused = &{1'b0, group_valid, px_x[X_W-1:T_W]};
`ifndef SYNTHESIS
    // the scanout's fetches are far enough apart that the store has always finished the last one
    always @(posedge clk) begin
        if (rst_n && fetch && fetch_busy) begin
            $display("board_core_fb: a fetch while the frame store is still busy with the last (%m): an RTL bug");
            $fatal(1);
        end
    end
`endif
endmodule
`default_nettype wire
