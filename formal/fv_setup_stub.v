// fv_setup_stub - spec_setup_machine's and spec_setup_finish's ports with the arithmetic left out, for the formal
// jobs of spec_setup and spec_shader (formal/formal.py), so that rtl/spec_setup.v itself (the holding register,
// the credits, the descriptor FIFO and its sizing from LATENCY / II) is what the properties are proved on.
//
//   - spec_setup_machine: the slot tau counts 0 .. II-1 and the span counter grows when it wraps, both reset to 0,
//     as in rtl/spec_setup_machine.v; tau0 and span are what spec_setup sees. The units, the banks and the
//     finish's reads (fin_*) are left out: fin_en stays 0.
//   - spec_setup_finish: a span started in a clock with side_we & side_valid gives d_valid exactly LATENCY clocks
//     later, in order, with that span's side information (n, l, rule, invalid); a reset clears every span in
//     flight (as rtl/spec_setup_finish.v's valid bits). The other fields are a fixed function of the side
//     information (C = ~n, zeta0 = n, dzeta = l, flags {invalid, rule, 0, n[3:0]}), so that the properties can
//     tell from a descriptor or a pixel's tuser whose it is and check every bit of it.
// The real machine starts a span in every tau0 clock whether spec_setup has one or not (side_valid says which),
// and the real finish turns the results of a valid span into d_valid LATENCY clocks after its start; the
// bit-exact simulation tests (make test, make test-long) check that, and the values. II and LATENCY are those of
// the setup_params.vh on the include path: formal.py puts a header with small ones first (its FV_SCHED).
`default_nettype none
`include "setup_params.vh"
`include "spec_params.vh"
module spec_setup_machine #(
    parameter EFU_FILE = `SETUP_EFU_FILE,
    parameter UC_FILE = `SETUP_UC_FILE,
    parameter N_W = 10,
    parameter L_W = 16
) (
    input  wire                        clk,
    input  wire                        rst,
    output wire                        tau0,
    output wire [`SETUP_STAGE_W-1:0]   span,
    input  wire [15*`SETUP_VEC_W+14:0] beat_vec,
    input  wire                        beat_rule,
    input  wire [`SETUP_STR_W-1:0]     beat_strength,
    input  wire [N_W-1:0]              beat_n,
    input  wire [L_W-1:0]              beat_l,
    output reg                         fin_en,
    output reg  [3:0]                  fin_field,
    output reg  [`SETUP_STAGE_W-1:0]   fin_span,
    output wire [`SETUP_W-1:0]         fin_data
);
    localparam II = `SETUP_II, SW = `SETUP_STAGE_W;
    localparam TAUW = (II > 512) ? 10 : (II > 256) ? 9 : (II > 128) ? 8 : (II > 64) ? 7 : (II > 32) ? 6 : (II > 16) ? 5 : 4;
    reg [TAUW-1:0] tau;
    reg [SW-1:0] s_cnt;
    wire last = tau == II - 1;
    always @(posedge clk) begin
        tau <= (rst | last) ? {TAUW{1'b0}} : tau + 1'b1;
        if (rst) s_cnt <= {SW{1'b0}};
        else if (last) s_cnt <= s_cnt + 1'b1;
        fin_en <= 1'b0;
        fin_field <= 4'd0;
        fin_span <= {SW{1'b0}};
    end
    assign tau0 = tau == {TAUW{1'b0}};
    assign span = s_cnt;
    assign fin_data = {`SETUP_W{1'b0}};
    wire unused;
    assign unused = &{1'b0, beat_vec, beat_rule, beat_strength, beat_n, beat_l};
endmodule

module spec_setup_finish #(
    parameter EXP2_FILE = `SETUP_EXP2_FILE
) (
    input  wire                      clk,
    input  wire                      rst,
    input  wire                      side_we,
    input  wire [`SETUP_STAGE_W-1:0] side_span,
    input  wire                      side_valid,
    input  wire                      side_invalid,
    input  wire                      side_rule,
    input  wire [`SPEC_N_W-1:0]      side_n,
    input  wire [`SPEC_L_W-1:0]      side_l,
    input  wire                      fin_en,
    input  wire [3:0]                fin_field,
    input  wire [`SETUP_STAGE_W-1:0] fin_span,
    input  wire [`SETUP_W-1:0]       fin_data,
    output wire                      d_valid,
    output wire [`SPEC_C_W-1:0]      d_c,
    output wire [`SPEC_N_W-1:0]      d_n,
    output wire [`SPEC_L_W-1:0]      d_l,
    output wire [`SPEC_ANG_W-1:0]    d_zeta0,
    output wire [`SPEC_ANG_W-1:0]    d_dzeta,
    output wire [6:0]                d_flags
);
    localparam LAT = `SETUP_LATENCY, N_W = `SPEC_N_W, L_W = `SPEC_L_W;
    localparam SIW = 2 + N_W + L_W;         // a span's side word {invalid, rule, n, l}
    reg [LAT-1:0] v;                        // stage k: a span started k + 1 clocks ago
    reg [LAT*SIW-1:0] sd;                   // its side word at [k*SIW +: SIW]
    always @(posedge clk) begin
        if (rst) v <= {LAT{1'b0}};
        else v <= {v[LAT-2:0], side_we & side_valid};
        sd <= {sd[0 +: (LAT - 1) * SIW], side_invalid, side_rule, side_n, side_l};
    end
    wire [SIW-1:0] o = sd[(LAT - 1) * SIW +: SIW];
    wire o_inv = o[SIW-1], o_rule = o[SIW-2];
    wire [N_W-1:0] o_n = o[L_W +: N_W];
    assign d_valid = v[LAT-1];
    assign d_n = o_n;
    assign d_l = o[0 +: L_W];
    assign d_c = ~o_n;
    assign d_zeta0 = o_n;
    assign d_dzeta = o[0 +: L_W];
    assign d_flags = {o_inv, o_rule, 1'b0, o_n[3:0]};
    wire unused;
    assign unused = &{1'b0, side_span, fin_en, fin_field, fin_span, fin_data};
endmodule
`default_nettype wire
