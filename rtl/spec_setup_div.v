// spec_setup_div - register 2's step dzeta = round(gamma / l) in the descriptor's angle format: the
// quotient floor((g + l * 2^(S-1)) / (l * 2^S)), g the angle lane's gamma (ZF fraction bits), S = ZF - ANG_FRAC.
// Restoring long division, one quotient bit per pipeline stage (LAT = NW clocks, a new division every clock).
// l = 0 gives garbage (a one-pixel span is flat; the caller uses 0). Bit for bit SetupModel::divide.
`timescale 1ns / 1ps
`default_nettype none
module spec_setup_div #(
    parameter GW = 33,       // g: unsigned
    parameter LW = 16,       // l: unsigned
    parameter S = 2
) (
    input  wire                clk,
    input  wire [GW-1:0]       g,
    input  wire [LW-1:0]       l,
    output wire [GW:0]         q      // NW = GW + 1 bits
);
    localparam NW = GW + 1;
    localparam DW = LW + S;
    wire [NW-1:0] num = {1'b0, g} + ({{(NW - LW) {1'b0}}, l} << (S - 1));
    wire [DW-1:0] den = {l, {S{1'b0}}};

    // stage k consumes numerator bit NW-1-k; nq holds the numerator bits not yet used above the quotient
    // bits made so far
    wire [DW-1:0] rem[0:NW];            // < the divisor
    wire [NW-1:0] nq[0:NW];
    wire [DW-1:0] dd[0:NW];
    assign rem[0] = {DW{1'b0}};
    assign nq[0] = num;
    assign dd[0] = den;
    genvar k;
    generate
        for (k = 0; k < NW; k = k + 1) begin : g_bit
            wire [DW:0] shifted = {rem[k], nq[k][NW-1]};
            wire ge = shifted >= {1'b0, dd[k]};
            wire [DW:0] diff = shifted - {1'b0, dd[k]};
            wire unused_top = diff[DW];
            reg [DW-1:0] r;
            reg [NW-1:0] n;
            reg [DW-1:0] d;
            always @(posedge clk) begin
                r <= ge ? diff[DW-1:0] : shifted[DW-1:0];
                n <= {nq[k][NW-2:0], ge};
                d <= dd[k];
            end
            assign rem[k+1] = r;
            assign nq[k+1] = n;
            assign dd[k+1] = d;
        end
    endgenerate
    assign q = nq[NW];
    wire unused_div;
    assign unused_div = &{1'b0, rem[NW], dd[NW]};
endmodule
`default_nettype wire
