// spec_saccum - the accumulating adder (adder 6, register 8) of spec_stream, pipelined for one pixel per
// clock at high clock rates. spec_unit's saturating adder closes a loop through a 33-bit carry chain and the
// saturation mux every pixel; here:
//   - the sum zeta0 + i * dzeta is kept exact in AW = ANG_W + L_W bits (|zeta0 + l * dzeta| < 2^(AW-1) for
//     any l < 2^L_W, so it never overflows);
//   - it is cut into NSEG segments of SEG bits, one pipeline stage each: stage k adds segment k of the step
//     and the carry that stage k-1 registered one clock earlier (a skewed, carry-save-free accumulator),
//     so no loop holds more than a SEG-bit carry chain; the first pixel of a span loads segment k of zeta0
//     instead (every pixel carries its span's zeta0, dzeta and a `first` flag down the stages);
//   - the segments are re-aligned by delays and clamped to ANG_W bits in a last stage.
// For a constant step the clamp of the exact sum equals spec_unit's step-by-step saturation (the sequence is
// monotone: once past an end it stays past it), so the angles are bit for bit those of spec_unit.
// Latency: the angle of the pixel presented with ce = 1 in cycle t is on `angle` in cycle t + NSEG + 2.
`timescale 1ns / 1ps
`default_nettype none
module spec_saccum #(
    parameter ANG_W = 32,
    parameter L_W = 16,
    parameter SEG = 16,
    parameter NSEG = (ANG_W + L_W + SEG - 1) / SEG   // derived (>= 2): do not override
) (
    input  wire             clk,
    input  wire             ce,
    input  wire             first,    // the presented pixel is its span's first
    input  wire [ANG_W-1:0] zeta0,    // its span's start angle
    input  wire [ANG_W-1:0] dzeta,    // its span's step
    output reg  [ANG_W-1:0] angle     // register 8, two's complement, saturated
);
    localparam AW = NSEG * SEG;

    wire [AW-1:0] z_in = {{(AW - ANG_W) {zeta0[ANG_W-1]}}, zeta0};
    wire [AW-1:0] d_in = {{(AW - ANG_W) {dzeta[ANG_W-1]}}, dzeta};

    // stage k: seg[k] = segment k of the sum of the pixel presented k + 1 clocks ago
    reg [SEG-1:0] seg[0:NSEG-1];
    reg [NSEG-2:0] carry;
    // first_s[k], z_s[k], d_s[k]: what the pixel that stage k processed brings to stage k + 1
    reg [NSEG-2:0] first_s;
    reg [AW-1:0] z_s[0:NSEG-2];
    reg [AW-1:0] d_s[0:NSEG-2];
    always @(posedge clk) begin
        if (ce) begin
            first_s[0] <= first;
            z_s[0] <= z_in;
            d_s[0] <= d_in;
        end
    end

    genvar k;
    generate
        for (k = 0; k < NSEG; k = k + 1) begin : g_seg
            wire f, cin;
            wire [SEG-1:0] zk, dk;
            if (k == 0) begin : g_first
                assign f = first;
                assign zk = z_in[SEG-1:0];
                assign dk = d_in[SEG-1:0];
                assign cin = 1'b0;
            end else begin : g_next
                assign f = first_s[k-1];
                assign zk = z_s[k-1][k*SEG +: SEG];
                assign dk = d_s[k-1][k*SEG +: SEG];
                assign cin = carry[k-1];
            end
            wire [SEG:0] sum = {1'b0, seg[k]} + {1'b0, dk} + {{SEG{1'b0}}, cin};
            always @(posedge clk) begin
                if (ce) seg[k] <= f ? zk : sum[SEG-1:0];
            end
            if (k < NSEG - 1) begin : g_carry
                always @(posedge clk) begin
                    if (ce) carry[k] <= ~f & sum[SEG];
                end
            end else begin : g_top
                wire unused_top;
                assign unused_top = &{1'b0, sum[SEG]};
            end
            if (k > 0 && k < NSEG - 1) begin : g_pass
                always @(posedge clk) begin
                    if (ce) begin
                        first_s[k] <= first_s[k-1];
                        z_s[k] <= z_s[k-1];
                        d_s[k] <= d_s[k-1];
                    end
                end
            end
        end
    endgenerate

    // re-align: segment k waits NSEG - 1 - k clocks
    wire [AW-1:0] exact;
    generate
        for (k = 0; k < NSEG; k = k + 1) begin : g_align
            spec_delay #(.W(SEG), .N(NSEG - 1 - k)) u_d (.clk(clk), .ce(ce), .d(seg[k]), .q(exact[k*SEG +: SEG]));
        end
    endgenerate

    // clamp, in two stages: the range flags, then the choice
    reg [ANG_W-1:0] low_c;
    reg all0, all1, sign_c;
    always @(posedge clk) begin
        if (ce) begin
            low_c <= exact[ANG_W-1:0];
            all0 <= ~|exact[AW-1:ANG_W-1];
            all1 <= &exact[AW-1:ANG_W-1];
            sign_c <= exact[AW-1];
            angle <= (all0 | all1) ? low_c
                                   : (sign_c ? {1'b1, {(ANG_W - 1) {1'b0}}} : {1'b0, {(ANG_W - 1) {1'b1}}});
        end
    end
endmodule
`default_nettype wire
