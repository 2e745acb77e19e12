// parallax_step - one iteration step of the iterative parallax mapping of the companion paper C
// (seeds/002, eq. 4-5; docs/methods.md):
//   hV_i    = hV_(i-1) + d_(i-1) * Vh        multiplication 1, addition 1 (saturating)
//   d_i     = h_i - hV_i                     addition 2 (saturating)
//   u_(i+1) = u_i + d_i * Vu                 multiplication 2, addition 3 (wrapping: the texture repeats)
//   v_(i+1) = v_i + d_i * Vv                 multiplication 3, addition 4 (wrapping)
// The three multiplications and four additions the paper counts; the products are truncated (arithmetic
// shift right by V_F, no rounding adder). h_i is the height map's sample at (u_i, v_i), fetched outside.
// Formats: u, v two's complement UV_W bits; h, hV, d two's complement H_W bits with the same fraction bits as
// u, v (heights in texture units); Vu, Vv, Vh two's complement V_W bits with V_F fraction bits.
// Seven pipeline stages, one step per clock: the outputs of a step presented with in_valid appear seven
// cycles later with out_valid (stage 1: the product d_(i-1) Vh; 2: the sum for hV_i; 3: its saturation;
// 4: h_i - hV_i; 5: its saturation, d_i; 6: the products d_i Vu, d_i Vv; 7: P_(i+1)). Each stage holds one
// multiplication, one carry chain or one saturation, for the iCE40's pixel clock; saturation detects the
// overflow from the sum's top bits instead of comparing. rst is synchronous
// and clears the valid flags only. Bit-exact model: spec::methods::step_fixed (sim/methods/parallax_fixed.cpp).
`timescale 1ns / 1ps
`default_nettype none
module parallax_step #(
    parameter UV_W = 24,
    parameter H_W = 16,
    parameter V_W = 16,
    parameter V_F = 14
) (
    input  wire            clk,
    input  wire            rst,
    input  wire            in_valid,
    input  wire [UV_W-1:0] u_i,
    input  wire [UV_W-1:0] v_i,
    input  wire [H_W-1:0]  h_i,
    input  wire [H_W-1:0]  hv_prev_i,
    input  wire [H_W-1:0]  d_prev_i,
    input  wire [V_W-1:0]  vu_i,
    input  wire [V_W-1:0]  vv_i,
    input  wire [V_W-1:0]  vh_i,
    output reg             out_valid,
    output reg  [UV_W-1:0] u_o,
    output reg  [UV_W-1:0] v_o,
    output reg  [H_W-1:0]  hv_o,
    output reg  [H_W-1:0]  d_o
);
    localparam PW = H_W + V_W;                        // a product
    localparam QW = PW - V_F;                         // a product shifted right by V_F
    localparam HSW = (QW > H_W ? QW : H_W) + 1;       // hV's sum: no wider than it must be (the carry chain)
    localparam USW = (QW > UV_W ? QW : UV_W) + 1;     // u's and v's sums

    // the valid flags of the seven stages
    reg [6:0] vld;
    always @(posedge clk) begin
        if (rst) vld <= 7'd0;
        else vld <= {vld[5:0], in_valid};
    end
    always @* out_valid = vld[6];

    // ---- stage 1: the product d_(i-1) Vh ----
    reg signed [PW-1:0] p1_1;
    reg [H_W-1:0]  h_1, hv_1;
    reg [UV_W-1:0] u_1, w_1;
    reg [V_W-1:0]  vu_1, vv_1;
    always @(posedge clk) begin
        p1_1 <= $signed(d_prev_i) * $signed(vh_i);
        h_1 <= h_i;
        hv_1 <= hv_prev_i;
        u_1 <= u_i;
        w_1 <= v_i;
        vu_1 <= vu_i;
        vv_1 <= vv_i;
    end

    // ---- stage 2: hV_(i-1) + d_(i-1) Vh ----
    wire signed [QW-1:0]  p1_s = p1_1[PW-1:V_F];  // the arithmetic shift right by V_F (floor)
    reg  signed [HSW-1:0] hs_2;
    reg [H_W-1:0]  h_2;
    reg [UV_W-1:0] u_2, w_2;
    reg [V_W-1:0]  vu_2, vv_2;
    always @(posedge clk) begin
        hs_2 <= {{(HSW - H_W) {hv_1[H_W-1]}}, hv_1} + {{(HSW - QW) {p1_s[QW-1]}}, p1_s};
        h_2 <= h_1;
        u_2 <= u_1;
        w_2 <= w_1;
        vu_2 <= vu_1;
        vv_2 <= vv_1;
    end

    // ---- stage 3: hV_i = sat(...), in range iff the bits from H_W - 1 up are all equal ----
    wire hv_in = &hs_2[HSW-1:H_W-1] | ~|hs_2[HSW-1:H_W-1];
    reg [H_W-1:0]  h_3, hv_3;
    reg [UV_W-1:0] u_3, w_3;
    reg [V_W-1:0]  vu_3, vv_3;
    always @(posedge clk) begin
        hv_3 <= hv_in ? hs_2[H_W-1:0] : {hs_2[HSW-1], {(H_W - 1) {~hs_2[HSW-1]}}};
        h_3 <= h_2;
        u_3 <= u_2;
        w_3 <= w_2;
        vu_3 <= vu_2;
        vv_3 <= vv_2;
    end

    // ---- stage 4: h_i - hV_i ----
    reg signed [H_W:0] ds_4;
    reg [H_W-1:0]  hv_4;
    reg [UV_W-1:0] u_4, w_4;
    reg [V_W-1:0]  vu_4, vv_4;
    always @(posedge clk) begin
        ds_4 <= {h_3[H_W-1], h_3} - {hv_3[H_W-1], hv_3};
        hv_4 <= hv_3;
        u_4 <= u_3;
        w_4 <= w_3;
        vu_4 <= vu_3;
        vv_4 <= vv_3;
    end

    // ---- stage 5: d_i = sat(...) ----
    wire d_in = ds_4[H_W] == ds_4[H_W-1];
    reg [H_W-1:0]  d_5, hv_5;
    reg [UV_W-1:0] u_5, w_5;
    reg [V_W-1:0]  vu_5, vv_5;
    always @(posedge clk) begin
        d_5 <= d_in ? ds_4[H_W-1:0] : {ds_4[H_W], {(H_W - 1) {~ds_4[H_W]}}};
        hv_5 <= hv_4;
        u_5 <= u_4;
        w_5 <= w_4;
        vu_5 <= vu_4;
        vv_5 <= vv_4;
    end

    // ---- stage 6: the products d_i Vu, d_i Vv ----
    reg signed [PW-1:0] p2_6, p3_6;
    reg [H_W-1:0]  d_6, hv_6;
    reg [UV_W-1:0] u_6, w_6;
    always @(posedge clk) begin
        p2_6 <= $signed(d_5) * $signed(vu_5);
        p3_6 <= $signed(d_5) * $signed(vv_5);
        d_6 <= d_5;
        hv_6 <= hv_5;
        u_6 <= u_5;
        w_6 <= w_5;
    end

    // ---- stage 7: P_(i+1) = P_i + d_i V(u, v), wrapping ----
    wire signed [QW-1:0]  p2_s = p2_6[PW-1:V_F];
    wire signed [QW-1:0]  p3_s = p3_6[PW-1:V_F];
    wire signed [USW-1:0] u_sum = {{(USW - UV_W) {u_6[UV_W-1]}}, u_6} + {{(USW - QW) {p2_s[QW-1]}}, p2_s};
    wire signed [USW-1:0] v_sum = {{(USW - UV_W) {w_6[UV_W-1]}}, w_6} + {{(USW - QW) {p3_s[QW-1]}}, p3_s};
    always @(posedge clk) begin
        u_o <= u_sum[UV_W-1:0];
        v_o <= v_sum[UV_W-1:0];
        hv_o <= hv_6;
        d_o <= d_6;
    end

    // the bits above each result: wrapped away; the products' bits below V_F: truncated
    wire unused_bits = &{1'b0, u_sum[USW-1:UV_W], v_sum[USW-1:UV_W], p1_1[V_F-1:0], p2_6[V_F-1:0], p3_6[V_F-1:0]};
endmodule
`default_nettype wire
