// tb_elab - spec_unit and spec_stream with every parameter settable (pow mode's: POW and POW_IDX_W) (iverilog -P tb_elab.NAME=VALUE), run for a few
// clocks: the ctests of tests/config_checks.py show that parameters against the ROM images and impossible
// parameter combinations stop Icarus with a message, and that the right ones run ("tb_elab: ran").
`timescale 1ns / 1ps
`default_nettype none
`include "spec_params.vh"
module tb_elab #(
    parameter C_W = `SPEC_C_W,
    parameter ANG_W = `SPEC_ANG_W,
    parameter ANG_FRAC = `SPEC_ANG_FRAC,
    parameter N_W = `SPEC_N_W,
    parameter L_W = `SPEC_L_W,
    parameter OUT_W = `SPEC_OUT_W,
    parameter SCALE_W = `SPEC_SCALE_W,
    parameter SCALE_FRAC = `SPEC_SCALE_FRAC,
    parameter TBL_AW = `SPEC_TBL_AW,
    parameter TBL_FRAC = `SPEC_TBL_FRAC,
    parameter INTERP = `SPEC_INTERP,
    parameter INTERP_FRAC = `SPEC_INTERP_FRAC,
    parameter DELTA_W = `SPEC_DELTA_W,
    parameter DECODER_ROM = `SPEC_DECODER_ROM,
    parameter TSEL_W = `SPEC_TSEL_W,
    parameter POW = `SPEC_POW,
    parameter POW_IDX_W = `SPEC_POW_IDX_W,
    parameter ROM9_FILE = `SPEC_ROM9_FILE,
    parameter ROM12_FILE = `SPEC_ROM12_FILE,
    parameter DESC_W = `SPEC_DESC_W,
    parameter DESC_C_LSB = `SPEC_DESC_C_LSB,
    parameter DESC_N_LSB = `SPEC_DESC_N_LSB,
    parameter DESC_L_LSB = `SPEC_DESC_L_LSB,
    parameter DESC_ZETA0_LSB = `SPEC_DESC_ZETA0_LSB,
    parameter DESC_DZETA_LSB = `SPEC_DESC_DZETA_LSB
);
    reg clk = 1'b0;
    reg rst_n = 1'b0;
    wire [OUT_W-1:0] intensity, px;
    wire busy, valid, s_ready, m_valid, m_last;

    spec_unit #(
        .C_W(C_W), .ANG_W(ANG_W), .ANG_FRAC(ANG_FRAC), .N_W(N_W), .L_W(L_W), .OUT_W(OUT_W), .SCALE_W(SCALE_W),
        .SCALE_FRAC(SCALE_FRAC), .TBL_AW(TBL_AW), .TBL_FRAC(TBL_FRAC), .INTERP(INTERP), .INTERP_FRAC(INTERP_FRAC),
        .DELTA_W(DELTA_W), .DECODER_ROM(DECODER_ROM), .TSEL_W(TSEL_W), .POW(POW), .POW_IDX_W(POW_IDX_W),
        .ROM9_FILE(ROM9_FILE), .ROM12_FILE(ROM12_FILE)
    ) u_unit (
        .clk(clk), .init_n(rst_n), .start(1'b0), .c_i({C_W{1'b0}}), .c_we(1'b0), .dzeta_i({ANG_W{1'b0}}),
        .dzeta_we(1'b0), .zeta0_i({ANG_W{1'b0}}), .zeta0_we(1'b0), .n_i({N_W{1'b0}}), .n_we(1'b0),
        .len_i({L_W{1'b0}}), .len_load_n(1'b1), .intensity_o(intensity), .busy_o(busy), .valid_o(valid)
    );
    spec_stream #(
        .C_W(C_W), .ANG_W(ANG_W), .ANG_FRAC(ANG_FRAC), .N_W(N_W), .L_W(L_W), .OUT_W(OUT_W), .SCALE_W(SCALE_W),
        .SCALE_FRAC(SCALE_FRAC), .TBL_AW(TBL_AW), .TBL_FRAC(TBL_FRAC), .INTERP(INTERP), .INTERP_FRAC(INTERP_FRAC),
        .DELTA_W(DELTA_W), .DECODER_ROM(DECODER_ROM), .TSEL_W(TSEL_W), .POW(POW), .POW_IDX_W(POW_IDX_W),
        .ROM9_FILE(ROM9_FILE), .ROM12_FILE(ROM12_FILE), .DESC_W(DESC_W), .DESC_C_LSB(DESC_C_LSB), .DESC_N_LSB(DESC_N_LSB), .DESC_L_LSB(DESC_L_LSB),
        .DESC_ZETA0_LSB(DESC_ZETA0_LSB), .DESC_DZETA_LSB(DESC_DZETA_LSB)
    ) u_stream (
        .clk(clk), .rst_n(rst_n), .s_axis_tvalid(1'b0), .s_axis_tready(s_ready), .s_axis_tdata({DESC_W{1'b0}}),
        .m_axis_tvalid(m_valid), .m_axis_tready(1'b1), .m_axis_tdata(px), .m_axis_tlast(m_last)
    );

    initial begin
        repeat (4) begin
            #5 clk = 1'b1;
            #5 clk = 1'b0;
            rst_n = 1'b1;
        end
        $display("tb_elab: ran");
        $finish;
    end
endmodule
`default_nettype wire
