// fv_spec_setup - formal properties of spec_setup's handshake and span accounting (pipelined configuration),
// proved by formal/formal.py (make formal) with yosys-smtbmc and z3.
//
// The core is `fv_core_setup`: rtl/spec_setup.v with a 4-entry FIFO (FIFO_AW = 2: 6 credits) and the
// arithmetic left out (formal/fv_setup_pipe_stub.v: a 3-stage shift register that passes n and l on), the
// credit counter and the FIFO's occupancy made ports by Yosys `expose`; the descriptor's widths are the
// reduced ones of formal.py. Every input is free but for the numbering: the source writes the number of the
// beat it offers (beats accepted so far, mod 2^N_W) into the n field, and the properties follow the numbers.
//
// Specification (docs/setup.md):
//   - AXI4-Stream source rules on the descriptor side: once m_axis_tvalid is 1 it stays 1, with m_axis_tdata
//     and m_axis_tuser unchanged, until m_axis_tready (a reset may drop it);
//   - every accepted beat gives exactly one descriptor, in order: the descriptor out is the f_out-th accepted
//     beat's (its n is f_out), never one that was not accepted (f_out != f_acc), none lost (the credit
//     counter is the number of beats in flight, and s_axis_tready only while the FIFO will have room);
//   - no deadlock: while beats are outstanding and the sink is ready, m_axis_tvalid rises within RESP cycles;
//   - reset: m_axis_tvalid = 0 and s_axis_tready = 0 in the cycle after a reset edge, s_axis_tready in the
//     one after; nothing accepted before the reset comes out after it.
`default_nettype none
`include "spec_params.vh"
`include "setup_params.vh"
module fv_spec_setup (
    input wire                       clk,
    input wire                       rst_n,
    input wire                       s_axis_tvalid,
    input wire [`SETUP_BEAT_W-1:0]   s_axis_tdata,
    input wire                       m_axis_tready
);
    localparam N_W = `SPEC_N_W;
    localparam DESC_W = `SPEC_DESC_W;
    localparam DEPTH = 6;                 // 2^FIFO_AW + 2
    localparam RESP = 12;

    wire s_axis_tready, m_axis_tvalid;
    wire [DESC_W-1:0] m_axis_tdata;
    wire [6:0] m_axis_tuser;
    wire [3:0] cnt;                       // exposed: the credit counter (FIFO_AW + 2 bits)
    wire [2:0] cm;                        // exposed: words in the FIFO's memory
    wire rv, skid_v;                      // exposed: the FIFO's read stage and skid buffer
    wire [2:0] pv;                        // exposed: the stub pipe's valid flags

    fv_core_setup dut (
        .clk(clk), .rst_n(rst_n), .s_axis_tvalid(s_axis_tvalid), .s_axis_tready(s_axis_tready),
        .s_axis_tdata(s_axis_tdata), .m_axis_tvalid(m_axis_tvalid), .m_axis_tready(m_axis_tready),
        .m_axis_tdata(m_axis_tdata), .m_axis_tuser(m_axis_tuser),
        .\g_pipe.cnt (cnt), .\g_pipe.u_fifo.cm (cm), .\g_pipe.u_fifo.rv (rv), .\g_pipe.u_fifo.skid_v (skid_v),
        .\g_pipe.u_pipe.v (pv)
    );

    reg f_past = 1'b0, f_past_2 = 1'b0, f_rst_q = 1'b0, f_rst_q2 = 1'b0;
    always @(posedge clk) begin
        f_past <= 1'b1;
        f_past_2 <= f_past;
        f_rst_q <= rst_n;
        f_rst_q2 <= f_rst_q;
    end
    always @(*) if (!f_past) assume (!rst_n);

    wire accept = s_axis_tvalid & s_axis_tready & rst_n;
    wire hand = m_axis_tvalid & m_axis_tready & rst_n;
    reg [N_W-1:0] f_acc, f_out;           // beats accepted, descriptors handed over (mod 2^N_W)
    reg [4:0] f_wait;
    always @(posedge clk) begin
        if (!rst_n) begin
            f_acc <= 0;
            f_out <= 0;
            f_wait <= 0;
        end else begin
            f_acc <= f_acc + accept;
            f_out <= f_out + hand;
            f_wait <= (f_acc != f_out && m_axis_tready && !m_axis_tvalid) ? f_wait + 1'b1 : 0;
        end
    end
    // the source numbers its beats
    always @(*) if (s_axis_tvalid) assume (s_axis_tdata[`SETUP_BEAT_N_LSB +: N_W] == f_acc);

    reg f_stall_q = 1'b0;
    reg [DESC_W-1:0] f_data_q;
    reg [6:0] f_user_q;
    always @(posedge clk) begin
        f_stall_q <= rst_n & m_axis_tvalid & ~m_axis_tready;
        f_data_q <= m_axis_tdata;
        f_user_q <= m_axis_tuser;
    end
    wire [N_W-1:0] out_n = m_axis_tdata[`SPEC_DESC_N_LSB +: N_W];
    wire [N_W-1:0] inflight = f_acc - f_out;
    always @(*) begin
        if (f_past) begin
            if (f_stall_q) assert (m_axis_tvalid && m_axis_tdata == f_data_q && m_axis_tuser == f_user_q);
            if (!f_rst_q) assert (!m_axis_tvalid && !s_axis_tready);
            if (f_rst_q && !f_rst_q2) assert (s_axis_tready);
            if (m_axis_tvalid) assert (inflight != 0);
`ifndef FV_COUNT_ONLY
            if (m_axis_tvalid) assert (out_n == f_out);
`endif
            assert (f_wait < RESP);
            // credits: the counter is what is in flight, and never more than the FIFO holds
            assert (cnt == inflight && inflight <= DEPTH);
            if (s_axis_tready) assert (inflight < DEPTH);
            assert (cm <= 4);
            // helper: where the spans in flight are
            assert (inflight == pv[0] + pv[1] + pv[2] + cm + rv + skid_v + m_axis_tvalid);
            if (skid_v) assert (m_axis_tvalid);
            if (!f_rst_q) assert (pv == 0 && cm == 0 && !rv && !skid_v && cnt == 0);
        end
    end

    // covers: the FIFO full with the sink stalled, credits used up, a reset with spans in flight
    always @(*) begin
        if (f_past && rst_n) begin
            cover (cm == 4 && skid_v && m_axis_tvalid);
            cover (!s_axis_tready && f_rst_q && f_rst_q2 && inflight == DEPTH);
            cover (hand && f_out == 7);
        end
        if (f_past && !rst_n) cover (inflight >= 3);
    end
endmodule
`default_nettype wire
