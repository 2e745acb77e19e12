// spec_setup_gain - a third coordinate times the CORDIC gain G (HALVE = 1: G/2) as the generator's sum of
// shifted copies, sum of sign * floor(t / 2^shift) (rom/setup_params.vh: SETUP_GAIN_* / SETUP_HALF_*), one
// term per pipeline stage, then delayed to LAT clocks in all. The partial sums may wrap in W bits: the terms
// are floored one by one, so the sum modulo 2^W is the exact result, which fits W bits (SetupModel::gain_mul).
`timescale 1ns / 1ps
`default_nettype none
`include "setup_params.vh"
module spec_setup_gain #(
    parameter W = `SETUP_W,
    parameter HALVE = 0,
    parameter LAT = 27        // clocks from t_i to t_o, at least the number of terms
) (
    input  wire         clk,
    input  wire [W-1:0] t_i,
    output wire [W-1:0] t_o
);
    localparam N = (HALVE != 0) ? `SETUP_HALF_N : `SETUP_GAIN_N;
    localparam [8*`SETUP_GAIN_N-1:0] GSH = `SETUP_GAIN_SHIFT;
    localparam [`SETUP_GAIN_N-1:0] GNEG = `SETUP_GAIN_NEG;
    localparam [8*`SETUP_HALF_N-1:0] HSH = `SETUP_HALF_SHIFT;
    localparam [`SETUP_HALF_N-1:0] HNEG = `SETUP_HALF_NEG;

    // stage k: acc[k+1] = acc[k] + term k; the input t travels beside it
    wire [W-1:0] acc[0:N];
    wire [W-1:0] tt[0:N];
    assign acc[0] = {W{1'b0}};
    assign tt[0] = t_i;
    genvar k;
    generate
        for (k = 0; k < N; k = k + 1) begin : g_term
            localparam [7:0] SH8 = (HALVE != 0) ? HSH[8*k +: 8] : GSH[8*k +: 8];
            localparam integer SH = SH8[7] ? -{24'd0, ~SH8 + 8'd1} : {24'd0, SH8};
            localparam NEG = (HALVE != 0) ? HNEG[k] : GNEG[k];
            wire signed [W-1:0] t = tt[k];
            wire signed [W-1:0] term = (SH >= 0) ? (t >>> SH) : (t <<< -SH);
            reg [W-1:0] ra, rt;
            always @(posedge clk) begin
                ra <= NEG ? acc[k] - term : acc[k] + term;
                rt <= tt[k];
            end
            assign acc[k+1] = ra;
            assign tt[k+1] = rt;
        end
    endgenerate
    wire unused_t;
    assign unused_t = &{1'b0, tt[N]};

    spec_delay #(.W(W), .N(LAT - N)) u_rest (.clk(clk), .ce(1'b1), .d(acc[N]), .q(t_o));
endmodule
`default_nettype wire
