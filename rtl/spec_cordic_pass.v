// spec_cordic_pass - one CORDIC pass of spec_setup, fully pipelined: a new set of lanes every clock.
//
// Lane 0 drives: its pair (a, b) is rotated onto the positive a axis by ITERS micro-rotations
// (rotate by -atan(2^-i) when b >= 0, by +atan(2^-i) when b < 0); every other lane's pair gets the same
// micro-rotations. Each lane's third coordinate t is multiplied by the pass's gain (G, or G/2 with HALVE)
// as a sum of shifted copies (spec_setup_gain), so that all three coordinates of a vector keep one scale.
// Before the micro-rotations:
//   HALVE = 1     every pair is rounded to half its length: (a + 1) >>> 1
//   ANGLE = 0     if lane 0's a < 0, every pair is turned by pi (both coordinates negated)
//   ANGLE = 1     (one lane) a quarter turn when a < 0, and the angle lane z accumulates the rotation:
//                 z = atan2(b, a) in (-pi, pi], ZF fraction bits; the lane's a is then G * |(a, b)|
// Latency ITERS + 1 clocks (input stage, then one micro-rotation per stage); no stalls, no reset: the valid
// flag that qualifies the lanes travels in spec_setup_pipe. Bit for bit SetupModel::pass / vector_angle.
`timescale 1ns / 1ps
`default_nettype none
`include "setup_params.vh"
module spec_cordic_pass #(
    parameter LANES = 1,
    parameter W = `SETUP_W,
    parameter ITERS = `SETUP_ITERS,
    parameter ZW = `SETUP_ZW,
    parameter HALVE = 0,
    parameter ANGLE = 0
) (
    input  wire                  clk,
    input  wire [LANES*W-1:0]    a_i,      // lane k in bits [k*W +: W], two's complement
    input  wire [LANES*W-1:0]    b_i,
    input  wire [LANES*W-1:0]    t_i,      // third coordinates
    output wire [LANES*W-1:0]    a_o,
    output wire [LANES*W-1:0]    b_o,
    output wire [LANES*W-1:0]    t_o,
    output wire [ZW-1:0]         z_o       // ANGLE = 1: atan2(b, a) of lane 0's input
);
    localparam [ITERS*ZW-1:0] ATAN = `SETUP_ATAN;
    localparam signed [ZW-1:0] HALF_PI = `SETUP_HALF_PI;

    // ---- input stage: halving, then the turn that puts lane 0 into the half-plane a >= 0 ----------------
    wire signed [W-1:0] a0h, b0h;
    reg  [LANES*W-1:0] sa, sb;
    reg  [ZW-1:0]      sz;
    genvar k;
    generate
        for (k = 0; k < LANES; k = k + 1) begin : g_in
            wire signed [W-1:0] ai = a_i[k*W +: W];
            wire signed [W-1:0] bi = b_i[k*W +: W];
            wire signed [W-1:0] ah = (HALVE != 0) ? ((ai + 1) >>> 1) : ai;
            wire signed [W-1:0] bh = (HALVE != 0) ? ((bi + 1) >>> 1) : bi;
            if (k == 0) begin : g_lead
                assign a0h = ah;
                assign b0h = bh;
            end
            always @(posedge clk) begin
                if (ANGLE == 0) begin
                    sa[k*W +: W] <= a0h[W-1] ? -ah : ah;
                    sb[k*W +: W] <= a0h[W-1] ? -bh : bh;
                end else begin
                    // quarter turn: (a, b) -> (b, -a) for b >= 0, (-b, a) for b < 0
                    sa[k*W +: W] <= !a0h[W-1] ? ah : (!b0h[W-1] ? bh : -bh);
                    sb[k*W +: W] <= !a0h[W-1] ? bh : (!b0h[W-1] ? -ah : ah);
                end
            end
        end
    endgenerate
    always @(posedge clk) begin
        sz <= (ANGLE == 0 || !a0h[W-1]) ? {ZW{1'b0}} : (!b0h[W-1] ? HALF_PI : -HALF_PI);
    end

    // ---- micro-rotations: stage i holds the lanes after rotation i ----------------------------------------
    wire [LANES*W-1:0] ra[0:ITERS];
    wire [LANES*W-1:0] rb[0:ITERS];
    wire [ZW-1:0]      rz[0:ITERS];
    assign ra[0] = sa;
    assign rb[0] = sb;
    assign rz[0] = sz;
    genvar i;
    generate
        for (i = 0; i < ITERS; i = i + 1) begin : g_it
            wire pos = ~rb[i][W-1];   // lane 0's b >= 0: rotate by -atan(2^-i)
            reg [LANES*W-1:0] qa, qb;
            for (k = 0; k < LANES; k = k + 1) begin : g_lane
                wire signed [W-1:0] a = ra[i][k*W +: W];
                wire signed [W-1:0] b = rb[i][k*W +: W];
                wire signed [W-1:0] as = a >>> i;
                wire signed [W-1:0] bs = b >>> i;
                // one adder each, the direction folded into the operand (a - x = a + ~x + 1): a mux of two
                // adders would double the carry chains
                wire [W-1:0] bx = bs ^ {W{~pos}};
                wire [W-1:0] ax = as ^ {W{pos}};
                always @(posedge clk) begin
                    qa[k*W +: W] <= a + bx + {{(W - 1) {1'b0}}, ~pos};   // pos: a + bs, else a - bs
                    qb[k*W +: W] <= b + ax + {{(W - 1) {1'b0}}, pos};    // pos: b - as, else b + as
                end
            end
            assign ra[i+1] = qa;
            assign rb[i+1] = qb;
            if (ANGLE != 0) begin : g_z
                localparam signed [ZW-1:0] AT = ATAN[i*ZW +: ZW];
                reg signed [ZW-1:0] qz;
                wire [ZW-1:0] atx = AT ^ {ZW{~pos}};
                always @(posedge clk) qz <= rz[i] + atx + {{(ZW - 1) {1'b0}}, ~pos};   // pos: + atan, else - atan
                assign rz[i+1] = qz;
            end else begin : g_noz
                assign rz[i+1] = sz;
            end
        end
    endgenerate
    assign a_o = ra[ITERS];
    assign b_o = rb[ITERS];
    assign z_o = rz[ITERS];

    // ---- third coordinates: times G (or G/2), delayed to meet the pair ------------------------------------
    generate
        for (k = 0; k < LANES; k = k + 1) begin : g_third
            spec_setup_gain #(.W(W), .HALVE(HALVE), .LAT(ITERS + 1)) u_gain (
                .clk(clk), .t_i(t_i[k*W +: W]), .t_o(t_o[k*W +: W])
            );
        end
    endgenerate
endmodule
`default_nettype wire
