// frame_store_packed - frame_store's interface and behaviour (a frame buffer of FB_W x FB_H pixels, RGB444,
// a writer's commands and a reader's fetches of 4-pixel groups) on a memory of 36-bit words, three pixels a
// word, for block RAM that has no 4-bit write enables (the ECP5's DP16KD in its 512 x 36 mode: 320 x 240
// pixels take 25 600 words, 50 blocks, where 16-bit words with nibble enables would take 60 to 64).
//
// Layout: pixel p is bits 12 (p % 3) + 11 .. 12 (p % 3) of word p / 3, as {r, g, b}. Groups of four pixels
// straddle two words: a fetch of group g reads words 4g / 3 and 4g / 3 + 1 and returns frame_store's group
// layout ({blue word, green word, red word}, nibble k of each the colour of pixel 4g + k).
// Commands: cmd_clear = 0: pixel cmd_arg := cmd_rgb; cmd_clear = 1: the FB_W pixels of line cmd_arg := BG_RGB.
// Each pixel is a read-modify-write of its word (a read, then a write of the whole word); a line clear is FB_W
// of them. One memory access a cycle (no read and write of the same word at the same edge): the reader's
// reads first, the writer in the cycles left. Commands are applied in order.
// Division by 3 (p / 3, 4g / 3): p * 43691 >> 17, exact for p < 2^17 (a multiplier).
// Reset: rst_n is synchronous, active low: idle. The memory is not cleared (the renderer writes every pixel).
`timescale 1ns / 1ps
`default_nettype none
module frame_store_packed #(
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
    localparam WORDS = FB_W * FB_H / 3;
    localparam A_W = $clog2(WORDS);

    generate
        if ((FB_W % 4) != 0 || ((FB_W * FB_H) % 3) != 0 || P_W > 17 || FB_W * FB_H > (1 << P_W)) begin : g_bad
            initial begin
                $display("frame_store_packed: FB_W must be a multiple of 4, FB_W * FB_H of 3, P_W <= 17 (%m)");
                $finish;
            end
            frame_store_packed_parameters_out_of_range u_error ();
        end
    endgenerate

    reg [35:0] mem[0:WORDS-1];
    reg [A_W-1:0] addr;
    reg we;
    reg [35:0] wdata;
    reg [35:0] rdata;
    always @(posedge clk) begin
        if (we) mem[addr] <= wdata;
        else rdata <= mem[addr];
    end

    // ---- the reader: two reads per fetch, ahead of the writer ---------------------------------------------
    reg [1:0] rd_n;                    // reads left to issue (2, 1)
    reg rd_div;                        // the fetch's word index is being computed
    reg [16:0] rd_pix;                 // 4g
    reg [A_W-1:0] rd_addr;
    reg [1:0] rd_off;                  // 4g % 3
    reg rd_pend, rd_got;
    reg [35:0] rd_w0;
    wire reading = (rd_n != 2'd0);
    wire [33:0] rd_prod = {17'd0, rd_pix} * 34'd43691;     // rd_pix / 3 = rd_prod >> 17
    wire [16:0] rd_quo = rd_prod[33:17];
    wire [16:0] rd_rem = rd_pix - (rd_quo + rd_quo + rd_quo);
    wire [A_W+1:0] rd_q = {rd_rem[1:0], rd_quo[A_W-1:0]};
    wire [71:0] pair = {rdata, rd_w0};
    wire [47:0] quad = pair[12 * rd_off +: 48];   // pixels 4g .. 4g + 3, 12 bits each

    // ---- the writer: a run of pixels (1, or FB_W for a clear), each read, then written --------------------
    localparam L_W = $clog2(FB_H);
    localparam C_W = $clog2(FB_W + 1);
    reg w_busy, w_div, w_rd, w_pend, w_wr;
    reg [16:0] w_pix;
    reg [A_W-1:0] w_word;
    reg [1:0] w_off;
    reg [C_W-1:0] w_left;              // pixels left in the run, this one included
    reg [11:0] w_rgb;
    reg [35:0] w_data;                 // the word read
    wire [33:0] w_prod = {17'd0, w_pix} * 34'd43691;
    wire [16:0] w_quo = w_prod[33:17];
    wire [16:0] w_rem = w_pix - (w_quo + w_quo + w_quo);
    wire [A_W+1:0] w_q = {w_rem[1:0], w_quo[A_W-1:0]};
    assign cmd_ready = !w_busy;
    wire [35:0] merged = (w_off == 2'd0) ? {w_data[35:12], w_rgb} :
                         (w_off == 2'd1) ? {w_data[35:24], w_rgb, w_data[11:0]} : {w_rgb, w_data[23:0]};

    always @(*) begin
        we = 1'b0;
        addr = rd_addr;
        wdata = merged;
        if (!reading && w_busy && (w_rd || w_wr)) begin
            addr = w_word;
            we = w_wr;
        end
    end

    // the fetch's first pixel and the command's pixel, 17 bits (one spare bit: no zero-width padding)
    wire [17:0] grp_pix = {{(18 - P_W) {1'b0}}, fetch_group, 2'b00};
    wire [17:0] cmd_pix = {{(18 - P_W) {1'b0}}, cmd_arg};
    wire unused_pad = &{1'b0, grp_pix[17], cmd_pix[17], rd_prod[16:0], w_prod[16:0], rd_rem[16:2], w_rem[16:2],
                        rd_quo[16:A_W], w_quo[16:A_W]};
    integer k;
    always @(posedge clk) begin
        if (!rst_n) begin
            rd_n <= 2'd0;
            rd_div <= 1'b0;
            rd_pend <= 1'b0;
            fetch_busy <= 1'b0;
            group_valid <= 1'b0;
            w_busy <= 1'b0;
            w_div <= 1'b0;
            w_rd <= 1'b0;
            w_pend <= 1'b0;
            w_wr <= 1'b0;
        end else begin
            group_valid <= 1'b0;
            // reader
            rd_pend <= reading;
            if (fetch && !fetch_busy) begin
                fetch_busy <= 1'b1;
                rd_div <= 1'b1;
                rd_got <= 1'b0;
                rd_pix <= grp_pix[16:0];
            end
            if (rd_div) begin
                rd_div <= 1'b0;
                rd_addr <= rd_q[A_W-1:0];
                rd_off <= rd_q[A_W+1:A_W];
                rd_n <= 2'd2;
            end else if (reading) begin
                rd_n <= rd_n - 2'd1;
                rd_addr <= rd_addr + 1'b1;
            end
            if (rd_pend) begin
                rd_got <= 1'b1;
                if (!rd_got) begin
                    rd_w0 <= rdata;
                end else begin
                    for (k = 0; k < 4; k = k + 1) begin
                        group[4 * k +: 4] <= quad[12 * k + 8 +: 4];
                        group[16 + 4 * k +: 4] <= quad[12 * k + 4 +: 4];
                        group[32 + 4 * k +: 4] <= quad[12 * k +: 4];
                    end
                    group_valid <= 1'b1;
                    fetch_busy <= 1'b0;
                end
            end
            // writer
            w_pend <= !reading && w_busy && w_rd;
            if (!w_busy) begin
                if (cmd_valid) begin
                    w_busy <= 1'b1;
                    w_div <= 1'b1;
                    w_rgb <= cmd_clear ? BG_RGB : cmd_rgb;
                    w_pix <= cmd_clear ? cmd_arg[L_W-1:0] * FB_W[16:0] : cmd_pix[16:0];
                    w_left <= cmd_clear ? FB_W[C_W-1:0] : {{(C_W - 1) {1'b0}}, 1'b1};
                end
            end else if (w_div) begin
                w_div <= 1'b0;
                w_word <= w_q[A_W-1:0];
                w_off <= w_q[A_W+1:A_W];
                w_rd <= 1'b1;
            end else if (w_rd) begin
                if (!reading) w_rd <= 1'b0;            // the read is issued this cycle
            end else if (w_pend) begin
                w_data <= rdata;
                w_wr <= 1'b1;
            end else if (w_wr && !reading) begin     // the write is issued this cycle
                w_wr <= 1'b0;
                if (w_left == {{(C_W - 1) {1'b0}}, 1'b1}) begin
                    w_busy <= 1'b0;
                end else begin
                    w_left <= w_left - 1'b1;
                    w_rd <= 1'b1;
                    if (w_off == 2'd2) begin
                        w_off <= 2'd0;
                        w_word <= w_word + 1'b1;
                    end else begin
                        w_off <= w_off + 2'd1;
                    end
                end
            end
        end
    end
endmodule
`default_nettype wire
