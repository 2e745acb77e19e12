// tb_rom_check - ROM 9 and ROM 12 alone, for the ctests of the image checks in Verilator (tests/config_checks.py):
// the images at ROM9_FILE / ROM12_FILE (set when the model is Verilated) are replaced by broken ones, and the
// model must stop at time 0 with a message naming the file.
`timescale 1ns / 1ps
`default_nettype none
`include "spec_params.vh"
module tb_rom_check #(
    parameter ROM9_FILE = "",
    parameter ROM12_FILE = ""
) (
    input  wire clk,
    output wire [`SPEC_SCALE_W-1:0] scale,
    output wire [`SPEC_TBL_FRAC:0] value
);
    wire [`SPEC_TSEL_W-1:0] tsel_unused;
    spec_rom9 #(
        .N_W(`SPEC_N_W), .SCALE_W(`SPEC_SCALE_W), .SCALE_FRAC(`SPEC_SCALE_FRAC), .DECODER_ROM(`SPEC_DECODER_ROM),
        .TSEL_W(`SPEC_TSEL_W), .INIT_FILE(ROM9_FILE)
    ) u_rom9 (
        .clk(clk), .en(1'b1), .n({`SPEC_N_W{1'b0}}), .scale(scale), .table_sel(tsel_unused)
    );
    spec_rom12 #(
        .TBL_AW(`SPEC_TBL_AW), .TSEL_W(`SPEC_TSEL_W), .TBL_FRAC(`SPEC_TBL_FRAC), .INTERP(`SPEC_INTERP),
        .DELTA_W(`SPEC_DELTA_W), .INIT_FILE(ROM12_FILE)
    ) u_rom12 (
        .clk(clk), .en(1'b1), .table_sel({`SPEC_TSEL_W{1'b0}}), .index({`SPEC_TBL_AW{1'b0}}), .value(value)
    );
    wire unused;
    assign unused = &{1'b0, tsel_unused};
endmodule
`default_nettype wire
