// spec_param_check - the parameter rules of spec_unit, spec_stream and spec_stream_seq (patent, tuned and pow mode),
// checked at elaboration in every tool.
// A combination the datapath cannot compute stops elaboration: each rule that fails instantiates a module that
// does not exist, whose name says what is wrong: Icarus says "Unknown module type: spec_parameter_error_...",
// the Verilator linter "Cannot find file containing module: 'spec_parameter_error_...'" and Yosys "Module ... is
// not part of the design". Verilog-2005 has no $error at elaboration; this works in all three tools alike.
// The same rules as the generator's Format::validate (rom/gen/romgen.cpp), which writes the ROM images.
`timescale 1ns / 1ps
`default_nettype none
module spec_param_check #(
    parameter C_W = 16,
    parameter ANG_W = 32,
    parameter ANG_FRAC = 28,
    parameter N_W = 10,
    parameter L_W = 16,
    parameter OUT_W = 16,
    parameter SCALE_W = 18,
    parameter SCALE_FRAC = 15,
    parameter TBL_AW = 12,
    parameter TBL_FRAC = 16,
    parameter INTERP = 0,
    parameter INTERP_FRAC = 10,
    parameter DELTA_W = 10,
    parameter DECODER_ROM = 0,
    parameter TSEL_W = 2,
    parameter POW = 0,          // pow mode (spec_powpath, docs/pow.md) and its parameters
    parameter POW_SEG_W = 3,
    parameter POW_IDX_W = 6,
    parameter POW_FRAC = 10,
    parameter POW_VAL_W = 16,
    parameter POW_DLT_W = 14,
    parameter POW_SH_W = 5,
    parameter POW_XB = 12,
    parameter POW_YF = 18,
    parameter POW_YI = 5,
    parameter POW_K = 421657428
) ();
    generate
        if (OUT_W != C_W) begin : g_out_w
            spec_parameter_error_OUT_W_must_equal_C_W so_that_n_0_gives_C_exactly ();
        end
        if (ANG_W % 2 != 0) begin : g_ang_w
            spec_parameter_error_ANG_W_must_be_even multiplier_11_splits_the_angle_in_halves ();
        end
        if (ANG_W < 8 || ANG_FRAC < 4 || ANG_FRAC > ANG_W - 3) begin : g_ang_frac
            spec_parameter_error_ANG_FRAC_must_be_4_to_ANG_W_minus_3 the_angle_range_must_hold_pi ();
        end
        if (N_W < 4) begin : g_n_w
            spec_parameter_error_N_W_must_be_at_least_4 decoder_10_reads_bit_3_of_n ();
        end
        if (C_W < 2 || L_W < 1 || TBL_AW < 4 || TBL_FRAC < 4) begin : g_small
            spec_parameter_error_C_W_L_W_TBL_AW_or_TBL_FRAC_too_small see_Format_validate ();
        end
        if (SCALE_W <= SCALE_FRAC || ANG_FRAC + SCALE_FRAC <= TBL_AW + 1) begin : g_scale
            spec_parameter_error_ANG_FRAC_plus_SCALE_FRAC_must_exceed_TBL_AW_plus_1 the_position_needs_a_fraction ();
        end
        if (INTERP != 0 && (INTERP_FRAC < 1 || ANG_FRAC + SCALE_FRAC < TBL_AW + INTERP_FRAC || DELTA_W < 1))
        begin : g_interp
            spec_parameter_error_INTERP_FRAC_must_be_1_to_ANG_FRAC_plus_SCALE_FRAC_minus_TBL_AW see_Format_validate ();
        end
        if (DECODER_ROM == 0 && TSEL_W != 2) begin : g_tsel
            spec_parameter_error_TSEL_W_must_be_2_when_decoder_10_gates_choose the_patent_has_four_tables ();
        end
        if (TSEL_W < 1 || TSEL_W > 4) begin : g_tsel_range
            spec_parameter_error_TSEL_W_must_be_1_to_4 at_most_16_tables ();
        end
        if (POW != 0 && POW != 1) begin : g_pow
            spec_parameter_error_POW_must_be_0_or_1 check_the_POW_parameter ();
        end
        if (POW != 0 && DECODER_ROM != 0) begin : g_pow_dec
            spec_parameter_error_POW_1_takes_no_table_field_DECODER_ROM_must_be_0 pow_mode_has_no_cos_k_tables ();
        end
        if (POW != 0 && (POW_SEG_W < 1 || POW_SEG_W > 4 || POW_IDX_W < 2 || POW_IDX_W > 8 || POW_FRAC < 1 ||
                         POW_FRAC > 16 || POW_VAL_W < 8 || POW_VAL_W > 18 || POW_DLT_W < 1 || POW_DLT_W > POW_VAL_W ||
                         POW_SH_W < 1 || POW_SH_W > 6 || POW_YI < 1 || POW_YI > 6 || TBL_FRAC < 8))
        begin : g_pow_widths
            spec_parameter_error_POW_widths_out_of_range see_Format_validate ();
        end
        if (POW != 0 && (ANG_FRAC > 29 || ANG_FRAC - 1 - POW_IDX_W - POW_FRAC < 0 ||
                         ANG_FRAC - 1 - POW_IDX_W - ((1 << POW_SEG_W) - 2) < 0 || POW_K < (1 << ANG_FRAC) ||
                         POW_K >= (2 << ANG_FRAC)))
        begin : g_pow_angle
            spec_parameter_error_POW_log_table_does_not_fit_ANG_FRAC see_Format_validate ();
        end
        if (POW != 0 && (POW_XB < 0 || POW_XB > POW_YF || POW_YF > 24 ||
                         POW_YF < TBL_AW + ((INTERP != 0) ? INTERP_FRAC : 1)))
        begin : g_pow_y
            spec_parameter_error_POW_YF_must_hold_ROM_12_position_and_fraction see_Format_validate ();
        end
    endgenerate
endmodule
`default_nettype wire
