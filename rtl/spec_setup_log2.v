// spec_setup_log2 - log2(x) * 2^LF for x > 0, pipelined (a new x every clock, LAT = 5 clocks):
//   1  leading one e of x
//   2  the TB + RB bits below it: table index j and position r; table reads of words j and j + 1
//   3  (the words arrive; word 2^TB is 2^LF, a constant)
//   4  (word j+1 - word j) * r
//   5  e * 2^LF + word j + round(product / 2^RB)
// The table is rom/setup_log2.hex (setuprom): word j = round(log2(1 + j/2^TB) * 2^LF). x = 0 gives garbage
// (the caller never uses it). Bit for bit SetupModel::log2_fixed.
`timescale 1ns / 1ps
`default_nettype none
`include "setup_params.vh"
module spec_setup_log2 #(
    parameter XW = `SETUP_F + 2,         // width of x (unsigned)
    parameter LW = `SETUP_LF + 6,        // width of the result (unsigned: x >= 1)
    parameter LF = `SETUP_LF,
    parameter TB = `SETUP_TB,
    parameter RB = `SETUP_RB,
    parameter TABLE_FILE = `SETUP_LOG2_FILE
) (
    input  wire          clk,
    input  wire [XW-1:0] x,
    output reg  [LW-1:0] y
);
    // 1: leading one
    reg [5:0] e1;
    reg [XW-1:0] x1;
    reg [5:0] e_c;
    integer k;
    always @* begin
        e_c = 6'd0;
        for (k = 0; k < XW; k = k + 1) if (x[k]) e_c = k[5:0];
    end
    always @(posedge clk) begin
        e1 <= e_c;
        x1 <= x;
    end
    // 2: normalize (leading one shifted out at bit XW), split into j and r; read the table
    wire [XW+TB+RB-1:0] xn = {x1, {(TB + RB) {1'b0}}} << (XW - 1 - e1);
    wire [TB-1:0] j = xn[XW+TB+RB-2 -: TB];
    wire [RB-1:0] r = xn[XW+RB-2 -: RB];
    wire unused_xn;
    assign unused_xn = &{1'b0, xn[XW+TB+RB-1], xn[XW-2:0]};
    reg [5:0] e2, e3, e4;
    reg [RB-1:0] r2, r3;
    reg last2;
    always @(posedge clk) begin
        e2 <= e1;
        r2 <= r;
        last2 <= &j;   // j = 2^TB - 1: word j + 1 is the constant 2^LF
    end
    wire [LF-1:0] w0, w1;
    spec_rom #(.AW(TB), .DW(LF), .INIT_FILE(TABLE_FILE)) u_t0 (.clk(clk), .en(1'b1), .addr(j), .data(w0));
    spec_rom #(.AW(TB), .DW(LF), .INIT_FILE(TABLE_FILE)) u_t1 (.clk(clk), .en(1'b1), .addr(j + 1'b1), .data(w1));
    // 3: the words
    reg [LF:0] t0, t1;
    always @(posedge clk) begin
        e3 <= e2;
        r3 <= r2;
        t0 <= {1'b0, w0};
        t1 <= last2 ? (1 << LF) : {1'b0, w1};
    end
    // 4: interpolation product
    wire [LF:0] tdiff = t1 - t0;
    reg [LF+RB:0] p4;
    reg [LF:0] t4;
    always @(posedge clk) begin
        e4 <= e3;
        t4 <= t0;
        p4 <= tdiff * r3;
    end
    // 5: result
    localparam [LF+RB:0] HALF_R = 1 << (RB - 1);
    wire [LF+RB:0] p4r = p4 + HALF_R;
    wire unused_p4r;
    assign unused_p4r = &{1'b0, p4r[RB-1:0]};
    always @(posedge clk) begin
        y <= {e4, {LF{1'b0}}} + {{(LW - LF - 1) {1'b0}}, t4} + {{(LW - LF - 1) {1'b0}}, p4r[LF+RB:RB]};
    end
endmodule
`default_nettype wire
