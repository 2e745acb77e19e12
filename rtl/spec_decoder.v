// spec_decoder - decoder 10 of UA 71489 (Fig. 10 rule, gates of Fig. 13) on register 4's n.
//   n = 1           -> 30 (cos)        element 47
//   n = 2           -> 31 (cos^2)      element 48
//   n = 3..6        -> 32 (cos^4)      elements 49..52 and OR 53
//   any other n     -> 33 (cos^16)     element 54: none of the above; covers n = 0 (ROM 9 gives scale 0,
//                                      so cos^16(0) = 1) and n = 1001..1023 (like 7..1000)
// The one-hot outputs stay observable; `table_sel` is their 2-bit code, the top address bits of ROM 12
// (the patent puts the four one-hot lines there, 30 most significant; see docs/decisions.md).
`timescale 1ns / 1ps
`default_nettype none
module spec_decoder #(
    parameter N_W = 10
) (
    input  wire [N_W-1:0] n,
    output wire           d30,
    output wire           d31,
    output wire           d32,
    output wire           d33,
    output wire [1:0]     table_sel   // 0: k = 1, 1: k = 2, 2: k = 4, 3: k = 16
);
    // AND/OR gates as in Fig. 13 (no magnitude comparators): the bits above v3 are zero, and v3..v1 match
    wire low = ~|n[N_W-1:3];
    wire [2:0] v = n[2:0];
    assign d30 = low & (v == 3'd1);
    assign d31 = low & (v == 3'd2);
    assign d32 = low & ((v == 3'd3) | (v == 3'd4) | (v == 3'd5) | (v == 3'd6));
    assign d33 = ~(d30 | d31 | d32);
    assign table_sel = {d32 | d33, d31 | d33};
endmodule
`default_nettype wire
