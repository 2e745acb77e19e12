// spec_shader - a whole per-pixel Blinn-Phong specular shader without a CPU: spec_setup (the patent's "external
// device": span ends -> register contents) in front of spec_stream (the patent's device, one pixel per clock).
// Span ends in (one 256-bit AXI4-Stream beat per span, docs/setup.md), pixels out (UQ0.16, l + 1 per span,
// tlast on a span's last pixel, the span's setup flags on tuser with every one of its pixels).
//
// The AXI4-Stream rules are spec_stream's: m_axis_tvalid, m_axis_tdata, m_axis_tlast, m_axis_tuser and
// s_axis_tready are registers; once valid, the outputs hold until m_axis_tready; no span is lost, duplicated
// or reordered. A FIFO of 2^FLAGS_AW flag words holds the flags of the spans between the setup and the pixel
// output: a descriptor enters spec_stream only while the FIFO has room, and the flags of the span whose
// pixels are leaving wait in a register (m_axis_tuser) loaded when the span before it ends.
//
// The two configurations (docs/setup.md):
//   ecp5: ITERATIVE = 0, spec_setup (the multiplier setup: a span every II clocks, several in flight) with
//         spec_stream (BACKEND = 0) in its default configuration;
//   up5k: ITERATIVE = 1, spec_setup_small (the small CORDIC setup, one span at a time, for the iCE40 UP5K where
//         the multiplier setup does not fit) with spec_stream_seq (BACKEND = 1) and spec_stream's up5k tables.
// BACKEND: 0 = spec_stream (one pixel per clock across span boundaries); 1 = spec_stream_seq (the compact back
// end, one span at a time: the same pixels, a few hundred flip-flops instead of a few thousand, datapath
// latency + 2 clocks between spans; for the small setup, which takes thousands of clocks a span).
// Reset: rst_n synchronous, active low, for both; spans in flight are dropped.
`timescale 1ns / 1ps
`default_nettype none
`include "setup_params.vh"
`include "setup_small_params.vh"
`include "spec_params.vh"
module spec_shader #(
    parameter ITERATIVE = 0,                    // 0: spec_setup (multiplier); 1: spec_setup_small (CORDIC)
    parameter FLAGS_AW = (ITERATIVE != 0) ? 2 : 5,   // flags of up to 2^FLAGS_AW - 1 spans between setup and pixels
    parameter DELAY_RAM = 0,                    // 1: spec_stream's side-band delays in block RAM (UP5K: fewer cells)
    parameter BACKEND = 0,                      // 0: spec_stream; 1: spec_stream_seq (one span at a time)
    parameter EFU_FILE = `SETUP_EFU_FILE,       // spec_setup's tables and microcode
    parameter EXP2_FILE = `SETUP_EXP2_FILE,
    parameter UC_FILE = `SETUP_UC_FILE,
    parameter SMALL_LOG2_FILE = `SMALL_LOG2_FILE,   // spec_setup_small's tables
    parameter SMALL_EXP2_FILE = `SMALL_EXP2_FILE,
    // spec_stream's configuration (docs/stream.md)
    parameter SCALE_W = `SPEC_SCALE_W,
    parameter SCALE_FRAC = `SPEC_SCALE_FRAC,
    parameter TBL_AW = `SPEC_TBL_AW,
    parameter TBL_FRAC = `SPEC_TBL_FRAC,
    parameter INTERP = `SPEC_INTERP,
    parameter INTERP_FRAC = `SPEC_INTERP_FRAC,
    parameter DELTA_W = `SPEC_DELTA_W,
    parameter ROM9_FILE = `SPEC_ROM9_FILE,
    parameter ROM12_FILE = `SPEC_ROM12_FILE,
    parameter BEAT_W = `SETUP_BEAT_W,
    parameter OUT_W = `SPEC_OUT_W
) (
    input  wire              clk,
    input  wire              rst_n,
    input  wire              s_axis_tvalid,
    output wire              s_axis_tready,
    input  wire [BEAT_W-1:0] s_axis_tdata,
    output wire              m_axis_tvalid,
    input  wire              m_axis_tready,
    output wire [OUT_W-1:0]  m_axis_tdata,
    output wire              m_axis_tlast,
    output reg  [6:0]        m_axis_tuser
);
    localparam DESC_W = `SPEC_DESC_W;
    wire rst = ~rst_n;

    // ---- setup ---------------------------------------------------------------------------------------------------
    wire d_valid, d_ready;
    wire [DESC_W-1:0] d_data;
    wire [6:0] d_flags;
    generate
        if (ITERATIVE == 0) begin : g_mul
            spec_setup #(.EFU_FILE(EFU_FILE), .EXP2_FILE(EXP2_FILE), .UC_FILE(UC_FILE)) u_setup (
                .clk(clk), .rst_n(rst_n), .s_axis_tvalid(s_axis_tvalid), .s_axis_tready(s_axis_tready),
                .s_axis_tdata(s_axis_tdata), .m_axis_tvalid(d_valid), .m_axis_tready(d_ready), .m_axis_tdata(d_data),
                .m_axis_tuser(d_flags)
            );
        end else begin : g_small
            spec_setup_small #(.LOG2_FILE(SMALL_LOG2_FILE), .EXP2_FILE(SMALL_EXP2_FILE)) u_setup (
                .clk(clk), .rst_n(rst_n), .s_axis_tvalid(s_axis_tvalid), .s_axis_tready(s_axis_tready),
                .s_axis_tdata(s_axis_tdata), .m_axis_tvalid(d_valid), .m_axis_tready(d_ready), .m_axis_tdata(d_data),
                .m_axis_tuser(d_flags)
            );
        end
    endgenerate

    // ---- the flags of the spans in spec_stream ---------------------------------------------------------------------
    reg [6:0] fmem[0:(1 << FLAGS_AW) - 1];
    reg [FLAGS_AW-1:0] fw, fr;
    reg [FLAGS_AW:0] fcnt;
    reg fspace;                                 // the FIFO has room for one more span (a register)
    reg fempty, fone;                           // fcnt is 0, fcnt is 1 (registers kept with fcnt)
    wire s_ready;                               // spec_stream takes a descriptor
    wire to_stream = d_valid & fspace;
    assign d_ready = s_ready & fspace;
    wire push = to_stream & s_ready;
    wire pop = m_axis_tvalid & m_axis_tready & m_axis_tlast;
    wire [FLAGS_AW:0] fcnt_n = fcnt + {{FLAGS_AW{1'b0}}, push} - {{FLAGS_AW{1'b0}}, pop};
    wire [FLAGS_AW-1:0] fr_next = fr + 1'b1;
    // fcnt_n is 0 after a pop exactly when fcnt + push is 1: from the registered tests, not from fcnt_n
    wire fzero_pop = (fone & ~push) | (fempty & push);
    always @(posedge clk) begin
        if (push) fmem[fw] <= d_flags;
        if (rst) begin
            fw <= {FLAGS_AW{1'b0}};
            fr <= {FLAGS_AW{1'b0}};
            fcnt <= {(FLAGS_AW + 1) {1'b0}};
            fspace <= 1'b0;
            fempty <= 1'b1;
            fone <= 1'b0;
        end else begin
            if (push) fw <= fw + 1'b1;
            if (pop) fr <= fr_next;
            fcnt <= fcnt_n;
            fspace <= fcnt_n < (1 << FLAGS_AW) - 1;
            fempty <= fcnt_n == {(FLAGS_AW + 1) {1'b0}};
            fone <= fcnt_n == {{FLAGS_AW{1'b0}}, 1'b1};
        end
        // m_axis_tuser: the oldest span's flags, loaded when a span arrives at an empty FIFO and when the oldest
        // span's last pixel leaves (its first pixel comes many clocks after its descriptor); reset to 0. The tests
        // of fcnt are the registers fempty and fone, so that pop (tlast, tready) sees no adder on its way here.
        if (rst) m_axis_tuser <= 7'd0;
        else if (pop ? !fzero_pop : (push && fempty)) begin
            if (pop && fone) m_axis_tuser <= d_flags;   // it was the only span
            else m_axis_tuser <= pop ? fmem[fr_next] : d_flags;
        end
    end

    // ---- the core --------------------------------------------------------------------------------------------------
    wire unused_keep;   // one lane (LANES = 1): tkeep is always 1
    generate
        if (BACKEND == 0) begin : g_stream
            spec_stream #(
                .SCALE_W(SCALE_W), .SCALE_FRAC(SCALE_FRAC), .TBL_AW(TBL_AW), .TBL_FRAC(TBL_FRAC), .INTERP(INTERP),
                .INTERP_FRAC(INTERP_FRAC), .DELTA_W(DELTA_W), .ROM9_FILE(ROM9_FILE), .ROM12_FILE(ROM12_FILE),
                .DELAY_RAM(DELAY_RAM)
            ) u_stream (
                .clk(clk), .rst_n(rst_n), .s_axis_tvalid(to_stream), .s_axis_tready(s_ready), .s_axis_tdata(d_data),
                .m_axis_tvalid(m_axis_tvalid), .m_axis_tready(m_axis_tready), .m_axis_tdata(m_axis_tdata),
                .m_axis_tlast(m_axis_tlast), .m_axis_tkeep(unused_keep)
            );
        end else if (BACKEND == 1) begin : g_seq
            spec_stream_seq #(
                .SCALE_W(SCALE_W), .SCALE_FRAC(SCALE_FRAC), .TBL_AW(TBL_AW), .TBL_FRAC(TBL_FRAC), .INTERP(INTERP),
                .INTERP_FRAC(INTERP_FRAC), .DELTA_W(DELTA_W), .ROM9_FILE(ROM9_FILE), .ROM12_FILE(ROM12_FILE)
            ) u_stream (
                .clk(clk), .rst_n(rst_n), .s_axis_tvalid(to_stream), .s_axis_tready(s_ready), .s_axis_tdata(d_data),
                .m_axis_tvalid(m_axis_tvalid), .m_axis_tready(m_axis_tready), .m_axis_tdata(m_axis_tdata),
                .m_axis_tlast(m_axis_tlast), .m_axis_tkeep(unused_keep)
            );
        end else begin : g_backend
            spec_parameter_error_BACKEND_must_be_0_or_1 check_the_BACKEND_parameter ();
        end
    endgenerate
endmodule
`default_nettype wire
