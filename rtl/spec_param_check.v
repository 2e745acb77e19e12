// spec_param_check - the parameter rules of spec_unit and spec_stream, checked at elaboration in every tool.
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
    parameter TSEL_W = 2
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
    endgenerate
endmodule
`default_nettype wire
