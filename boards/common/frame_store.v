// frame_store - a frame buffer of FB_W x FB_H pixels, RGB444, in one single-port memory of 16-bit words with a
// write enable per 4-bit nibble (Yosys infers the iCE40 UP5K's SPRAM, SB_SPRAM256KA, with synth_ice40 -spram),
// shared by a writer (the renderer's commands) and a reader (the scanout's fetches, first in every cycle).
//
// Layout: three planes (red, green, blue) of FB_W * FB_H / 4 words each; pixel p's nibble of plane c is nibble
// p % 4 of word c * PLANE + p / 4. A fetch of group g reads the three words of pixels 4g .. 4g + 3.
// Commands (AXI4-Stream, one per beat): cmd_clear = 0: write cmd_rgb ({r, g, b}) to pixel cmd_arg (three
// nibble writes); cmd_clear = 1: write the background BG_RGB to the FB_W pixels of line cmd_arg (whole
// words). Commands are applied in order, in cycles the reader does not need. A command is read where it is,
// not copied (the writer holds no command register): it is taken (cmd_ready) in the clock of its last write,
// and AXI4-Stream keeps it stable until then. cmd_ready therefore depends on the reader, not on cmd_valid.
// Fetch: fetch (with fetch_group, a word index within a plane) while fetch_busy = 0; the three words arrive
// in group (and group_valid pulses) a few cycles later: reads take the memory ahead of writes.
// Reset: rst_n is synchronous, active low: idle. The memory is not cleared (the renderer writes every
// pixel of a frame).
`timescale 1ns / 1ps
`default_nettype none
module frame_store #(
    parameter FB_W = 320,
    parameter FB_H = 240,
    parameter P_W = 17,                // pixel index width
    parameter [11:0] BG_RGB = 12'h111
) (
    input  wire           clk,
    input  wire           rst_n,
    input  wire           cmd_valid,
    output wire           cmd_ready,
    input  wire           cmd_clear,
    input  wire [P_W-1:0] cmd_arg,     // pixel index y * FB_W + x, or the line for cmd_clear
    input  wire [11:0]    cmd_rgb,
    input  wire           fetch,
    input  wire [P_W-3:0] fetch_group,
    output reg            fetch_busy,
    output reg  [47:0]    group,       // {blue word, green word, red word}
    output reg            group_valid
);
    localparam PLANE = FB_W * FB_H / 4;
    localparam WORDS = 3 * PLANE;
    localparam A_W = $clog2(WORDS);
    localparam integer GW = FB_W / 4;  // words per line and plane

    generate
        if ((FB_W % 4) != 0 || FB_W * FB_H > (1 << P_W)) begin : g_bad_params
            initial begin
                $display("frame_store: FB_W must be a multiple of 4 and FB_W * FB_H must fit P_W (%m)");
                $finish;
            end
            frame_store_parameters_out_of_range u_error ();
        end
    endgenerate

    reg [15:0] mem[0:WORDS-1];
    reg [A_W-1:0] addr;
    reg we;
    reg [3:0] mask;
    reg [15:0] wdata;
    reg [15:0] rdata;
    always @(posedge clk) begin
        if (we) begin
            if (mask[0]) mem[addr][3:0] <= wdata[3:0];
            if (mask[1]) mem[addr][7:4] <= wdata[7:4];
            if (mask[2]) mem[addr][11:8] <= wdata[11:8];
            if (mask[3]) mem[addr][15:12] <= wdata[15:12];
        end else begin
            rdata <= mem[addr];
        end
    end

    // ---- the reader: three reads per fetch, ahead of the writer -------------------------------------------
    reg [1:0] rd_n;                    // reads left to issue (3, 2, 1)
    reg [A_W-1:0] rd_addr;             // the next read's address
    reg [1:0] rd_got;                  // words received
    reg rd_pend;                       // a read was issued last cycle (its word is in rdata now)
    wire reading = (rd_n != 2'd0);

    // ---- the writer ---------------------------------------------------------------------------------------
    reg w_busy;                        // the command at the input is being written (w_plane, w_word, w_left set)
    wire w_clear = cmd_clear;
    reg [1:0] w_plane;
    reg [A_W-1:0] w_word;              // word within the plane
    wire [1:0] w_nib = cmd_arg[1:0];
    wire [11:0] w_rgb = cmd_rgb;
    reg [$clog2(GW + 1)-1:0] w_left;   // clear: words left in this plane's line
    wire w_more = w_clear && w_left != {{($clog2(GW + 1) - 1) {1'b0}}, 1'b1};   // more words in this plane
    // the command's last write is this clock: it is taken
    assign cmd_ready = w_busy && !reading && !w_more && w_plane == 2'd2;
    localparam L_W = $clog2(FB_H);
    localparam [A_W-1:0] GW_A = GW[A_W-1:0];
    // the line's first word: line * GW by shifts and adds over GW's set bits (a constant: no DSP)
    function [A_W-1:0] times_gw;
        input [L_W-1:0] line;
        integer b;
        begin
            times_gw = {A_W{1'b0}};
            for (b = 0; b < A_W; b = b + 1)
                if (GW_A[b]) times_gw = times_gw + ({{(A_W - L_W) {1'b0}}, line} << b);
        end
    endfunction
    wire [A_W-1:0] line_word0 = times_gw(cmd_arg[L_W-1:0]);
    wire [3:0] w_color = (w_plane == 2'd0) ? w_rgb[11:8] : (w_plane == 2'd1) ? w_rgb[7:4] : w_rgb[3:0];
    wire [3:0] bg_color = (w_plane == 2'd0) ? BG_RGB[11:8] : (w_plane == 2'd1) ? BG_RGB[7:4] : BG_RGB[3:0];
    wire [A_W-1:0] plane_base = (w_plane == 2'd0) ? {A_W{1'b0}} : (w_plane == 2'd1) ? PLANE[A_W-1:0] :
                                                                                      PLANE[A_W-1:0] << 1;

    always @(*) begin
        we = 1'b0;
        addr = rd_addr;
        mask = 4'd0;
        wdata = {4{w_clear ? bg_color : w_color}};
        if (!reading && w_busy) begin
            we = 1'b1;
            addr = plane_base + w_word;
            mask = w_clear ? 4'hf : (4'd1 << w_nib);
        end
    end

    always @(posedge clk) begin
        if (!rst_n) begin
            rd_n <= 2'd0;
            rd_pend <= 1'b0;
            fetch_busy <= 1'b0;
            group_valid <= 1'b0;
            w_busy <= 1'b0;
        end else begin
            group_valid <= 1'b0;
            // reader
            rd_pend <= reading;
            if (fetch && !fetch_busy) begin
                fetch_busy <= 1'b1;
                rd_n <= 2'd3;
                rd_got <= 2'd0;
                rd_addr <= {{(A_W - P_W + 2) {1'b0}}, fetch_group};
            end else if (reading) begin
                rd_n <= rd_n - 2'd1;
                rd_addr <= rd_addr + PLANE[A_W-1:0];
            end
            if (rd_pend) begin
                group[16 * rd_got +: 16] <= rdata;
                rd_got <= rd_got + 2'd1;
                if (rd_got == 2'd2) begin
                    group_valid <= 1'b1;
                    fetch_busy <= 1'b0;
                end
            end
            // writer
            if (!w_busy) begin
                if (cmd_valid) begin
                    w_busy <= 1'b1;
                    w_plane <= 2'd0;
                    w_word <= cmd_clear ? line_word0 : {{(A_W - P_W + 2) {1'b0}}, cmd_arg[P_W-1:2]};
                    w_left <= GW[$clog2(GW + 1)-1:0];
                end
            end else if (!reading) begin
                // one nibble (pixel) or one word (clear) written this cycle
                if (w_more) begin
                    w_left <= w_left - 1'b1;
                    w_word <= w_word + 1'b1;
                end else if (w_plane != 2'd2) begin
                    w_plane <= w_plane + 2'd1;
                    w_left <= GW[$clog2(GW + 1)-1:0];
                    if (w_clear) w_word <= line_word0;
                end else begin
                    w_busy <= 1'b0;
                end
            end
        end
    end
endmodule
`default_nettype wire
