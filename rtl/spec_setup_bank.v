// spec_setup_bank - one bank of spec_setup_machine: a RAM with one write port and one read port, the read
// registered (the value read in the clock its address is given arrives in the next). The schedule never reads a
// word in the clock it is written (rom/gen/setup_sched.h), so no read-during-write behaviour is relied on.
`timescale 1ns / 1ps
`default_nettype none
module spec_setup_bank #(
    parameter AW = 4,
    parameter DW = 31
) (
    input  wire          clk,
    input  wire          we,
    input  wire [AW-1:0] wa,
    input  wire [DW-1:0] wd,
    input  wire [AW-1:0] ra,
    output reg  [DW-1:0] rd
);
    (* no_rw_check *) reg [DW-1:0] mem[0:(1 << AW) - 1];
    always @(posedge clk) begin
        if (we) mem[wa] <= wd;
        rd <= mem[ra];
    end
endmodule
`default_nettype wire
