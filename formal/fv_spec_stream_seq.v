// fv_spec_stream_seq - formal properties of spec_stream_seq (the compact streaming back end: spec_stream's ports
// and AXI4-Stream rules with LANES = 1, one span at a time), proved by formal/formal.py (make formal-shader) with
// yosys-smtbmc and z3 at the reduced widths of formal.py.
//
// The core is `fv_core_stream_seq`: rtl/spec_stream_seq.v at those widths, flattened, with the span generator's
// registers, the datapath's valid and last flags (spec_datapath's valid pipeline)
// and the output's skid buffer made ports by Yosys `expose`; rtl/ is not edited. The datapath's pixel value is
// cut off and left free (f_px): the properties are about flow control. Every input is free: the source may
// raise and drop s_axis_tvalid as it likes, the sink's m_axis_tready is anything, rst_n is anything after
// the first cycle (0 there).
//
// Specification (spec_stream_seq.v's header, docs/stream.md):
//   - AXI4-Stream source rules on the pixel side: once m_axis_tvalid is 1 it stays 1, with m_axis_tdata,
//     m_axis_tkeep and m_axis_tlast unchanged, until m_axis_tready (a reset may drop it); m_axis_tkeep = 1;
//   - every accepted descriptor gives exactly l + 1 pixels, spans in the order accepted, m_axis_tlast on each
//     span's last pixel only, no pixel that no descriptor asked for: the wrapper keeps every accepted
//     descriptor's l by number and counts the pixels out;
//   - one span at a time: s_axis_tready only when no span is being generated and the datapath is empty;
//   - no deadlock: while spans are outstanding and the sink is ready, m_axis_tvalid rises within RESP cycles
//     (the first pixel's latency, LAT + 2);
//   - reset: m_axis_tvalid = 0 and s_axis_tready = 0 in the cycle after a reset edge, s_axis_tready in the one
//     after; nothing accepted before the reset comes out after it.
// The helper invariants (below: every valid pixel of the output register, the skid buffer, the datapath's
// stages and the generator tied to its span and place by walking from the last pixel out) make the
// properties inductive with k = 1: proved for traces of any length (formal.py's spec_stream_seq job).
`default_nettype none
`include "spec_params.vh"
module fv_spec_stream_seq (
    input wire         clk,
    input wire         rst_n,
    input wire         s_axis_tvalid,
    input wire [`SPEC_DESC_W-1:0] s_axis_tdata,
    input wire         m_axis_tready,
    input wire [`SPEC_OUT_W-1:0] f_px    // free: the datapath's pixel value (cut off, see formal.py)
);
    localparam L_W = `SPEC_L_W;
    localparam OUT_W = `SPEC_OUT_W;
    localparam LAT = `SPEC_DATAPATH_LATENCY;   // spec_datapath with PIPE = 0 (Format::datapath_latency)
    localparam IW = 3;                   // descriptor numbers (at most three spans in flight)
    localparam RESP = LAT + 2;

    wire s_axis_tready, m_axis_tvalid, m_axis_tlast, m_axis_tkeep;
    wire [OUT_W-1:0] m_axis_tdata;
    // internals (Yosys `expose`)
    wire ready_q, run, ce, have_q, skid_v, skid_keep, skid_last;
    wire [L_W-1:0] cnt;
    wire [LAT:1] vs;                     // the datapath's valid flags (stage s: entered s clocks of ce ago)
    wire [LAT:1] ls_q;                   // their last flags (stage s at bit s)
    wire [LAT-1:0] ls = ls_q[LAT:1];     // ls[s - 1]: stage s's
    fv_core_stream_seq dut (
        .clk(clk), .rst_n(rst_n), .s_axis_tvalid(s_axis_tvalid), .s_axis_tready(s_axis_tready),
        .s_axis_tdata(s_axis_tdata), .m_axis_tvalid(m_axis_tvalid), .m_axis_tready(m_axis_tready),
        .m_axis_tdata(m_axis_tdata), .m_axis_tkeep(m_axis_tkeep), .m_axis_tlast(m_axis_tlast),
        .\dp_out.i (f_px), .dp_out(), .ready_q(ready_q), .run(run), .cnt(cnt), .ce(ce),
        .\u_dp.g_ctrl.vs_q (vs),
        .\u_dp.g_ctrl.ls_q (ls_q),
        .\u_out.have_q (have_q), .\u_out.skid_v (skid_v), .\u_out.skid_keep (skid_keep),
        .\u_out.skid_last (skid_last)
    );
    wire [L_W-1:0] d_l = s_axis_tdata[`SPEC_DESC_L_LSB +: L_W];

    // ---- the interface's model ---------------------------------------------------------------------------
    reg f_past = 1'b0, f_past_2 = 1'b0, f_rst_q = 1'b0, f_rst_q2 = 1'b0;
    always @(posedge clk) begin
        f_past <= 1'b1;
        f_past_2 <= f_past;
        f_rst_q <= rst_n;
        f_rst_q2 <= f_rst_q;
    end
    always @(*) if (!f_past) assume (!rst_n);

    wire accept = s_axis_tvalid & s_axis_tready & rst_n;
    wire beat = m_axis_tvalid & m_axis_tready & rst_n;
    reg [IW-1:0] f_acc;          // descriptors accepted since reset (mod 2^IW): the next one's number
    reg [IW-1:0] f_ended;        // spans whose last pixel is out: the number of the span now out
    reg [L_W:0] f_run;           // pixels of that span out so far
    reg [4:0] f_wait;            // cycles the sink was ready, spans were outstanding and no pixel offered
    reg [L_W-1:0] f_l[0:(1 << IW) - 1];   // l of every accepted descriptor, by number
    always @(posedge clk) if (accept) f_l[f_acc] <= d_l;
    wire b_last = f_run == {1'b0, f_l[f_ended]};   // the pixel out is its span's last
    always @(posedge clk) begin
        if (!rst_n) begin
            f_acc <= 0;
            f_ended <= 0;
            f_run <= 0;
            f_wait <= 0;
        end else begin
            f_acc <= f_acc + accept;
            if (beat) begin
                f_ended <= f_ended + b_last;
                f_run <= b_last ? {(L_W + 1) {1'b0}} : f_run + 1'b1;
            end
            f_wait <= (f_acc != f_ended && m_axis_tready && !m_axis_tvalid) ? f_wait + 1'b1 : 5'd0;
        end
    end
    wire [IW-1:0] outst = f_acc - f_ended;

    // ---- properties ----------------------------------------------------------------------------------------
    reg f_stall_q = 1'b0;
    reg [OUT_W-1:0] f_data_q;
    reg f_keep_q, f_last_q;
    always @(posedge clk) begin
        f_stall_q <= rst_n & m_axis_tvalid & ~m_axis_tready;
        f_data_q <= m_axis_tdata;
        f_keep_q <= m_axis_tkeep;
        f_last_q <= m_axis_tlast;
    end
    always @(*) begin
        if (f_past) begin
            if (f_stall_q) assert (m_axis_tvalid && m_axis_tdata == f_data_q && m_axis_tkeep == f_keep_q &&
                                   m_axis_tlast == f_last_q);
            if (!f_rst_q) assert (!m_axis_tvalid && !s_axis_tready);
            if (f_rst_q && !f_rst_q2) assert (s_axis_tready);
            if (m_axis_tvalid) begin
                assert (m_axis_tkeep);
                assert (outst != 0);                      // only pixels that spans asked for
                assert (m_axis_tlast == b_last);          // tlast on a span's last pixel only
            end
            if (s_axis_tready) assert (!run && vs == 0);  // one span at a time
            assert (f_wait < RESP);                       // no deadlock
        end
    end

    // ---- helper invariants (for the induction step) --------------------------------------------------------
    // Oldest first: the output register and the skid buffer (pixels of up to two spans), then the datapath's
    // stages LAT .. 1 and the generator, which hold one span only (a descriptor is taken when the datapath is
    // empty). Walking the output register and the skid buffer from the pixel after the last one out (f_ended,
    // f_run) gives each valid one its span and pixel number (and so its last flag); the datapath and the
    // generator then hold the rest of that span, x_id: its pixels x_run .. l, in the stages as one block of
    // valid flags (from stage 1 up while the span is generated) and cnt + 1 in the generator; the last flag is
    // on the block's youngest stage once the generator is done, else nowhere.
    reg [IW-1:0] x_id;
    reg [L_W:0] x_run;
    reg w_bad;                           // a valid pixel that no span asked for, beyond its span, or its last
    integer w_p;                         // flag wrong
    reg w_v, w_l;
    always @(*) begin
        x_id = f_ended;
        x_run = f_run;
        w_bad = 1'b0;
        for (w_p = 0; w_p < 2; w_p = w_p + 1) begin
            w_v = (w_p == 0) ? m_axis_tvalid : skid_v;
            w_l = (w_p == 0) ? m_axis_tlast : skid_last;
            if (w_v) begin
                if (x_id == f_acc || x_run > {1'b0, f_l[x_id]}) w_bad = 1'b1;
                if (w_l != (x_run == {1'b0, f_l[x_id]})) w_bad = 1'b1;
                if (x_run == {1'b0, f_l[x_id]}) begin
                    x_id = x_id + 1'b1;
                    x_run = 0;
                end else begin
                    x_run = x_run + 1'b1;
                end
            end
        end
    end
    wire [L_W-1:0] x_l = f_l[x_id];
    reg [4:0] n_dp;                      // valid stages
    integer s;
    always @(*) begin
        n_dp = 0;
        for (s = 1; s <= LAT; s = s + 1) n_dp = n_dp + vs[s];
    end
    wire [LAT:0] vx = {1'b0, vs};
    wire [LAT:0] v_low = vx & (~vx + 1'b1);                // the youngest valid stage's flag
    wire [LAT-1:0] ls_v = ls & vs;                         // the valid stages' last flags
    wire [5:0] n_left = {1'b0, n_dp} + (run ? {2'b00, cnt} + 6'd1 : 6'd0);   // the span's pixels not yet out
    // cycles of a ready sink until a pixel is offered: from the oldest valid position
    reg [4:0] near;
    always @(*) begin
        near = run ? LAT + 1 : 5'd31;
        for (s = 1; s <= LAT; s = s + 1) if (vs[s]) near = LAT - s + 1;
        if (m_axis_tvalid) near = 0;
    end
`ifdef FV_NO_HELPERS
    wire f_hp = 1'b0;        // covers and mutants (formal.py's lean_defines): the properties only
`else
    wire f_hp = f_past;
`endif
    always @(*) begin
        if (f_hp) begin
            if (!f_past_2) assert (!f_rst_q);
            if (!f_rst_q) assert (!run && vs == 0 && !skid_v && !have_q && ce && f_acc == 0 && f_ended == 0 &&
                                  f_run == 0 && f_wait == 0);
            assert (!w_bad);
            assert (outst <= 3);           // the output register, the skid buffer, the datapath: a span each
            if (outst == 0) assert (f_run == 0);
            else assert (f_run <= {1'b0, f_l[f_ended]});
            if (run || vs != 0) begin
                assert (x_id != f_acc && x_id + 1'b1 == f_acc && x_run <= {1'b0, x_l});
                assert (n_left == {2'b00, x_l} + 6'd1 - {1'b0, x_run});
            end else begin
                assert (x_run == 0 && x_id == f_acc);          // every accepted span's pixels out
            end
            if (run) assert ((vx & (vx + 1'b1)) == 0 && ls_v == 0);    // a block from stage 1 up, no last yet
            else assert (((vx + v_low) & vx) == 0 && {1'b0, ls_v} == v_low);   // the last the youngest
            if (ready_q) assert (!run && vs == 0);
            // the output register and the skid buffer
            assert (ce == !skid_v);
            assert (have_q == (skid_v | vs[LAT]));
            if (skid_v) assert (m_axis_tvalid && skid_keep);
            // how long the sink can wait: the oldest pixel gets one stage closer every cycle
            if (outst != 0) assert (near <= LAT + 1);
            if (f_wait != 0) assert (f_wait + near <= LAT + 1);
        end
    end

    // ---- covers ----------------------------------------------------------------------------------------------
    reg f_stall_last = 1'b0;     // the sink stalled on a pixel with tlast
    always @(posedge clk) begin
        if (!rst_n) f_stall_last <= 1'b0;
        else if (m_axis_tvalid && m_axis_tlast && !m_axis_tready) f_stall_last <= 1'b1;
    end
    always @(*) begin
        if (f_past && rst_n) begin
            cover (beat && m_axis_tlast && f_l[f_ended] == {L_W{1'b1}} && f_stall_last);  // longest span, stalled
            cover (f_ended == 1 && beat && f_run == 1);           // the second pixel of the second span
            cover (outst == 3);                                   // two spans in the output, one in the datapath
        end
        if (f_past && !rst_n) cover (outst != 0);                 // reset with a span in flight
    end
endmodule
`default_nettype wire
