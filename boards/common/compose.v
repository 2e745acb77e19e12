// compose - one pixel's colour from its diffuse and specular terms (docs/boards.md, "Colour"):
//
//   e = min(1, ka + dif)                       (ambient + Lambert, both already scaled: dif = kd Is max(0, N.L))
//   s_c = min(1, e * Cd_c + spc)               (spc = ks Is max(0, N.H)^n; white light and specular colour)
//   out_c = round(s_c * (2^OUT_BITS - 1))      per channel c = r, g, b
//
// in integers: dif, spc, ka UQ0.16; Cd_c UQ1.8 (256 = 1.0); e * Cd_c >> 8 truncated; the sums saturate at
// 65535; out_c = (s_c * (2^OUT_BITS - 1) + 32768) >> 16. Per-object constants from OBJ_FILE (one word per
// object: {ka[15:0], cd_r[8:0], cd_g[8:0], cd_b[8:0]}).
// Pipeline: 3 stages, no backpressure (the line buffer always takes a pixel): out_valid follows in_valid
// three clocks later with its x.
// Reset: rst_n is synchronous, active low: no output.
`timescale 1ns / 1ps
`default_nettype none
module compose #(
    parameter N_OBJ = 5,
    parameter OBJ_W = 3,
    parameter X_W = 11,
    parameter OUT_BITS = 8,
    parameter OBJ_FILE = ""
) (
    input  wire                  clk,
    input  wire                  rst_n,
    input  wire                  in_valid,
    input  wire [OBJ_W-1:0]      in_obj,
    input  wire [X_W-1:0]        in_x,
    input  wire [15:0]           in_dif,
    input  wire [15:0]           in_spc,
    input  wire                  in_last,    // carried along (the last pixel of a sub-span)
    output reg                   out_valid,
    output reg                   out_last,
    output reg  [X_W-1:0]        out_x,
    output reg  [3*OUT_BITS-1:0] out_rgb     // {r, g, b}
);
    generate
        if (OUT_BITS < 1 || OUT_BITS > 8 || N_OBJ < 1 || N_OBJ > (1 << OBJ_W)) begin : g_bad_params
            initial begin
                $display("compose: OUT_BITS must be 1..8 and N_OBJ must fit OBJ_W (%m)");
                $finish;
            end
            compose_parameters_out_of_range u_error ();
        end
    endgenerate

    reg [42:0] consts[0:N_OBJ-1];
    initial $readmemh(OBJ_FILE, consts);
    wire [42:0] k = consts[in_obj];

    // stage 1: e = ka + dif, saturated; the colour and spc travel along
    reg v1, last1, last2;
    reg [X_W-1:0] x1;
    reg [15:0] e1, spc1;
    reg [26:0] cd1;
    wire [16:0] e_sum = {1'b0, k[42:27]} + {1'b0, in_dif};
    // stage 2: e * Cd_c (16 x 9 bits) >> 8, plus spc, saturated
    reg v2;
    reg [X_W-1:0] x2;
    reg [15:0] s2[0:2];
    wire [24:0] prod_r = e1 * cd1[26:18];
    wire [24:0] prod_g = e1 * cd1[17:9];
    wire [24:0] prod_b = e1 * cd1[8:0];
    wire [17:0] sum_r = {1'b0, prod_r[24:8]} + {2'b00, spc1};
    wire [17:0] sum_g = {1'b0, prod_g[24:8]} + {2'b00, spc1};
    wire [17:0] sum_b = {1'b0, prod_b[24:8]} + {2'b00, spc1};
    wire unused_prod;
    assign unused_prod = &{1'b0, prod_r[7:0], prod_g[7:0], prod_b[7:0]};

    function [15:0] sat16;
        input [17:0] v;
        sat16 = (v[17:16] != 2'b00) ? 16'hffff : v[15:0];
    endfunction
    // out = (s * (2^OUT_BITS - 1) + 2^15) >> 16, per channel
    wire [OUT_BITS+15:0] t_r = ({{OUT_BITS{1'b0}}, s2[0]} << OUT_BITS) - {{OUT_BITS{1'b0}}, s2[0]}
                               + {{OUT_BITS{1'b0}}, 16'h8000};
    wire [OUT_BITS+15:0] t_g = ({{OUT_BITS{1'b0}}, s2[1]} << OUT_BITS) - {{OUT_BITS{1'b0}}, s2[1]}
                               + {{OUT_BITS{1'b0}}, 16'h8000};
    wire [OUT_BITS+15:0] t_b = ({{OUT_BITS{1'b0}}, s2[2]} << OUT_BITS) - {{OUT_BITS{1'b0}}, s2[2]}
                               + {{OUT_BITS{1'b0}}, 16'h8000};
    wire unused_low;
    assign unused_low = &{1'b0, t_r[15:0], t_g[15:0], t_b[15:0]};

    always @(posedge clk) begin
        if (!rst_n) begin
            v1 <= 1'b0;
            v2 <= 1'b0;
            out_valid <= 1'b0;
        end else begin
            v1 <= in_valid;
            v2 <= v1;
            out_valid <= v2;
        end
        x1 <= in_x;
        last1 <= in_last;
        last2 <= last1;
        out_last <= last2;
        e1 <= e_sum[16] ? 16'hffff : e_sum[15:0];
        spc1 <= in_spc;
        cd1 <= k[26:0];
        x2 <= x1;
        s2[0] <= sat16(sum_r);
        s2[1] <= sat16(sum_g);
        s2[2] <= sat16(sum_b);
        out_x <= x2;
        out_rgb <= {t_r[OUT_BITS+15:16], t_g[OUT_BITS+15:16], t_b[OUT_BITS+15:16]};
    end
endmodule
`default_nettype wire
