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
// Two pipeline stages, one step per clock: the outputs of a step presented with in_valid appear two cycles
// later with out_valid. rst is synchronous and clears the valid flags only. Bit-exact model:
// spec::methods::step_fixed (sim/methods/parallax.cpp).
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
    localparam PW = H_W + V_W;                   // a product
    localparam SW = (PW > UV_W ? PW : UV_W) + 1;  // sums, wide enough for every operand
    localparam signed [SW-1:0] H_MAX = {{(SW - H_W + 1) {1'b0}}, {(H_W - 1) {1'b1}}};
    localparam signed [SW-1:0] H_MIN = {{(SW - H_W + 1) {1'b1}}, {(H_W - 1) {1'b0}}};

    // ---- stage 1: hV_i and d_i ----
    wire signed [PW-1:0] p1 = $signed(d_prev_i) * $signed(vh_i);
    wire signed [SW-1:0] p1_s = $signed({{(SW - PW) {p1[PW-1]}}, p1}) >>> V_F;
    wire signed [SW-1:0] hv_sum = {{(SW - H_W) {hv_prev_i[H_W-1]}}, hv_prev_i} + p1_s;
    wire signed [SW-1:0] hv_sat = hv_sum > H_MAX ? H_MAX : (hv_sum < H_MIN ? H_MIN : hv_sum);
    wire signed [SW-1:0] d_sum = {{(SW - H_W) {h_i[H_W-1]}}, h_i} - hv_sat;
    wire signed [SW-1:0] d_sat = d_sum > H_MAX ? H_MAX : (d_sum < H_MIN ? H_MIN : d_sum);

    reg            v1;
    reg [UV_W-1:0] u1, w1;
    reg [H_W-1:0]  hv1, d1;
    reg [V_W-1:0]  vu1, vv1;
    always @(posedge clk) begin
        if (rst) v1 <= 1'b0;
        else v1 <= in_valid;
        u1 <= u_i;
        w1 <= v_i;
        hv1 <= hv_sat[H_W-1:0];
        d1 <= d_sat[H_W-1:0];
        vu1 <= vu_i;
        vv1 <= vv_i;
    end

    // ---- stage 2: P_(i+1) ----
    wire signed [PW-1:0] p2 = $signed(d1) * $signed(vu1);
    wire signed [PW-1:0] p3 = $signed(d1) * $signed(vv1);
    wire signed [SW-1:0] p2_s = $signed({{(SW - PW) {p2[PW-1]}}, p2}) >>> V_F;
    wire signed [SW-1:0] p3_s = $signed({{(SW - PW) {p3[PW-1]}}, p3}) >>> V_F;
    wire signed [SW-1:0] u_sum = {{(SW - UV_W) {u1[UV_W-1]}}, u1} + p2_s;
    wire signed [SW-1:0] v_sum = {{(SW - UV_W) {w1[UV_W-1]}}, w1} + p3_s;

    always @(posedge clk) begin
        if (rst) out_valid <= 1'b0;
        else out_valid <= v1;
        u_o <= u_sum[UV_W-1:0];
        v_o <= v_sum[UV_W-1:0];
        hv_o <= hv1;
        d_o <= d1;
    end

    // the bits above each result: saturated or wrapped away
    wire unused_bits = &{1'b0, hv_sat[SW-1:H_W], d_sat[SW-1:H_W], u_sum[SW-1:UV_W], v_sum[SW-1:UV_W]};
endmodule
`default_nettype wire
