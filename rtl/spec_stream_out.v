// spec_stream_out - the AXI4-Stream source of the streaming back ends (spec_stream, spec_stream_seq): an
// output register with a skid buffer behind a pipeline that moves with `ce`.
// The pipeline's enable ce is a register (the skid buffer is empty), not m_axis_tready itself: no
// combinational path from m_axis_tready into the core's enables. When the sink stalls, the one beat already
// on its way is caught in the skid buffer and the pipeline stops a clock later. m_axis_tvalid, m_axis_tdata,
// m_axis_tkeep and m_axis_tlast are registers and hold until accepted.
// The pipeline's last stage: in_valid (it holds a beat: in_data, in_keep, in_last), in_valid_next (in_valid in
// the next cycle, from the stage before it and ce), so that the next-state functions below each have at most
// four inputs: one LUT level from the flip-flops.
// Reset (rst, synchronous): m_axis_tvalid, tdata, tkeep, tlast and the skid buffer cleared, ce = 1 next.
`timescale 1ns / 1ps
`default_nettype none
module spec_stream_out #(
    parameter LANES = 1,
    parameter OUT_W = 16
) (
    input  wire                    clk,
    input  wire                    rst,
    input  wire                    in_valid,
    input  wire                    in_valid_next,
    input  wire [LANES*OUT_W-1:0]  in_data,
    input  wire [LANES-1:0]        in_keep,
    input  wire                    in_last,
    output wire                    ce,          // the pipeline advances (a flip-flop)
    output wire                    ce_next,     // ce in the next cycle
    output reg                     m_axis_tvalid,
    input  wire                    m_axis_tready,
    output reg  [LANES*OUT_W-1:0]  m_axis_tdata,
    output reg  [LANES-1:0]        m_axis_tkeep,
    output reg                     m_axis_tlast
);
    reg skid_v, skid_last;
    reg ce_q;            // = ~skid_v: the pipeline's enable straight from a flip-flop
    reg [LANES-1:0] skid_keep;
    reg [LANES*OUT_W-1:0] skid_data;
    assign ce = ce_q;
    // have_q = skid_v | in_valid (a beat to offer: in the skid buffer or at the pipeline's end), kept as a
    // register
    reg have_q;
    wire o_load = have_q & (~m_axis_tvalid | m_axis_tready);
    wire skid_v_d = skid_v ? ~m_axis_tready : (in_valid & m_axis_tvalid & ~m_axis_tready);
    assign ce_next = ~skid_v_d;
    always @(posedge clk) begin
        if (rst) begin
            m_axis_tvalid <= 1'b0;
            skid_v <= 1'b0;
            ce_q <= 1'b1;
            have_q <= 1'b0;
        end else begin
            ce_q <= ~skid_v_d;
            have_q <= skid_v_d | in_valid_next;
            m_axis_tvalid <= have_q | (m_axis_tvalid & ~m_axis_tready);
            skid_v <= skid_v_d;
        end
        if (~skid_v) begin                  // an empty skid buffer copies the pipeline's output
            skid_data <= in_data;
            skid_keep <= in_keep;
            skid_last <= in_last;
        end
        if (rst) begin                      // defined from the first reset on (4-state simulators)
            m_axis_tdata <= {LANES*OUT_W{1'b0}};
            m_axis_tkeep <= {LANES{1'b0}};
            m_axis_tlast <= 1'b0;
        end else if (o_load) begin
            m_axis_tdata <= skid_v ? skid_data : in_data;
            m_axis_tkeep <= skid_v ? skid_keep : in_keep;
            m_axis_tlast <= skid_v ? skid_last : in_last;
        end
    end
endmodule
`default_nettype wire
