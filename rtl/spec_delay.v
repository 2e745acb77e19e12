// spec_delay - N clock-enabled register stages for the side band that travels beside the datapath
// (C, table select, flags). N = 0 is a wire. No reset: the valid flags that qualify it are reset elsewhere.
// RAM = 1 (2 <= N <= 1024; otherwise registers): the same delay in a memory instead of N * W flip-flops, for block RAM (iCE40 SB_RAM40_4K,
// ECP5 DP16KD): written at a counting address when ce is high and read N - 1 addresses behind it into a
// read register that also moves with ce, so q is d of N enabled clocks ago, as with the registers. Use it
// for long, wide delays where flip-flops are scarce (spec_stream's DELAY_RAM, spec_setup_ramdelay).
`timescale 1ns / 1ps
`default_nettype none
module spec_delay #(
    parameter W = 1,
    parameter N = 1,
    parameter RAM = 0
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
        end else if (RAM != 0 && N >= 2 && N <= 1024) begin : g_ram
            localparam AW = (N <= 2) ? 1 : (N <= 4) ? 2 : (N <= 8) ? 3 : (N <= 16) ? 4 : (N <= 32) ? 5 :
                            (N <= 64) ? 6 : (N <= 128) ? 7 : (N <= 256) ? 8 : (N <= 512) ? 9 : 10;
            localparam integer BACK = N - 1;
            (* ram_style = "block" *) reg [W-1:0] mem[0:(1 << AW) - 1];
            reg [AW-1:0] wa = {AW{1'b0}};
            reg [W-1:0] rq;
            wire [AW-1:0] ra = wa - BACK[AW-1:0];   // written N - 1 enabled clocks ago; rq adds one
            always @(posedge clk) begin
                if (ce) begin
                    mem[wa] <= d;
                    rq <= mem[ra];
                    wa <= wa + 1'b1;
                end
            end
            assign q = rq;
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
