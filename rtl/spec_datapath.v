// spec_datapath - the pixel datapath after register 8, shared by spec_unit and spec_stream:
// multiplier 11 -> ROM 12 (table chosen by decoder 10) -> [interpolator, INTERP = 1] -> multiplier 13.
// Every stage is registered and advances when `ce` is 1 (a stall holds everything, including ROM 12's read
// register). Each pixel carries its own C, scale, table and `last` flag, so consecutive pixels may belong to
// different spans. Latency from the input to `out`: LAT = 4 clocks (5 with INTERP = 1) of `ce`.
`timescale 1ns / 1ps
`default_nettype none
module spec_datapath #(
    parameter C_W = 16,
    parameter ANG_W = 32,
    parameter ANG_FRAC = 28,
    parameter OUT_W = 16,
    parameter SCALE_W = 18,
    parameter SCALE_FRAC = 15,
    parameter TBL_AW = 12,
    parameter TBL_FRAC = 16,
    parameter INTERP = 0,
    parameter INTERP_FRAC = 10,
    parameter DELTA_W = 10,
    parameter ROM12_FILE = ""
) (
    input  wire               clk,
    input  wire               rst,        // synchronous: clears the valid flags and the output
    input  wire               ce,
    input  wire               in_valid,
    input  wire               in_last,
    input  wire [ANG_W-1:0]   angle,      // register 8
    input  wire [SCALE_W-1:0] scale,      // ROM 9
    input  wire [1:0]         table_sel,  // decoder 10
    input  wire [C_W-1:0]     c,          // register 1
    output wire [OUT_W-1:0]   out,        // output 27
    output wire               out_valid,
    output wire               out_last,
    output wire               busy        // a pixel is somewhere in the pipeline
);
    localparam TBL_DW = TBL_FRAC + 1;
    localparam WORD_W = TBL_DW + ((INTERP != 0) ? DELTA_W : 0);
    localparam FRAC_W = (INTERP != 0) ? INTERP_FRAC : 1;

    // side band: s1 = multiplier 11's partial products, s2 = its position, s3 = ROM 12's read register
    reg v1, v2, v3, l1, l2, l3;
    reg [C_W-1:0] c1, c2, c3;
    reg [1:0] t1, t2;
    reg zero3;
    reg [FRAC_W-1:0] frac3;
    always @(posedge clk) begin
        if (rst) begin
            v1 <= 1'b0;
            v2 <= 1'b0;
            v3 <= 1'b0;
        end else if (ce) begin
            v1 <= in_valid;
            v2 <= v1;
            v3 <= v2;
        end
        if (ce) begin
            l1 <= in_last;   l2 <= l1;   l3 <= l2;
            c1 <= c;         c2 <= c1;   c3 <= c2;
            t1 <= table_sel; t2 <= t1;
        end
    end

    // multiplier 11 (two stages)
    wire [TBL_AW-1:0] index11;
    wire [FRAC_W-1:0] frac11;
    wire zero11;
    spec_mul11 #(
        .ANG_W(ANG_W), .SCALE_W(SCALE_W), .PROD_FRAC(ANG_FRAC + SCALE_FRAC), .TBL_AW(TBL_AW),
        .INTERP(INTERP), .INTERP_FRAC(INTERP_FRAC)
    ) u_mul11 (
        .clk(clk), .ce(ce), .angle(angle), .scale(scale), .index(index11), .frac(frac11), .zero(zero11)
    );

    // ROM 12 (the zero flag and the fraction travel beside its read register)
    wire [WORD_W-1:0] word12;
    always @(posedge clk) begin
        if (ce) begin
            zero3 <= zero11;
            frac3 <= frac11;
        end
    end
    spec_rom12 #(.TBL_AW(TBL_AW), .WORD_W(WORD_W), .INIT_FILE(ROM12_FILE)) u_rom12 (
        .clk(clk), .en(ce), .table_sel(t2), .index(index11), .value(word12)
    );

    // interpolator (INTERP = 1) or the plain table value
    wire [TBL_DW-1:0] value_m;
    wire zero_m, v_m, l_m;
    wire [C_W-1:0] c_m;
    generate
        if (INTERP != 0) begin : g_interp
            reg v4, l4, zero4;
            reg [C_W-1:0] c4;
            always @(posedge clk) begin
                if (rst) v4 <= 1'b0;
                else if (ce) v4 <= v3;
                if (ce) begin
                    l4 <= l3;
                    zero4 <= zero3;
                    c4 <= c3;
                end
            end
            spec_interp #(.TBL_DW(TBL_DW), .DELTA_W(DELTA_W), .INTERP_FRAC(INTERP_FRAC)) u_interp (
                .clk(clk), .ce(ce), .word(word12), .frac(frac3), .value(value_m)
            );
            assign zero_m = zero4;
            assign v_m = v4;
            assign l_m = l4;
            assign c_m = c4;
        end else begin : g_plain
            wire unused_frac;
            assign unused_frac = &{1'b0, frac3};
            assign value_m = word12;
            assign zero_m = zero3;
            assign v_m = v3;
            assign l_m = l3;
            assign c_m = c3;
        end
    endgenerate

    // multiplier 13 -> output 27
    reg vo, lo;
    always @(posedge clk) begin
        if (rst) vo <= 1'b0;
        else if (ce) vo <= v_m;
        if (ce) lo <= l_m;
    end
    spec_mul13 #(.C_W(C_W), .TBL_DW(TBL_DW), .OUT_W(OUT_W), .SHIFT(C_W + TBL_FRAC - OUT_W)) u_mul13 (
        .clk(clk), .rst(rst), .en(ce & v_m), .c(c_m), .value(value_m), .zero(zero_m), .out(out)
    );
    assign out_valid = vo;
    assign out_last = lo;
    assign busy = v1 | v2 | v3 | v_m | vo;
endmodule
`default_nettype wire
