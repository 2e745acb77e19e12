// line_buffer - two line memories that take turns: while the scanout reads one (the display bank), the
// renderer writes the next line into the other. The scanout clears each pixel to the background after
// reading it, through the display bank's write port (unused by the renderer then), so every line starts
// from the background without a separate clearing pass. Each bank: DEPTH x W, one write and one registered
// read port (block RAM).
// Addresses must be below DEPTH (the line's width).
// Ports: render writes go to bank render_bank; scanout reads and clears the other bank. Read data is valid
// the cycle after rd_en and held until the next rd_en.
// No reset: the contents are defined by the clearing (docs/boards.md: the raster starts in the vertical
// blanking, whose lines clear both banks before the first line is shown).
`timescale 1ns / 1ps
`default_nettype none
module line_buffer #(
    parameter W = 24,
    parameter DEPTH = 640,
    parameter AW = 10
) (
    input  wire          clk,
    input  wire          render_bank,  // the bank the renderer writes; the scanout uses the other
    input  wire          wr_en,        // renderer
    input  wire [AW-1:0] wr_addr,
    input  wire [W-1:0]  wr_data,
    input  wire          rd_en,        // scanout
    input  wire [AW-1:0] rd_addr,
    output wire [W-1:0]  rd_data,
    input  wire          clr_en,       // scanout: write clr_data at clr_addr in the display bank
    input  wire [AW-1:0] clr_addr,
    input  wire [W-1:0]  clr_data
);
    reg [W-1:0] bank0[0:DEPTH-1];
    reg [W-1:0] bank1[0:DEPTH-1];
    reg [W-1:0] q0, q1;
    reg sel;                           // the bank read last

    wire we0 = render_bank ? clr_en : wr_en;
    wire [AW-1:0] wa0 = render_bank ? clr_addr : wr_addr;
    wire [W-1:0] wd0 = render_bank ? clr_data : wr_data;
    wire we1 = render_bank ? wr_en : clr_en;
    wire [AW-1:0] wa1 = render_bank ? wr_addr : clr_addr;
    wire [W-1:0] wd1 = render_bank ? wr_data : clr_data;

    always @(posedge clk) begin
        if (we0) bank0[wa0] <= wd0;
        if (rd_en & render_bank) q0 <= bank0[rd_addr];
    end
    always @(posedge clk) begin
        if (we1) bank1[wa1] <= wd1;
        if (rd_en & ~render_bank) q1 <= bank1[rd_addr];
    end
    always @(posedge clk) if (rd_en) sel <= render_bank;
    assign rd_data = sel ? q0 : q1;
endmodule
`default_nettype wire
