// spec_setup_exp2 - register 1's code round(2^(C_W - p / 2^LF)) for p > 0, pipelined (LAT = 4 clocks):
//   1  p = i + f (integer and fraction); table reads of words j and j + 1 (j the top TB bits of f)
//   2  (the words arrive; word 2^TB is 2^(EF-1), a constant)
//   3  (word j - word j+1) * r, r the next RB bits of f
//   4  2^-f = word j - round(product / 2^RB), rounded to C_W - i fraction bits; 0 when i > C_W + 1;
//      at most 2^C_W - 1
// The table is rom/setup_exp2.hex (setuprom): word j = round(2^(-j/2^TB) * 2^EF). The caller handles p <= 0
// (C >= 1: saturation). Bit for bit SetupModel::c_code.
`timescale 1ns / 1ps
`default_nettype none
`include "setup_params.vh"
`include "spec_params.vh"
module spec_setup_exp2 #(
    parameter PW = 48,                   // width of p (only p > 0 is used)
    parameter C_W = `SPEC_C_W,
    parameter LF = `SETUP_LF,
    parameter EF = `SETUP_EF,
    parameter TB = `SETUP_TB,
    parameter RB = `SETUP_RB,
    parameter TABLE_FILE = `SETUP_EXP2_FILE
) (
    input  wire           clk,
    input  wire [PW-1:0]  p,
    output reg  [C_W-1:0] code
);
    wire [PW-LF-1:0] pi = p[PW-1:LF];
    wire [TB-1:0] j = p[LF-1 -: TB];
    wire [RB-1:0] r = p[LF-TB-1 -: RB];
    wire unused_p;
    assign unused_p = &{1'b0, p[LF-TB-RB-1:0]};
    // 1: read
    reg [RB-1:0] r1, r2;
    reg last1;
    reg big1, big2, big3;              // i > C_W + 1: the code is 0
    reg [4:0] s1, s2, s3;              // i (when not big)
    always @(posedge clk) begin
        r1 <= r;
        last1 <= &j;
        big1 <= pi > C_W + 1;
        s1 <= pi[4:0];
    end
    wire [EF:0] w0, w1;
    spec_rom #(.AW(TB), .DW(EF + 1), .INIT_FILE(TABLE_FILE)) u_t0 (.clk(clk), .en(1'b1), .addr(j), .data(w0));
    spec_rom #(.AW(TB), .DW(EF + 1), .INIT_FILE(TABLE_FILE)) u_t1 (.clk(clk), .en(1'b1), .addr(j + 1'b1), .data(w1));
    // 2: the words
    reg [EF:0] e0, e1;
    always @(posedge clk) begin
        r2 <= r1;
        big2 <= big1;
        s2 <= s1;
        e0 <= w0;
        e1 <= last1 ? (1 << (EF - 1)) : w1;
    end
    // 3: interpolation product
    wire [EF:0] ediff = e0 - e1;
    reg [EF+RB:0] p3;
    reg [EF:0] e3;
    always @(posedge clk) begin
        big3 <= big2;
        s3 <= s2;
        e3 <= e0;
        p3 <= ediff * r2;
    end
    // 4: the value and its code
    localparam [EF+RB:0] HALF_R = 1 << (RB - 1);
    wire [EF+RB:0] p3r = p3 + HALF_R;
    wire [EF:0] ev = e3 - p3r[EF+RB:RB];
    wire unused_p3r;
    assign unused_p3r = &{1'b0, p3r[RB-1:0]};
    wire [5:0] sh = EF - C_W + {1'b0, s3};                // >= EF - C_W >= 1
    wire [EF+1:0] rounded = ({1'b0, ev} + ({{(EF + 1) {1'b0}}, 1'b1} << (sh - 1))) >> sh;
    always @(posedge clk) begin
        if (big3) code <= {C_W{1'b0}};
        else if (rounded > {{(EF + 2 - C_W) {1'b0}}, {C_W{1'b1}}}) code <= {C_W{1'b1}};
        else code <= rounded[C_W-1:0];
    end
endmodule
`default_nettype wire
