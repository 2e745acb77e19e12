// video_timing - the raster of a video mode: horizontal and vertical counters, sync pulses and data enable.
//
// Counters: h = 0 .. H_TOTAL-1, v = 0 .. V_TOTAL-1; (h, v) = (0, 0) is the first active pixel, so the active
// area is h < H_ACTIVE, v < V_ACTIVE, followed by front porch, sync and back porch on each axis (VESA DMT,
// CTA-861). The counters advance once per clock with ce = 1 (the pixel clock enable; tie ce high when the
// clock is the pixel clock). hsync, vsync and de are registers that belong to the same (h, v) as the
// counters in the same cycle. vsync's edges coincide with hsync's leading edge: it is active from the hsync
// of line V_ACTIVE + V_FP - 1 to the hsync of line V_ACTIVE + V_FP + V_SYNC - 1, i.e. for the V_SYNC lines
// V_ACTIVE + V_FP .. counted from one hsync to the next. H_POL / V_POL = 1: the pulse is high (positive),
// 0: low (negative).
// Reset: rst_n is synchronous, active low; it puts the raster at (0, V_ACTIVE), the first line of the
// vertical front porch, so that V_FP + V_SYNC + V_BP blanking lines pass before the first active line.
`timescale 1ns / 1ps
`default_nettype none
module video_timing #(
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
    parameter X_W = 11,     // width of h: H_TOTAL must fit
    parameter Y_W = 10      // width of v: V_TOTAL must fit
) (
    input  wire           clk,
    input  wire           rst_n,
    input  wire           ce,
    output reg  [X_W-1:0] h,
    output reg  [Y_W-1:0] v,
    output reg            hsync,
    output reg            vsync,
    output reg            de
);
    localparam H_TOTAL = H_ACTIVE + H_FP + H_SYNC + H_BP;
    localparam V_TOTAL = V_ACTIVE + V_FP + V_SYNC + V_BP;
    localparam integer H_LAST_I = H_TOTAL - 1, V_LAST_I = V_TOTAL - 1;
    localparam integer HS_BEGIN_I = H_ACTIVE + H_FP, HS_END_I = H_ACTIVE + H_FP + H_SYNC;
    localparam integer VS_BEGIN_I = V_ACTIVE + V_FP, VS_END_I = V_ACTIVE + V_FP + V_SYNC;
    localparam [X_W-1:0] H_LAST = H_LAST_I[X_W-1:0];
    localparam [Y_W-1:0] V_LAST = V_LAST_I[Y_W-1:0];
    localparam [Y_W-1:0] V_ACT = V_ACTIVE[Y_W-1:0];

    // misconfiguration stops elaboration (every tool) and simulation (with a message)
    generate
        if (H_ACTIVE < 1 || H_FP < 1 || H_SYNC < 1 || H_BP < 1 || V_ACTIVE < 1 || V_FP < 1 || V_SYNC < 1
            || V_BP < 1 || H_TOTAL >= (1 << X_W) || V_TOTAL >= (1 << Y_W)) begin : g_bad_params
            initial begin
                $display("video_timing: every interval must be >= 1 and the totals must fit X_W / Y_W (%m)");
                $finish;
            end
            video_timing_parameters_out_of_range u_error ();
        end
    endgenerate

    // Every decision is an equality with a constant on the registered counters (no magnitude compares
    // chained after the increments): flags for "active column", "active line", hsync and vsync change at the
    // count before their boundary, in step with the counters.
    localparam integer H_ACT_LAST_I = H_ACTIVE - 1, V_ACT_LAST_I = V_ACTIVE - 1;
    localparam integer HS_ON_I = HS_BEGIN_I - 1, HS_OFF_I = HS_END_I - 1;
    localparam integer VS_ON_I = VS_BEGIN_I - 1, VS_OFF_I = VS_END_I - 1;
    localparam [X_W-1:0] H_ACT_LAST = H_ACT_LAST_I[X_W-1:0];
    localparam [Y_W-1:0] V_ACT_LAST = V_ACT_LAST_I[Y_W-1:0];
    localparam [X_W-1:0] HS_ON = HS_ON_I[X_W-1:0];
    localparam [X_W-1:0] HS_OFF = HS_OFF_I[X_W-1:0];
    localparam [Y_W-1:0] VS_ON = VS_ON_I[Y_W-1:0];
    localparam [Y_W-1:0] VS_OFF = VS_OFF_I[Y_W-1:0];
    reg h_act, v_act, hs_q, vs_q;      // for the current (h, v): h < H_ACTIVE, v < V_ACTIVE, syncs active
    wire h_wrap = (h == H_LAST);
    wire h_act_d = h_wrap ? 1'b1 : (h == H_ACT_LAST) ? 1'b0 : h_act;
    wire v_act_d = !h_wrap ? v_act : (v == V_LAST) ? 1'b1 : (v == V_ACT_LAST) ? 1'b0 : v_act;
    wire hs_d = (h == HS_ON) ? 1'b1 : (h == HS_OFF) ? 1'b0 : hs_q;
    // vsync switches with the hsync leading edge (CTA-861 and VESA DMT draw a line from one hsync to the
    // next): on at the hsync of line V_ACTIVE + V_FP - 1, off at the hsync of line V_ACTIVE + V_FP + V_SYNC - 1
    wire vs_d = (h != HS_ON) ? vs_q : (v == VS_ON) ? 1'b1 : (v == VS_OFF) ? 1'b0 : vs_q;

    always @(posedge clk) begin
        if (!rst_n) begin
            h <= {X_W{1'b0}};
            v <= V_ACT;
            h_act <= 1'b1;
            v_act <= 1'b0;
            hs_q <= 1'b0;
            vs_q <= 1'b0;
            hsync <= (H_POL == 0);
            vsync <= (V_POL == 0);
            de <= 1'b0;
        end else if (ce) begin
            h <= h_wrap ? {X_W{1'b0}} : h + {{(X_W - 1) {1'b0}}, 1'b1};
            if (h_wrap) v <= (v == V_LAST) ? {Y_W{1'b0}} : v + {{(Y_W - 1) {1'b0}}, 1'b1};
            h_act <= h_act_d;
            v_act <= v_act_d;
            hs_q <= hs_d;
            vs_q <= vs_d;
            hsync <= hs_d ^ (H_POL == 0);
            vsync <= vs_d ^ (V_POL == 0);
            de <= h_act_d & v_act_d;
        end
    end
endmodule
`default_nettype wire
