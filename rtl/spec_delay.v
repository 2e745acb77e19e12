// spec_delay - N clock-enabled register stages for the side band that travels beside the datapath
// (C, table select, flags). N = 0 is a wire. No reset: the valid flags that qualify it are reset elsewhere.
`timescale 1ns / 1ps
`default_nettype none
module spec_delay #(
    parameter W = 1,
    parameter N = 1
) (
    input  wire         clk,
    input  wire         ce,
    input  wire [W-1:0] d,
    output wire [W-1:0] q
);
    generate
        if (N == 0) begin : g_wire
            wire unused_clk;
            assign unused_clk = &{1'b0, clk, ce};
            assign q = d;
        end else begin : g_regs
            reg [W-1:0] r[0:N-1];
            integer i;
            always @(posedge clk) begin
                if (ce) begin
                    r[0] <= d;
                    for (i = 1; i < N; i = i + 1) r[i] <= r[i-1];
                end
            end
            assign q = r[N-1];
        end
    endgenerate
endmodule
`default_nettype wire
