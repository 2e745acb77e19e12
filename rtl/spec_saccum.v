// spec_saccum - the accumulating adder (adder 6, register 8) of spec_stream, pipelined for one pixel per
// clock at high clock rates; spec_stream has one per lane. spec_unit's saturating adder closes a loop through
// a 33-bit carry chain and the saturation mux every pixel. Here a lane's angles are computed as
//     angle = clamp(base + acc),  base = zeta0 + offs,  acc = 0 for the lane's first pixel of a span, then
//                                                            acc + step for each later one,
// with offs = o * dzeta (o = the number of the lane's first pixel in its span, 0 .. LANES - 1; OFFS = 0: always
// 0) and step = LANES * dzeta, so that the lane gets zeta0 + k * dzeta for its pixels k, exactly as spec_unit.
//   - Every sum is exact in AW = NSEG * SEG >= ANG_W + L_W bits: |zeta0 + k * dzeta| <= 2^(AW-1) for every
//     pixel k <= l < 2^L_W, and acc, base are such values or k * dzeta itself, so nothing overflows.
//   - Each adder is spec_add: the carries between segments enter and leave the carry chains as operand bits.
//   - The sums are cut into NSEG segments of SEG bits, one pipeline stage each, with the carry between
//     segments registered (a skewed adder): the only loop, acc, is a SEG-bit carry chain whose operands come
//     straight from flip-flops, and its "0 for the first pixel" is the flip-flops' synchronous reset; base
//     (and the final sum) are feed-forward.
//   - The segments are re-aligned by delays and clamped to ANG_W bits in two last stages.
// For a constant step the clamp of the exact sum equals spec_unit's step-by-step saturation (the sequence is
// monotone: once past an end it stays past it), so the angles are bit for bit those of spec_unit.
// Stages: an input register (so that the chains start at flip-flops placed beside them), NSEG segment stages
// for acc and base, one more for the last sum segment, two for the clamp.
// Latency: the angle of the pixel presented with ce = 1 in cycle t is on `angle` in cycle t + NSEG + 4.
`timescale 1ns / 1ps
`default_nettype none
module spec_saccum #(
    parameter ANG_W = 32,
    parameter L_W = 16,
    parameter SEG = 12,
    parameter OW = ANG_W + 2,                        // width of offs and step (two's complement)
    parameter OFFS = 0,                              // 1: offs is used (LANES > 1); 0: offs is ignored
    parameter NSEG = (ANG_W + L_W + SEG - 1) / SEG   // derived (>= 2): do not override
) (
    input  wire             clk,
    input  wire             ce,
    input  wire             first,    // the presented pixel is its lane's first of its span
    input  wire [ANG_W-1:0] zeta0,    // its span's start angle
    input  wire [OW-1:0]    offs,     // o * dzeta
    input  wire [OW-1:0]    step,     // LANES * dzeta
    output reg  [ANG_W-1:0] angle     // register 8, two's complement, saturated
);
    localparam AW = NSEG * SEG;

    // input stage
    reg first_q;
    reg [ANG_W-1:0] zeta0_q;
    reg [OW-1:0] offs_q, step_q;
    always @(posedge clk) begin
        if (ce) begin
            first_q <= first;
            zeta0_q <= zeta0;
            offs_q <= offs;
            step_q <= step;
        end
    end
    wire [AW-1:0] z_in = {{(AW - ANG_W) {zeta0_q[ANG_W-1]}}, zeta0_q};
    wire [AW-1:0] o_in = {{(AW - OW) {offs_q[OW-1]}}, offs_q};
    wire [AW-1:0] s_in = {{(AW - OW) {step_q[OW-1]}}, step_q};
    wire unused_offs;
    assign unused_offs = &{1'b0, o_in};

    // segment stages: segment k of the pixel presented k + 2 clocks ago
    wire [NSEG-1:0] c_acc, c_base;            // the carries out of segment k of acc and base (stage k)
    wire [AW-1:0] sum;                        // segment k of base + acc, registered one stage later
    wire [NSEG-1:0] c_sum;
    genvar k;
    generate
        for (k = 0; k < NSEG; k = k + 1) begin : g_seg
            // what segment k needs, delayed k stages
            wire f;
            wire [SEG-1:0] zk, ok, dk;
            spec_delay #(.W(1 + 3 * SEG), .N(k)) u_in (
                .clk(clk), .ce(ce),
                .d({first_q, z_in[k*SEG +: SEG], o_in[k*SEG +: SEG], s_in[k*SEG +: SEG]}),
                .q({f, zk, ok, dk})
            );
            wire ca_in = (k == 0) ? 1'b0 : c_acc[(k == 0) ? 0 : k - 1];
            wire cb_in = (k == 0) ? 1'b0 : c_base[(k == 0) ? 0 : k - 1];
            wire cs_in = (k == 0) ? 1'b0 : c_sum[(k == 0) ? 0 : k - 1];

            // acc: the loop; 0 (synchronous reset) for a first pixel
            reg [SEG-1:0] acc_r;
            reg ca_r;
            wire [SEG-1:0] a_sum;
            wire a_co;
            spec_add #(.W(SEG)) u_acc (.a(acc_r), .b(dk), .cin(ca_in), .p(f), .sum(a_sum), .cout(a_co));
            always @(posedge clk) begin
                if (ce) begin
                    acc_r <= f ? {SEG{1'b0}} : a_sum;
                    ca_r <= f ? 1'b0 : a_co;
                end
            end
            assign c_acc[k] = ca_r;

            // base = zeta0 + offs (feed-forward)
            reg [SEG-1:0] base_r;
            if (OFFS != 0) begin : g_offs
                reg cb_r;
                wire [SEG-1:0] b_sum;
                wire b_co;
                spec_add #(.W(SEG)) u_base (.a(zk), .b(ok), .cin(cb_in), .p(f), .sum(b_sum), .cout(b_co));
                always @(posedge clk) begin
                    if (ce) begin
                        base_r <= b_sum;
                        cb_r <= b_co;
                    end
                end
                assign c_base[k] = cb_r;
            end else begin : g_nooffs
                always @(posedge clk) begin
                    if (ce) base_r <= zk;
                end
                assign c_base[k] = 1'b0;
                wire unused_b;
                assign unused_b = &{1'b0, ok, cb_in};
            end

            // base + acc, one stage later (feed-forward)
            reg [SEG-1:0] sum_r;
            reg cs_r;
            wire [SEG-1:0] s_sum;
            wire s_co;
            spec_add #(.W(SEG)) u_sum (
                .a(base_r), .b(acc_r), .cin(cs_in), .p(base_r[SEG-1]), .sum(s_sum), .cout(s_co)
            );
            always @(posedge clk) begin
                if (ce) begin
                    sum_r <= s_sum;
                    cs_r <= s_co;
                end
            end
            assign sum[k*SEG +: SEG] = sum_r;
            assign c_sum[k] = cs_r;
        end
    endgenerate
    wire unused_carries;
    assign unused_carries = &{1'b0, c_acc[NSEG-1], c_base[NSEG-1], c_sum[NSEG-1]};

    // re-align: segment k of the sum waits NSEG - 1 - k clocks
    wire [AW-1:0] exact;
    generate
        for (k = 0; k < NSEG; k = k + 1) begin : g_align
            spec_delay #(.W(SEG), .N(NSEG - 1 - k)) u_d (.clk(clk), .ce(ce), .d(sum[k*SEG +: SEG]), .q(exact[k*SEG +: SEG]));
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
