// spec_setup_prescale - an end vector's three components shifted left by one common amount so that the
// largest magnitude lands in [2^(F-1), 2^F): exact (a power of two), the direction is unchanged, and every
// vector then has the same relative precision in the CORDIC passes. zero = 1 for the zero vector (invalid).
// Combinational; SetupModel::prescale.
`timescale 1ns / 1ps
`default_nettype none
`include "setup_params.vh"
module spec_setup_prescale #(
    parameter VEC_W = `SETUP_VEC_W,
    parameter F = `SETUP_F,
    parameter W = `SETUP_W
) (
    input  wire [3*VEC_W-1:0] v_i,     // x, y, z in [0 +: VEC_W], [VEC_W +: VEC_W], [2*VEC_W +: VEC_W]
    output wire [3*W-1:0]     v_o,
    output wire               zero
);
    wire signed [VEC_W-1:0] x = v_i[0 +: VEC_W];
    wire signed [VEC_W-1:0] y = v_i[VEC_W +: VEC_W];
    wire signed [VEC_W-1:0] z = v_i[2*VEC_W +: VEC_W];
    // magnitudes, VEC_W bits unsigned (|-2^(VEC_W-1)| = 2^(VEC_W-1) fits)
    wire [VEC_W-1:0] mx = x[VEC_W-1] ? -x : x;
    wire [VEC_W-1:0] my = y[VEC_W-1] ? -y : y;
    wire [VEC_W-1:0] mz = z[VEC_W-1] ? -z : z;
    wire [VEC_W-1:0] m = mx | my | mz;   // its leading one is the largest magnitude's
    assign zero = ~|m;

    // e = index of the leading one; shift = F - 1 - e
    localparam [5:0] FM1 = F - 1;
    reg [5:0] e;
    integer j;
    always @* begin
        e = 6'd0;
        for (j = 0; j < VEC_W; j = j + 1) if (m[j]) e = j[5:0];
    end
    wire [5:0] sh = FM1 - e;
    wire signed [W-1:0] xe = {{(W - VEC_W) {x[VEC_W-1]}}, x};   // sign-extended
    wire signed [W-1:0] ye = {{(W - VEC_W) {y[VEC_W-1]}}, y};
    wire signed [W-1:0] ze = {{(W - VEC_W) {z[VEC_W-1]}}, z};
    assign v_o = {ze <<< sh, ye <<< sh, xe <<< sh};
endmodule
`default_nettype wire
