// spec_add - a W-bit adder with a carry in and a carry out, written so that both travel through the carry
// chain's own cells: x = {p, a, cin} + {p, b, cin}. The lowest position adds cin + cin, which carries cin
// into bit 1 (sum = a + b + cin), and the top position adds p + p + carry, whose sum bit is the carry out
// (p ^ p ^ c = c) whatever p is. On the iCE40 a carry that enters a chain from a flip-flop, or leaves it for
// one, otherwise costs a logic cell of its own and its routing (nextpnr inserts a feed-in/feed-out cell); here
// both are ordinary operand bits of the chain and the carry-out flip-flop sits in the top cell. `p` may be any
// signal except `cin` (a live one, so that synthesis keeps the top cell; with cin the packer merges the top
// cell into the bottom one). Purely combinational; the same function for every tool.
`timescale 1ns / 1ps
`default_nettype none
module spec_add #(
    parameter W = 12,
    parameter CO = 1    // 0: no carry out (cout = 0, p unused): no top cell
) (
    input  wire [W-1:0] a,
    input  wire [W-1:0] b,
    input  wire         cin,
    input  wire         p,      // any live signal other than cin (see above)
    output wire [W-1:0] sum,
    output wire         cout
);
    generate
        if (CO != 0) begin : g_co
            wire [W+1:0] x = {p, a, cin} + {p, b, cin};
            assign sum = x[W:1];
            assign cout = x[W+1];
            wire unused_lsb;
            assign unused_lsb = &{1'b0, x[0]};
        end else begin : g_noco
            wire [W:0] x = {a, cin} + {b, cin};
            assign sum = x[W:1];
            assign cout = 1'b0;
            wire unused_lsb;
            assign unused_lsb = &{1'b0, x[0], p};
        end
    endgenerate
endmodule
`default_nettype wire
