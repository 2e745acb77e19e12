// spec_desc_check - the descriptor layout rules of the streaming back ends (spec_stream, spec_stream_seq),
// checked at elaboration in every tool: each field [LSB +: width] lies inside DESC_W bits and no two overlap.
// A layout that breaks a rule stops elaboration the way spec_param_check does (a module that does not exist,
// named after the rule). No logic.
`timescale 1ns / 1ps
`default_nettype none
module spec_desc_check #(
    parameter C_W = 16,
    parameter N_W = 10,
    parameter L_W = 16,
    parameter ANG_W = 32,
    parameter DESC_W = 128,
    parameter DESC_C_LSB = 0,
    parameter DESC_N_LSB = 16,
    parameter DESC_L_LSB = 32,
    parameter DESC_ZETA0_LSB = 64,
    parameter DESC_DZETA_LSB = 96
) ();
    localparam C_END = DESC_C_LSB + C_W, N_END = DESC_N_LSB + N_W, L_END = DESC_L_LSB + L_W;
    localparam Z_END = DESC_ZETA0_LSB + ANG_W, D_END = DESC_DZETA_LSB + ANG_W;
    generate
        if (DESC_C_LSB < 0 || DESC_N_LSB < 0 || DESC_L_LSB < 0 || DESC_ZETA0_LSB < 0 || DESC_DZETA_LSB < 0 ||
            C_END > DESC_W || N_END > DESC_W || L_END > DESC_W || Z_END > DESC_W || D_END > DESC_W)
        begin : g_desc_inside
            spec_parameter_error_a_descriptor_field_lies_outside_DESC_W check_the_DESC_LSB_parameters ();
        end
        if (!(C_END <= DESC_N_LSB || N_END <= DESC_C_LSB) || !(C_END <= DESC_L_LSB || L_END <= DESC_C_LSB) ||
            !(C_END <= DESC_ZETA0_LSB || Z_END <= DESC_C_LSB) || !(C_END <= DESC_DZETA_LSB || D_END <= DESC_C_LSB) ||
            !(N_END <= DESC_L_LSB || L_END <= DESC_N_LSB) || !(N_END <= DESC_ZETA0_LSB || Z_END <= DESC_N_LSB) ||
            !(N_END <= DESC_DZETA_LSB || D_END <= DESC_N_LSB) || !(L_END <= DESC_ZETA0_LSB || Z_END <= DESC_L_LSB) ||
            !(L_END <= DESC_DZETA_LSB || D_END <= DESC_L_LSB) ||
            !(Z_END <= DESC_DZETA_LSB || D_END <= DESC_ZETA0_LSB))
        begin : g_desc_overlap
            spec_parameter_error_descriptor_fields_overlap check_the_DESC_LSB_parameters ();
        end
    endgenerate
endmodule
`default_nettype wire
