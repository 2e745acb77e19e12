// spec_mul13 - multiplier 13 ("first multiplier") of UA 71489 Fig. 1: C (register 1) x ROM 12 -> output 27.
// out = round(C * table / 2^SHIFT), 0 when `zero`. With OUT_W = C_W and SHIFT = TBL_FRAC, table = 1.0
// gives C exactly and the result never exceeds 2^OUT_W - 1. The table's top bit (1.0) is only set when the
// rest is 0: then the result is C itself, otherwise C x (low TBL_DW-1 bits): one C_W x (TBL_DW-1) multiplier
// (a single 16x16 DSP block at the default widths). Requires OUT_W = C_W and SHIFT = TBL_DW - 1. Two pipeline stages: the product (registered when
// `ce`), then the rounding (the output register, written when `en`, so output 27 holds the last pixel
// between pixels; cleared by the synchronous reset).
`timescale 1ns / 1ps
`default_nettype none
module spec_mul13 #(
    parameter C_W = 16,
    parameter TBL_DW = 17,
    parameter OUT_W = 16,
    parameter SHIFT = 16
) (
    input  wire              clk,
    input  wire              rst,
    input  wire              ce,    // stage 1
    input  wire              en,    // stage 2 (the output register)
    input  wire [C_W-1:0]    c,
    input  wire [TBL_DW-1:0] value,
    input  wire              zero,
    output reg  [OUT_W-1:0]  out
);
    localparam PW = C_W + TBL_DW - 1;
    // stage 1: input registers (synthesis may pack them into the DSP block, so that whatever computes
    // `value` ends at ordinary flip-flops)
    reg [C_W-1:0] c0;
    reg [TBL_DW-1:0] v0;
    reg zero0;
    always @(posedge clk) begin
        if (ce) begin
            c0 <= c;
            v0 <= value;
            zero0 <= zero;
        end
    end
    // stage 2: the multiplier alone (the flags wait beside it)
    reg [PW-1:0] prod;
    reg one1, zero1;
    reg [C_W-1:0] c1;
    always @(posedge clk) begin
        if (ce) begin
            prod <= {{(TBL_DW - 1) {1'b0}}, c0} * {{C_W{1'b0}}, v0[TBL_DW-2:0]};
            one1 <= v0[TBL_DW-1];     // 1.0: the product is C exactly (SHIFT = TBL_DW - 1)
            zero1 <= zero0;
            c1 <= c0;
        end
    end
    // stage 3: rounding and the two exact cases
    wire [PW-1:0] rounded = prod + ({{(PW - 1) {1'b0}}, 1'b1} << (SHIFT - 1));
    wire unused_bits;
    generate
        if (SHIFT + OUT_W < PW) begin : g_top
            assign unused_bits = &{1'b0, rounded[SHIFT-1:0], rounded[PW-1:SHIFT+OUT_W]};
        end else begin : g_notop
            assign unused_bits = &{1'b0, rounded[SHIFT-1:0]};
        end
    endgenerate

    always @(posedge clk) begin
        if (rst) out <= {OUT_W{1'b0}};
        else if (en) out <= zero1 ? {OUT_W{1'b0}} : one1 ? c1 : rounded[SHIFT+OUT_W-1:SHIFT];
    end
endmodule
`default_nettype wire
