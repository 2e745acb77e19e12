// spec_rom - a read-only memory with a registered read, loaded by $readmemh from INIT_FILE.
// The registered read lets Yosys map it to block RAM (SB_RAM40_4K on iCE40, DP16KD on ECP5).
// Simulation stops with an error when INIT_FILE cannot be opened (Verilator would only warn and
// Icarus would fill X); Yosys defines SYNTHESIS and skips that check.
`timescale 1ns / 1ps
`default_nettype none
module spec_rom #(
    parameter AW = 10,
    parameter DW = 18,
    parameter INIT_FILE = ""
) (
    input  wire          clk,
    input  wire          en,
    input  wire [AW-1:0] addr,
    output reg  [DW-1:0] data
);
    reg [DW-1:0] mem[0:(1 << AW) - 1];

`ifndef SYNTHESIS
    integer fd;
    initial begin
        fd = $fopen(INIT_FILE, "r");
        if (fd == 0) begin
            $display("spec_rom: cannot open ROM image '%0s' (INIT_FILE of %m)", INIT_FILE);
            $fatal(1);
        end
        $fclose(fd);
    end
`endif

    initial $readmemh(INIT_FILE, mem);

    always @(posedge clk) begin
        if (en) data <= mem[addr];
    end
endmodule
`default_nettype wire
