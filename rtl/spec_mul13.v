// spec_mul13 - multiplier 13 ("first multiplier") of UA 71489 Fig. 1: C (register 1) x ROM 12 -> output 27.
// out = round(C * table / 2^SHIFT) (half up), 0 when `zero`. With OUT_W = C_W and SHIFT = TBL_FRAC, table = 1.0
// gives C exactly and the result never exceeds 2^OUT_W - 1. The table's top bit (1.0) is only set when the
// rest is 0: then the result is C itself, otherwise C x (low TBL_DW-1 bits): one C_W x (TBL_DW-1) multiplier
// (a single 16x16 DSP block at the default widths). Requires OUT_W = C_W and SHIFT = TBL_DW - 1.
// Three pipeline stages (four with DSP_FF = 1: a copy of stage 2 in ordinary flip-flops after it):
//   1  input registers: the multiplier's operands in registers that feed nothing else (synthesis packs them
//      into the DSP block's input registers), the flags and a copy of C beside them;
//   2  the product (the DSP block's output register);
//   3  rounding, (prod >> SHIFT) + prod[SHIFT-1] - an OUT_W-bit increment - or C for the table's 1.0 (the
//      operands chosen before), 0 when `zero`: the output register, written when `en`, so output 27 holds
//      the last pixel between pixels; cleared by the synchronous reset.
`timescale 1ns / 1ps
`default_nettype none
module spec_mul13 #(
    parameter C_W = 16,
    parameter TBL_DW = 17,
    parameter OUT_W = 16,
    parameter SHIFT = 16,
    parameter DSP_FF = 0   // 1: a register stage after the DSP block's output (spec_stream)
) (
    input  wire              clk,
    input  wire              rst,
    input  wire              ce,    // stages 1 and 2
    input  wire              en,    // stage 3 (the output register)
    input  wire [C_W-1:0]    c,
    input  wire [TBL_DW-1:0] value,
    input  wire              zero,
    output reg  [OUT_W-1:0]  out
);
    localparam PW = C_W + TBL_DW - 1;
    // stage 1
    reg [C_W-1:0] c0, c0_copy;
    reg [TBL_DW-2:0] v0;
    reg one0, zero0;
    always @(posedge clk) begin
        if (ce) begin
            c0 <= c;
            v0 <= value[TBL_DW-2:0];
            one0 <= value[TBL_DW-1];   // 1.0: the product is C exactly (SHIFT = TBL_DW - 1)
            zero0 <= zero;
            c0_copy <= c;
        end
    end
    // stage 2: the multiplier alone (the flags wait beside it)
    reg [PW-1:0] prod_d;
    reg one_d, zero_d;
    reg [C_W-1:0] c_d;
    always @(posedge clk) begin
        if (ce) begin
            prod_d <= {{(TBL_DW - 1) {1'b0}}, c0} * {{C_W{1'b0}}, v0};
            one_d <= one0;
            zero_d <= zero0;
            c_d <= c0_copy;
        end
    end
    // the adder's operands: C itself for the table's 1.0 (plus 0), else prod >> SHIFT plus prod[SHIFT-1]; chosen
    // before the DSP_FF register, so that stage 3 is one carry chain whose result the output register takes
    // (zero is its synchronous clear)
    wire [OUT_W-1:0] op_d = one_d ? c_d : prod_d[SHIFT+OUT_W-1:SHIFT];
    wire rnd_d = ~one_d & prod_d[SHIFT-1];
    wire [OUT_W-1:0] op1;
    wire rnd1, zero1;
    spec_delay #(.W(OUT_W + 2), .N((DSP_FF != 0) ? 1 : 0)) u_dsp_ff (
        .clk(clk), .ce(ce), .d({op_d, rnd_d, zero_d}), .q({op1, rnd1, zero1})
    );
    // stage 3: rounding and the two exact cases; prod < 2^PW - 2^(SHIFT+1), so the increment never wraps
    wire [OUT_W-1:0] rounded;
    wire rounded_co;
    spec_add #(.W(OUT_W), .CO(0)) u_round (
        .a(op1), .b({OUT_W{1'b0}}), .cin(rnd1), .p(zero1), .sum(rounded), .cout(rounded_co)
    );
    wire unused_bits;
    generate
        if (SHIFT + OUT_W < PW) begin : g_top
            assign unused_bits = &{1'b0, rounded_co, prod_d[SHIFT-2:0], prod_d[PW-1:SHIFT+OUT_W]};
        end else begin : g_notop
            assign unused_bits = &{1'b0, rounded_co, prod_d[SHIFT-2:0]};
        end
    endgenerate

    always @(posedge clk) begin
        if (rst) out <= {OUT_W{1'b0}};
        else if (en) out <= zero1 ? {OUT_W{1'b0}} : rounded;
    end
endmodule
`default_nettype wire
