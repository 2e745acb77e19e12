// fv_setup_pipe_stub - spec_setup_pipe's ports with the arithmetic left out, for the formal jobs of spec_setup
// and spec_shader (formal/formal.py): a span in gives its descriptor LAT clocks later, n and l passed on (the
// properties number the spans through them), the other fields a fixed function of the input (the properties do
// not look at their values). spec_setup_pipe itself is a shift register of fixed depth without stalls or reset
// but the valid flags' (rtl/spec_setup_pipe.v), bit for bit its model in simulation; what the proofs are about
// is spec_setup's credits and FIFO around it, and spec_shader's flags FIFO.
`default_nettype none
`include "setup_params.vh"
`include "spec_params.vh"
module spec_setup_pipe #(
    parameter VEC_W = `SETUP_VEC_W,
    parameter STR_W = `SETUP_STR_W,
    parameter C_W = `SPEC_C_W,
    parameter N_W = `SPEC_N_W,
    parameter L_W = `SPEC_L_W,
    parameter ANG_W = `SPEC_ANG_W,
    parameter LOG2_FILE = "",
    parameter EXP2_FILE = "",
    parameter LAT = 3
) (
    input  wire               clk,
    input  wire               rst,
    input  wire               in_valid,
    input  wire [12*VEC_W-1:0] in_vec,
    input  wire [STR_W-1:0]   in_str,
    input  wire [N_W-1:0]     in_n,
    input  wire [L_W-1:0]     in_l,
    input  wire               in_rule,
    output wire               out_valid,
    output wire [C_W-1:0]     out_c,
    output wire [N_W-1:0]     out_n,
    output wire [L_W-1:0]     out_l,
    output wire [ANG_W-1:0]   out_zeta0,
    output wire [ANG_W-1:0]   out_dzeta,
    output wire [6:0]         out_flags
);
    reg [LAT-1:0] v;
    reg [N_W-1:0] n[0:LAT-1];
    reg [L_W-1:0] l[0:LAT-1];
    reg [C_W-1:0] c[0:LAT-1];
    integer i;
    always @(posedge clk) begin
        if (rst) v <= {LAT{1'b0}};
        else v <= {v[LAT-2:0], in_valid};
        n[0] <= in_n;
        l[0] <= in_l;
        c[0] <= in_str[C_W-1:0] ^ in_vec[C_W-1:0];
        for (i = 1; i < LAT; i = i + 1) begin
            n[i] <= n[i-1];
            l[i] <= l[i-1];
            c[i] <= c[i-1];
        end
    end
    assign out_valid = v[LAT-1];
    assign out_n = n[LAT-1];
    assign out_l = l[LAT-1];
    assign out_c = c[LAT-1];
    assign out_zeta0 = {{(ANG_W - N_W) {1'b0}}, n[LAT-1]};
    assign out_dzeta = {{(ANG_W - L_W) {1'b0}}, l[LAT-1]};
    // the flags: a function of the span's number (n), so that spec_shader's proof can see whose flags a pixel has
    assign out_flags = {3'b000, n[LAT-1][3:0]};
    wire unused;
    assign unused = &{1'b0, in_rule, in_vec, in_str};
endmodule
`default_nettype wire
