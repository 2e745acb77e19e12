// fv_spec_stream - formal properties of spec_stream (AXI4-Stream, one pixel per clock), proved by
// formal/formal.py (make formal) with yosys-smtbmc and z3 at the reduced widths of formal.py.
//
// The core is `fv_core_stream`: rtl/spec_stream.v at those widths, flattened, with the registers that say
// where pixels and spans are (descriptor buffer, span generator, valid and `last` flags of every pipeline
// stage, skid buffer) made ports by Yosys `expose`; rtl/ is not edited. Every input is free: the source may
// raise and drop s_axis_tvalid as it likes (the core must not rely on the source's AXI rules), the sink's
// m_axis_tready is anything, rst_n is anything after the first cycle (0 there).
//
// Specification (docs/stream.md):
//   - AXI4-Stream source rules on the pixel side: once m_axis_tvalid is 1 it stays 1, with m_axis_tdata
//     and m_axis_tlast unchanged, until m_axis_tready (a reset may drop it);
//   - every accepted descriptor (s_axis_tvalid & s_axis_tready) gives exactly l + 1 pixels, in the order
//     the descriptors came, with m_axis_tlast on the last one only: descriptors are numbered as they are
//     accepted, spans as they end (tlast beats); a pixel on the output belongs to span number f_ended, is its
//     f_run-th pixel, and carries tlast exactly when f_run = l of that descriptor. The descriptor's number
//     and l reach the output through a shadow of the core's registers (see below);
//   - no pixel that no descriptor asked for; no descriptor lost: the numbers of the spans in flight run
//     from f_ended to the last accepted one without a gap (s_axis_tready only while the buffer has room);
//   - no deadlock: while spans are outstanding and the sink is ready, m_axis_tvalid rises within NS cycles
//     (NS = the pipeline's stages from the span generator to the output);
//   - reset: m_axis_tvalid = 0 from the cycle after a reset edge, s_axis_tready 0 in that cycle and 1 in
//     the next; nothing accepted before the reset comes out after it.
// The shadow: each stage of the core (buffer entries, the span generator's pixel, accumulator and datapath
// stages, skid buffer, output register) gets shadow registers holding the number of the descriptor its
// pixel belongs to, that descriptor's l and the pixel's number within its span, loaded by the core's own
// enables (take, step, ce, o_load, the buffer's loads) from the stage before; a pixel the core drops,
// duplicates or reorders does the same to its shadow, and the invariants catch it: going from the output
// towards the input, each valid stage continues the sequence of the one before (same span and next pixel,
// or the next span's first pixel right after a last), its `last` flag says whether it is its span's
// (l + 1)-th, and the sequence ends at the last accepted descriptor. Every invariant is local (a stage and
// its neighbour), which keeps the induction step easy for the solver.
`default_nettype none
`include "spec_params.vh"
module fv_spec_stream (
    input wire         clk,
    input wire         rst_n,
    input wire         s_axis_tvalid,
    input wire [`SPEC_DESC_W-1:0] s_axis_tdata,
    input wire         m_axis_tready,
    input wire [`SPEC_OUT_W-1:0] f_px    // free: the datapath's pixel value (cut off, see formal.py)
);
    localparam C_W = `SPEC_C_W;
    localparam ANG_W = `SPEC_ANG_W;
    localparam N_W = `SPEC_N_W;
    localparam L_W = `SPEC_L_W;
    localparam OUT_W = `SPEC_OUT_W;
    localparam SCALE_W = `SPEC_SCALE_W;
    localparam TSEL_W = `SPEC_TSEL_W;
    localparam LAT = `SPEC_DATAPATH_LATENCY;              // spec_datapath's stages
    localparam ACC = `SPEC_STREAM_ACC;                    // spec_saccum's stages
    localparam SIDE_W = 1 + C_W + SCALE_W + TSEL_W;       // {last, C, scale, table} beside the accumulator
    localparam DW = C_W + N_W + L_W + 1 + 2 * ANG_W;      // a descriptor in the buffer
    localparam NS = 2 + LAT + ACC;                        // pixel stages: output, skid, datapath, accumulator
    localparam IW = 5;                                    // descriptor numbers (at most NS + 3 in flight)
    localparam WW = 6;                                    // the no-deadlock counter
    localparam RESP = NS + 1;                             // bound of the no-deadlock property

    wire s_axis_tready, m_axis_tvalid, m_axis_tlast;
    wire [OUT_W-1:0] m_axis_tdata;
    // internals (Yosys `expose`)
    wire head_v, tail_v, ready_q, head_single, cur_v, cur_last, skid_v, skid_last;
    wire ce, take, step, o_load, head_load;
    wire [L_W-1:0] head_l, cur_cnt;
    wire [DW-1:0] tail;
    wire [ACC:1] v8;
    wire [LAT:1] vs;
    wire [SIDE_W-1:0] side[0:ACC-1];
    wire dpl[0:LAT-1];

    fv_core_stream dut (
        .clk(clk), .rst_n(rst_n), .s_axis_tvalid(s_axis_tvalid), .s_axis_tready(s_axis_tready),
        .s_axis_tdata(s_axis_tdata), .m_axis_tvalid(m_axis_tvalid), .m_axis_tready(m_axis_tready),
        .m_axis_tdata(m_axis_tdata), .m_axis_tlast(m_axis_tlast), .\dp_out.i (f_px), .dp_out(),
        .head_v(head_v), .tail_v(tail_v), .ready_q(ready_q), .head_l(head_l), .head_single(head_single),
        .tail(tail), .cur_v(cur_v), .cur_cnt(cur_cnt), .cur_last(cur_last), .v8(v8), .\u_dp.vs (vs),
        .skid_v(skid_v), .skid_last(skid_last), .ce(ce), .take(take), .step(step), .o_load(o_load),
        .head_load(head_load),
        .\u_side8.g_regs.r[0] (side[0]), .\u_side8.g_regs.r[1] (side[1]), .\u_side8.g_regs.r[2] (side[2]),
        .\u_side8.g_regs.r[3] (side[3]),
        .\u_dp.u_last.g_regs.r[0] (dpl[0]), .\u_dp.u_last.g_regs.r[1] (dpl[1]),
        .\u_dp.u_last.g_regs.r[2] (dpl[2]), .\u_dp.u_last.g_regs.r[3] (dpl[3]),
        .\u_dp.u_last.g_regs.r[4] (dpl[4]), .\u_dp.u_last.g_regs.r[5] (dpl[5]),
        .\u_dp.u_last.g_regs.r[6] (dpl[6]), .\u_dp.u_last.g_regs.r[7] (dpl[7]),
        .\u_dp.u_last.g_regs.r[8] (dpl[8]), .\u_dp.u_last.g_regs.r[9] (dpl[9]),
        .\u_dp.u_last.g_regs.r[10] (dpl[10]), .\u_dp.u_last.g_regs.r[11] (dpl[11])
    );
    wire [L_W-1:0] tail_l = tail[2 * ANG_W + 1 +: L_W];
    wire tail_single = tail[2 * ANG_W];
    wire [L_W-1:0] d_l = s_axis_tdata[`SPEC_DESC_L_LSB +: L_W];

    // pixel stages, oldest first: 0 output register, 1 skid buffer, 2 .. LAT+1 datapath (stage LAT first),
    // LAT+2 .. NS-1 accumulator (stage ACC first); then the span generator's current pixel, the buffer
    wire [NS-1:0] sv, sl;
    assign sv[0] = m_axis_tvalid;
    assign sl[0] = m_axis_tlast;
    assign sv[1] = skid_v;
    assign sl[1] = skid_last;
    genvar k;
    generate
        for (k = 1; k <= LAT; k = k + 1) begin : g_dp
            assign sv[LAT + 2 - k] = vs[k];
            assign sl[LAT + 2 - k] = dpl[k - 1];
        end
        for (k = 1; k <= ACC; k = k + 1) begin : g_acc
            assign sv[NS - k] = v8[k];
            assign sl[NS - k] = side[k - 1][SIDE_W - 1];
        end
    endgenerate

    // ---- the interface's model ---------------------------------------------------------------------------
    reg f_past = 1'b0, f_past_2 = 1'b0;
    reg f_rst_q = 1'b0;          // rst_n in the cycle before
    always @(posedge clk) begin
        f_past <= 1'b1;
        f_past_2 <= f_past;
        f_rst_q <= rst_n;
    end
    always @(*) if (!f_past) assume (!rst_n);   // the first cycle (and any state before it) is a reset

    wire accept = s_axis_tvalid & s_axis_tready & rst_n;
    wire beat = m_axis_tvalid & m_axis_tready & rst_n;
    wire end_beat = beat & m_axis_tlast;
    reg [IW-1:0] f_acc;          // descriptors accepted since reset (mod 2^IW): the next one's number
    reg [IW-1:0] f_ended;        // spans ended by a tlast beat since reset: the number of the span now out
    reg [L_W:0] f_run;           // pixels of that span out so far
    reg [WW-1:0] f_wait;         // cycles the sink was ready, spans were outstanding and no pixel came
    always @(posedge clk) begin
        if (!rst_n) begin
            f_acc <= 0;
            f_ended <= 0;
            f_run <= 0;
            f_wait <= 0;
        end else begin
            f_acc <= f_acc + accept;
            if (end_beat) begin
                f_ended <= f_ended + 1'b1;
                f_run <= 0;
            end else if (beat) f_run <= f_run + 1'b1;
            f_wait <= (f_acc != f_ended && m_axis_tready && !m_axis_tvalid) ? f_wait + 1'b1 : 0;
        end
    end

    // ---- shadow: every descriptor's number and l, and every pixel's number within its span, carried through
    // the core beside its own registers and moved by the core's own enables (take, step, ce, o_load and the
    // buffer's loads). The invariants below say that the core's valid and last flags agree with the shadow.
    reg [IW-1:0] g_tail_id, g_head_id, g_cur_id;
    reg [L_W-1:0] g_tail_l, g_head_l, g_cur_l;
    reg [L_W:0] g_cur_ix;
    reg [IW-1:0] g_id[0:NS-1];
    reg [L_W-1:0] g_l[0:NS-1];
    reg [L_W:0] g_ix[0:NS-1];
    always @(posedge clk) begin
        if (!tail_v) begin
            g_tail_id <= f_acc;
            g_tail_l <= d_l;
        end
        if (head_load) begin
            g_head_id <= tail_v ? g_tail_id : f_acc;
            g_head_l <= tail_v ? g_tail_l : d_l;
        end
        if (take) begin
            g_cur_id <= g_head_id;
            g_cur_l <= g_head_l;
            g_cur_ix <= 0;
        end else if (step) g_cur_ix <= g_cur_ix + 1'b1;
        if (ce) begin
            g_id[NS - 1] <= g_cur_id;
            g_l[NS - 1] <= g_cur_l;
            g_ix[NS - 1] <= g_cur_ix;
        end
        if (!skid_v) begin
            g_id[1] <= g_id[2];
            g_l[1] <= g_l[2];
            g_ix[1] <= g_ix[2];
        end
        if (o_load) begin
            g_id[0] <= skid_v ? g_id[1] : g_id[2];
            g_l[0] <= skid_v ? g_l[1] : g_l[2];
            g_ix[0] <= skid_v ? g_ix[1] : g_ix[2];
        end
    end
    generate
        for (k = 2; k < NS - 1; k = k + 1) begin : g_shift
            always @(posedge clk) begin
                if (ce) begin
                    g_id[k] <= g_id[k + 1];
                    g_l[k] <= g_l[k + 1];
                    g_ix[k] <= g_ix[k + 1];
                end
            end
        end
    endgenerate

    // ---- properties ----------------------------------------------------------------------------------------
    reg f_rst_q2 = 1'b0;         // rst_n two cycles before
    reg f_stall_q = 1'b0;        // the previous cycle: a pixel offered and not taken, no reset
    reg [OUT_W-1:0] f_data_q;
    reg f_last_q;
    always @(posedge clk) begin
        f_rst_q2 <= f_rst_q;
        f_stall_q <= rst_n & m_axis_tvalid & ~m_axis_tready;
        f_data_q <= m_axis_tdata;
        f_last_q <= m_axis_tlast;
    end
    always @(*) begin
        if (f_past) begin
            // AXI4-Stream: valid held until ready, data and last stable while stalled
            if (f_stall_q) assert (m_axis_tvalid && m_axis_tdata == f_data_q && m_axis_tlast == f_last_q);
            // reset: no pixel and no tready in the next cycle, tready in the one after
            if (!f_rst_q) assert (!m_axis_tvalid && !s_axis_tready);
            if (f_rst_q && !f_rst_q2) assert (s_axis_tready);
        end
    end
    always @(*) begin
        if (f_past && m_axis_tvalid) begin
            // a pixel only when a span is outstanding, and it is the f_run-th pixel of the oldest one,
            // the f_ended-th accepted descriptor (its l carried by the shadow): tlast on the (l + 1)-th only
            assert (f_acc != f_ended);
            assert (g_id[0] == f_ended && g_ix[0] == f_run);
            assert (m_axis_tlast == (f_run == g_l[0]));
        end
        // no deadlock
        if (f_past) assert (f_wait < RESP);
    end

    // ---- helper invariants ---------------------------------------------------------------------------------
    // e_id/e_ix[i]: the descriptor and pixel number the next valid stage from i on must hold, from the pixel
    // last out onwards; after the stages the span generator's pixel, the buffer, and the next accept
    wire [IW-1:0] e_id[0:NS];
    wire [L_W:0] e_ix[0:NS];
    assign e_id[0] = f_ended;
    assign e_ix[0] = f_run;
    generate
        for (k = 0; k < NS; k = k + 1) begin : g_chain
            assign e_id[k + 1] = !sv[k] ? e_id[k] : sl[k] ? g_id[k] + 1'b1 : g_id[k];
            assign e_ix[k + 1] = !sv[k] ? e_ix[k] : sl[k] ? 0 : g_ix[k] + 1'b1;
            always @(*) begin
                if (f_past && sv[k]) begin
                    assert (g_id[k] == e_id[k] && g_ix[k] == e_ix[k]);
                    assert (sl[k] == (g_ix[k] == g_l[k]));
                    if (k > 0 && e_ix[k] != 0) assert (g_l[k] == l_before[k]);
                end
            end
        end
    endgenerate
    // the l of the span of the newest valid stage older than i (for the pixels of one span to agree on it)
    wire [L_W-1:0] l_before[0:NS];
    assign l_before[0] = g_l[0];
    generate
        for (k = 0; k < NS; k = k + 1) begin : g_lb
            assign l_before[k + 1] = sv[k] ? g_l[k] : l_before[k];
        end
    endgenerate
    wire [IW-1:0] e_head = cur_v ? g_cur_id + 1'b1 : e_id[NS];
    wire [IW-1:0] e_tail = head_v ? g_head_id + 1'b1 : e_head;
    wire [IW-1:0] e_next = tail_v ? g_tail_id + 1'b1 : e_tail;
    // near[i]: cycles of a ready sink until the oldest pixel in stages i.. (or the generator, the buffer)
    // is on the output
    wire [WW-1:0] near[0:NS];
    assign near[NS] = cur_v ? NS - 1 : NS;
    generate
        for (k = 0; k < NS; k = k + 1) begin : g_near
            assign near[k] = sv[k] ? ((k == 0) ? 0 : (k == 1) ? 1 : k - 1) : near[k + 1];
        end
    endgenerate

    always @(*) begin
        if (f_past) begin
            if (f_rst_q) assert (ready_q == !tail_v);
            // the state a reset edge leaves (the first cycle has rst_n = 0)
            if (!f_past_2) assert (!f_rst_q);
            assert (f_past || !f_past_2);
            if (!f_rst_q) assert (!head_v && !tail_v && !ready_q && !cur_v && sv == 0 && f_wait == 0);
            if (tail_v) assert (head_v);
            if (skid_v) assert (m_axis_tvalid);
            if (head_v) assert (head_single == (head_l == 0) && head_l == g_head_l);
            if (tail_v) assert (tail_single == (tail_l == 0) && tail_l == g_tail_l);
            if (cur_v) begin
                // the generator's pixel continues the stages' sequence and counts down its span
                assert (g_cur_id == e_id[NS] && g_cur_ix == e_ix[NS]);
                assert (g_cur_ix <= g_cur_l && cur_cnt == g_cur_l - g_cur_ix);
                assert (cur_last == (cur_cnt == 0));
                if (e_ix[NS] != 0) assert (g_cur_l == l_before[NS]);
            end else begin
                assert (e_ix[NS] == 0);   // no span left half-way in the stages
            end
            // the pixel last out (the output register keeps it)
            if (f_run != 0) assert (f_run <= g_l[0]);
            if (f_run != 0 && !m_axis_tvalid) assert (g_id[0] == f_ended && g_ix[0] + 1'b1 == f_run);
            if (head_v) assert (g_head_id == e_head);
            if (tail_v) assert (g_tail_id == e_tail);
            // every accepted descriptor is somewhere: the numbers run from f_ended to f_acc - 1 without a gap
            assert (e_next == f_acc);
            // how long the sink can wait: the nearest pixel gets one stage closer every cycle
            if (f_wait != 0) assert (f_wait + near[0] <= NS);
        end
    end

    // ---- covers ----------------------------------------------------------------------------------------------
    reg [3:0] f_ones = 0;        // one-pixel spans ended on consecutive clocks
    reg f_prev_end = 1'b0;
    reg f_stall_last = 1'b0;     // the sink stalled on a span's last pixel
    always @(posedge clk) begin
        f_prev_end <= end_beat;
        f_ones <= end_beat ? (f_prev_end ? f_ones + 1'b1 : 1) : 0;
        if (!rst_n) f_stall_last <= 1'b0;
        else if (m_axis_tvalid && m_axis_tlast && !m_axis_tready) f_stall_last <= 1'b1;
    end
    always @(*) begin
        if (f_past && rst_n) begin
            cover (end_beat && g_l[0] == {L_W{1'b1}} && f_stall_last);  // longest span, stalled on its last
            cover (f_ones == 4);                                        // l = 0 spans back to back, one a clock
            cover (head_v && tail_v && cur_v && f_acc - f_ended == 6);  // buffer full behind spans in flight
            cover (end_beat && f_ended == 3);                           // three spans through
        end
        if (f_past && !rst_n) cover (f_acc - f_ended >= 3);             // reset with three spans in flight
    end
endmodule
`default_nettype wire
