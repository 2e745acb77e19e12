// spec_shr - a right shift by a variable amount in pipeline stages of two levels each (a 4:1 choice per bit):
// q = d >> amt, the levels of amt's bits from the top. S = amt's width. LAST_COMB = 0: every level registered,
// (S + 1) / 2 stages; LAST_COMB = 1: the last level (amt's bit 0 when S is odd) after the last register, for a
// caller whose next register takes it (spec_powpath: multiplier 13's input registers), S / 2 stages. The amount
// travels beside the data (q_amt: as the last register holds it). spec_powpath's alignment of n * L and its shift of
// exp2's value by y's integer part.
`timescale 1ns / 1ps
`default_nettype none
module spec_shr #(
    parameter W = 32,
    parameter S = 5,
    parameter LAST_COMB = 0
) (
    input  wire         clk,
    input  wire         ce,
    input  wire [W-1:0] d,
    input  wire [S-1:0] amt,
    output wire [W-1:0] q,
    output wire [S-1:0] q_amt
);
    localparam NST = (LAST_COMB != 0) ? S / 2 : (S + 1) / 2;   // registered stages
    // stage k's input at [k*W +: W] and its amount at [k*S +: S]; stage NST: after the last register
    wire [(NST+1)*W-1:0] x;
    wire [(NST+1)*S-1:0] a;
    assign x[W-1:0] = d;
    assign a[S-1:0] = amt;
    genvar k;
    generate
        for (k = 0; k < NST; k = k + 1) begin : g_stage
            localparam integer B1 = S - 1 - 2 * k;
            localparam integer B0 = B1 - 1;
            wire [W-1:0] xi = x[k*W +: W];
            wire [S-1:0] ai = a[k*S +: S];
            wire [W-1:0] x1 = ai[B1] ? (xi >> (1 << B1)) : xi;
            wire [W-1:0] x0;
            if (B0 >= 0) begin : g_two
                assign x0 = ai[B0] ? (x1 >> (1 << B0)) : x1;
            end else begin : g_one
                assign x0 = x1;
            end
            reg [W-1:0] x_q;
            reg [S-1:0] a_q;
            always @(posedge clk) begin
                if (ce) begin
                    x_q <= x0;
                    a_q <= ai;
                end
            end
            assign x[(k+1)*W +: W] = x_q;
            assign a[(k+1)*S +: S] = a_q;
        end
        wire [W-1:0] xl = x[NST*W +: W];
        wire [S-1:0] al = a[NST*S +: S];
        if (LAST_COMB != 0 && S % 2 != 0) begin : g_last
            assign q = al[0] ? (xl >> 1) : xl;
        end else begin : g_nolast
            assign q = xl;
        end
        assign q_amt = al;
    endgenerate
endmodule
`default_nettype wire
