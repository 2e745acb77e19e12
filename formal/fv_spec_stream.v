// fv_spec_stream - formal properties of spec_stream (AXI4-Stream, LANES pixels per beat, PACK), checked by
// formal/formal.py (make formal) with yosys-smtbmc and z3 at the reduced widths of formal.py.
//
// The core is `fv_core_stream`: rtl/spec_stream.v at those widths and the job's LANES and PACK, flattened,
// with the span generator's registered enables and their definitions made ports by Yosys `expose`; rtl/ is
// not edited. The datapath's pixel values are cut off and left free (f_px): the properties are about flow
// control. Every input is free: the source may raise and drop s_axis_tvalid as it likes (the core must not
// rely on the source's AXI rules), the sink's m_axis_tready is anything, rst_n is anything after the first
// cycle (0 there).
//
// Specification (docs/stream.md), checked as a black box on the ports:
//   - AXI4-Stream source rules on the pixel side: once m_axis_tvalid is 1 it stays 1, with m_axis_tdata,
//     m_axis_tkeep and m_axis_tlast unchanged, until m_axis_tready (a reset may drop it);
//   - a beat's kept slots are slots 0 .. k-1, k >= 1;
//   - every accepted descriptor gives exactly l + 1 pixels, in the order the descriptors came: the wrapper
//     keeps every accepted descriptor's l (numbered as accepted) and walks the kept slots of each beat through
//     them; a pixel that no descriptor asked for fails. PACK = 0: a span's last pixel is the last kept slot of
//     its beat, tlast is set exactly on such beats, and a beat with empty slots ends a span. PACK = 1: tlast is
//     set exactly on the beats that hold a span's last pixel;
//   - no deadlock: while spans are outstanding and the sink is ready, m_axis_tvalid rises within RESP cycles;
//   - reset: m_axis_tvalid = 0 from the cycle after a reset edge, s_axis_tready 0 in that cycle and 1 in the
//     next; nothing accepted before the reset comes out after it;
//   - the span generator's registered enables equal their definitions (tk = ce & room & prep_v,
//     pl = ~prep_v | tk; rtl/spec_spangen.v).
// These are checked by bounded model checking from reset (formal.py's bmc cycles) and reached by covers.
// For LANES = 1 the wrapper also asserts helper invariants over the core's internal state (below: a shadow of
// the walk per pipeline position, the skid buffer, the running span, prep, head and tail tied to f_l, the
// no-deadlock distance), which make every assertion inductive with k = 1: with the base case, the properties
// hold for traces of any length (formal.py's spec_stream job; its induction step asks one query per
// assertion, formal/induct.py). LANES = 2 and 4 are bounded checks.
`default_nettype none
`include "spec_params.vh"
module fv_spec_stream #(
    parameter LANES = 1,
    parameter PACK = 0
) (
    input wire         clk,
    input wire         rst_n,
    input wire         s_axis_tvalid,
    input wire [`SPEC_DESC_W-1:0] s_axis_tdata,
    input wire         m_axis_tready,
    input wire [LANES*`SPEC_OUT_W-1:0] f_px    // free: the datapath's pixel values (cut off, see formal.py)
);
    localparam L_W = `SPEC_L_W;
    localparam OUT_W = `SPEC_OUT_W;
    localparam NC = `SPEC_STREAM_LATENCY - 4;             // the pipeline's stages of ce (accumulator, datapath)
    // descriptor numbers: fewer than 2^IW spans in flight. With LANES = 1 at most NC + 7 (one a position of the
    // NC + 1 below, the output register, the skid buffer, R, prep, head and tail): 5 bits for patent mode's
    // pipeline, 6 for pow mode's longer one (NC = 30 at formal.py's widths). LANES = 2 and 4 are bounded
    // checks that accept fewer than 2^IW descriptors in their cycles.
    localparam IW = (NC + 7 < 32) ? 5 : 6;
    localparam WW = 7;                                    // the no-deadlock counter
    localparam RESP = `SPEC_STREAM_LATENCY + 2;           // bound of the no-deadlock property

    localparam SH = (LANES == 4) ? 2 : (LANES == 2) ? 1 : 0;
    localparam QW = L_W - SH;                             // the span generator's beat counter
    localparam NG = (L_W > 4) ? (L_W - 4 + 3) / 4 : 1;    // spec_spangen's zero flags of l
    localparam LI = (LANES > 2) ? 2 : 1;
    localparam DW = `SPEC_C_W + `SPEC_N_W + L_W + NG + 2 * `SPEC_ANG_W;   // a descriptor in the buffer

    wire s_axis_tready, m_axis_tvalid, m_axis_tlast;
    wire [LANES*OUT_W-1:0] m_axis_tdata;
    wire [LANES-1:0] m_axis_tkeep;
    // internals (Yosys `expose`)
    wire ce, tk, pl, pl_n, room, prep_v, head_v, tail_v, have_q, skid_v, skid_last;
    wire r_v, r_ntk, r_last1_bc, r_second;
    wire [LI-1:0] r_end, r_s;
    wire [QW-1:0] bc, r_nt2, prep_nlqm1, prep_nlqm2;
    wire prep_lq0, prep_lq1, prep_lq2p;
    wire [1:0] prep_lr;
    wire [L_W-1:0] head_l;
    wire [NG-1:0] head_zg;
    wire [DW-1:0] tail;
    wire [LANES-1:0] bv, blst, skid_keep;
    wire [NC*LANES-1:0] ctl_v, ctl_l;

    fv_core_stream dut (
        .clk(clk), .rst_n(rst_n), .s_axis_tvalid(s_axis_tvalid), .s_axis_tready(s_axis_tready),
        .s_axis_tdata(s_axis_tdata), .m_axis_tvalid(m_axis_tvalid), .m_axis_tready(m_axis_tready),
        .m_axis_tdata(m_axis_tdata), .m_axis_tkeep(m_axis_tkeep), .m_axis_tlast(m_axis_tlast),
        .\dp_out.i (f_px), .dp_out(), .ce(ce), .\u_gen.tk (tk), .\u_gen.pl (pl), .\u_gen.pl_n (pl_n),
        .\u_gen.room (room), .\u_gen.prep_v (prep_v), .\u_gen.head_v (head_v), .\u_gen.tail_v (tail_v),
        .\u_gen.head_l (head_l), .\u_gen.head_zg (head_zg), .\u_gen.tail (tail),
        .\u_gen.prep_lq0 (prep_lq0), .\u_gen.prep_lq1 (prep_lq1), .\u_gen.prep_lq2p (prep_lq2p),
        .\u_gen.prep_nlqm1 (prep_nlqm1), .\u_gen.prep_nlqm2 (prep_nlqm2), .\u_gen.prep_lr (prep_lr),
        .\u_gen.r_v (r_v), .\u_gen.r_ntk (r_ntk), .\u_gen.r_last1_bc (r_last1_bc), .\u_gen.r_second (r_second),
        .\u_gen.r_end (r_end), .\u_gen.r_s (r_s), .\u_gen.bc (bc), .\u_gen.r_nt2 (r_nt2),
        .\u_gen.bv (bv), .\u_gen.blst (blst), .ctl_v(ctl_v), .ctl_l(ctl_l), .\u_out.have_q (have_q),
        .\u_out.skid_v (skid_v), .\u_out.skid_keep (skid_keep), .\u_out.skid_last (skid_last)
    );
    wire [L_W-1:0] d_l = s_axis_tdata[`SPEC_DESC_L_LSB +: L_W];

    // ---- the interface's model ---------------------------------------------------------------------------
    reg f_past = 1'b0, f_past_2 = 1'b0;
    reg f_rst_q = 1'b0;          // rst_n in the cycle before
    reg f_rst_q2 = 1'b0;         // rst_n two cycles before
    always @(posedge clk) begin
        f_past <= 1'b1;
        f_past_2 <= f_past;
        f_rst_q <= rst_n;
        f_rst_q2 <= f_rst_q;
    end
    always @(*) if (!f_past) assume (!rst_n);   // the first cycle is a reset

    wire accept = s_axis_tvalid & s_axis_tready & rst_n;
    wire beat = m_axis_tvalid & m_axis_tready & rst_n;
    reg [IW-1:0] f_acc;          // descriptors accepted since reset (mod 2^IW): the next one's number
    reg [IW-1:0] f_ended;        // spans whose last pixel is out: the number of the span now out
    reg [L_W:0] f_run;           // pixels of that span out so far
    reg [WW-1:0] f_wait;         // cycles the sink was ready, spans were outstanding and no beat came
    reg [L_W-1:0] f_l[0:(1 << IW) - 1];   // l of every accepted descriptor, by number
    always @(posedge clk) if (accept) f_l[f_acc] <= d_l;

    // the beat's kept slots walked through the descriptors: what comes after the beat, and what it shows
    reg [IW-1:0] e_id;
    reg [L_W:0] e_run;
    reg b_extra;                 // a pixel while no span is outstanding
    reg b_ends;                  // the beat holds a span's last pixel
    reg b_ends_mid;              // ... in a slot before its last kept one
    reg b_ends_last;             // ... in its last kept slot
    reg b_over;                  // a pixel beyond its span's l (helper invariant)
    integer j;
    always @(*) begin
        e_id = f_ended;
        e_run = f_run;
        b_extra = 1'b0;
        b_ends = 1'b0;
        b_ends_mid = 1'b0;
        b_ends_last = 1'b0;
        b_over = 1'b0;
        for (j = 0; j < LANES; j = j + 1) begin
            if (m_axis_tkeep[j]) begin
                if (e_id == f_acc) b_extra = 1'b1;
                if (e_run > {1'b0, f_l[e_id]}) b_over = 1'b1;
                if (e_run == {1'b0, f_l[e_id]}) begin
                    b_ends = 1'b1;
                    if (j + 1 < LANES && m_axis_tkeep[(j + 1 < LANES) ? j + 1 : j]) b_ends_mid = 1'b1;
                    else b_ends_last = 1'b1;
                    e_id = e_id + 1'b1;
                    e_run = 0;
                end else begin
                    e_run = e_run + 1'b1;
                end
            end
        end
    end
    wire [LANES:0] keep_x = {1'b0, m_axis_tkeep};
    wire keep_ok = (m_axis_tkeep != 0) && ((keep_x & (keep_x + 1'b1)) == 0);   // slots 0 .. k-1
    wire keep_all = &m_axis_tkeep;

    always @(posedge clk) begin
        if (!rst_n) begin
            f_acc <= 0;
            f_ended <= 0;
            f_run <= 0;
            f_wait <= 0;
        end else begin
            f_acc <= f_acc + accept;
            if (beat) begin
                f_ended <= e_id;
                f_run <= e_run;
            end
            f_wait <= (f_acc != f_ended && m_axis_tready && !m_axis_tvalid) ? f_wait + 1'b1 : 0;
        end
    end

    // ---- properties ----------------------------------------------------------------------------------------
    reg f_stall_q = 1'b0;        // the previous cycle: a beat offered and not taken, no reset
    reg [LANES*OUT_W-1:0] f_data_q;
    reg [LANES-1:0] f_keep_q;
    reg f_last_q;
    always @(posedge clk) begin
        f_stall_q <= rst_n & m_axis_tvalid & ~m_axis_tready;
        f_data_q <= m_axis_tdata;
        f_keep_q <= m_axis_tkeep;
        f_last_q <= m_axis_tlast;
    end
    always @(*) begin
        if (f_past) begin
            // AXI4-Stream: valid held until ready, data, keep and last stable while stalled
            if (f_stall_q) begin
                assert (m_axis_tvalid && m_axis_tdata == f_data_q && m_axis_tkeep == f_keep_q &&
                        m_axis_tlast == f_last_q);
            end
            // reset: no beat and no tready in the next cycle, tready in the one after
            if (!f_rst_q) assert (!m_axis_tvalid && !s_axis_tready);
            if (f_rst_q && !f_rst_q2) assert (s_axis_tready);
            // the registered enables are their definitions
            if (f_rst_q && rst_n) assert (tk == (ce & room & prep_v) && pl == (~prep_v | tk));
`ifndef FV_NO_WAIT
            // no deadlock
            assert (f_wait < RESP);
`endif
        end
        if (f_past && m_axis_tvalid) begin
            assert (keep_ok);
            assert (!b_extra);                            // only pixels that spans asked for
            if (PACK == 0) begin
                assert (!b_ends_mid);                     // a beat holds one span's pixels
                assert (m_axis_tlast == b_ends_last);     // tlast on a span's last beat only
                if (!keep_all) assert (b_ends_last);      // empty slots only after a span's last pixel
            end else begin
                assert (m_axis_tlast == b_ends);          // tlast on the beats that end spans
            end
        end
    end

    // ---- helper invariants (for the induction step) --------------------------------------------------------
    // Where every pixel is, oldest first: the output register, the skid buffer (beats with a beat-level last),
    // the pipeline's stages NC .. 1 and the span generator's presented beat (a valid and a last flag per slot),
    // the rest of the running span R, prep, head, tail. Walking through them from the pixel last out (f_ended,
    // f_run) gives every valid slot the span and pixel number it must hold; its last flag must say whether it
    // is that span's (l + 1)-th (l from f_l), and after the walk R, prep, head and tail hold the next spans in
    // order up to the last accepted one (f_acc).
    // They are written for LANES = 1 (the running span R's registers of the one-slot generator); with LANES = 2
    // and 4 they are not asserted (f_hp = 0), and those jobs are bounded checks of the properties above.
`ifdef FV_NO_HELPERS
    wire f_hp = 1'b0;        // covers and mutants (formal.py's lean_defines): the properties only
`else
    wire f_hp = f_past && LANES == 1;
`endif
    wire [IW-1:0] o_id = m_axis_tvalid ? e_id : f_ended;   // after the output register
    wire [L_W:0] o_run = m_axis_tvalid ? e_run : f_run;
    reg [IW-1:0] k_id;
    reg [L_W:0] k_run;
    reg k_extra, k_ends, k_ends_mid, k_ends_last, k_over;
    always @(*) begin
        k_id = o_id;
        k_run = o_run;
        k_extra = 1'b0;
        k_ends = 1'b0;
        k_ends_mid = 1'b0;
        k_ends_last = 1'b0;
        k_over = 1'b0;
        for (j = 0; j < LANES; j = j + 1) begin
            if (skid_keep[j]) begin
                if (k_id == f_acc) k_extra = 1'b1;
                if (k_run > {1'b0, f_l[k_id]}) k_over = 1'b1;
                if (k_run == {1'b0, f_l[k_id]}) begin
                    k_ends = 1'b1;
                    if (j + 1 < LANES && skid_keep[(j + 1 < LANES) ? j + 1 : j]) k_ends_mid = 1'b1;
                    else k_ends_last = 1'b1;
                    k_id = k_id + 1'b1;
                    k_run = 0;
                end else begin
                    k_run = k_run + 1'b1;
                end
            end
        end
    end
    wire [LANES:0] skeep_x = {1'b0, skid_keep};
    wire skeep_ok = (skid_keep != 0) && ((skeep_x & (skeep_x + 1'b1)) == 0);

    // the slots with their own flags: position p = 0 .. NC - 1 is the pipeline's stage NC - p, p = NC the
    // presented beat; slot j of position p at [p * LANES + j]
    localparam NP = NC + 1;
    wire [NP*LANES-1:0] pv, pls;
    genvar p, q;
    wire [IW-1:0] r_id;
    wire [L_W:0] r_run;
    generate
        for (p = 0; p < NC; p = p + 1) begin : g_pos
            assign pv[p*LANES +: LANES] = ctl_v[(NC-1-p)*LANES +: LANES];
            assign pls[p*LANES +: LANES] = ctl_l[(NC-1-p)*LANES +: LANES];
        end
    endgenerate
    assign pv[NC*LANES +: LANES] = bv;
    assign pls[NC*LANES +: LANES] = blst;
    // the shadow: the walk's value at the start of each position (the span and pixel its slot 0 must hold if
    // valid), moved along by the pipeline's own enable; the walk within a position is computed from it, so every
    // invariant below relates one position to its neighbour
    reg [NP*IW-1:0] sh_id;
    reg [NP*(L_W+1)-1:0] sh_run;
    wire [IW-1:0] q_id[0:NP*LANES];
    wire [L_W:0] q_run[0:NP*LANES];
    wire [IW-1:0] x_id = skid_v ? k_id : o_id;             // after the output register and the skid buffer
    wire [L_W:0] x_run = skid_v ? k_run : o_run;
    assign q_id[0] = x_id;
    assign q_run[0] = x_run;
    integer i;
    always @(posedge clk) begin
        if (!rst_n) begin
            sh_id <= 0;
            sh_run <= 0;
        end else if (ce) begin
            for (i = 0; i < NP - 1; i = i + 1) begin
                sh_id[i*IW +: IW] <= sh_id[(i+1)*IW +: IW];
                sh_run[i*(L_W+1) +: L_W+1] <= sh_run[(i+1)*(L_W+1) +: L_W+1];
            end
            sh_id[(NP-1)*IW +: IW] <= q_id[NP*LANES];
            sh_run[(NP-1)*(L_W+1) +: L_W+1] <= q_run[NP*LANES];
        end
    end
    generate
        for (q = 0; q < NP * LANES; q = q + 1) begin : g_slot
            wire [IW-1:0] in_id = (q % LANES == 0) ? sh_id[(q / LANES)*IW +: IW] : q_id[q];
            wire [L_W:0] in_run = (q % LANES == 0) ? sh_run[(q / LANES)*(L_W+1) +: L_W+1] : q_run[q];
            wire [L_W-1:0] l = f_l[in_id];
            wire ends = in_run == {1'b0, l};
            wire [IW-1:0] d = in_id - f_ended;
            assign q_id[q + 1] = (pv[q] && ends) ? in_id + 1'b1 : in_id;
            assign q_run[q + 1] = !pv[q] ? in_run : ends ? {(L_W + 1) {1'b0}} : in_run + 1'b1;
            always @(*) begin
                if (f_hp && pv[q]) begin
                    assert (d < f_acc - f_ended);                    // a pixel some span asked for
                    assert (in_run <= {1'b0, l});                    // within its span
                    assert (pls[q] == ends);                         // last flag on the span's last only
                end
            end
        end
        // neighbours: each position starts where the one before ended; no more spans than positions
        for (p = 0; p < NP; p = p + 1) begin : g_link
            wire [IW-1:0] d = sh_id[p*IW +: IW] - f_ended;
            always @(*) begin
                if (f_hp) begin
                    if (p == 0) assert (sh_id[0 +: IW] == x_id && sh_run[0 +: L_W+1] == x_run);
                    else assert (sh_id[p*IW +: IW] == q_id[p*LANES] && sh_run[p*(L_W+1) +: L_W+1] == q_run[p*LANES]);
                    assert (d <= (p + 2) * LANES);
                end
            end
        end
        // each position's beat: kept slots 0 .. k-1 (or none); PACK = 0: one span per beat, ending in its last
        // kept slot when a slot is empty
        for (p = 0; p < NP; p = p + 1) begin : g_beat
            wire [LANES-1:0] v = pv[p*LANES +: LANES];
            wire [LANES-1:0] ls = pls[p*LANES +: LANES];
            wire [LANES:0] vx = {1'b0, v};
            wire [LANES:0] lsx = {1'b0, ls & v};
            always @(*) begin
                if (f_hp) begin
                    assert ((vx & (vx + 1'b1)) == 0);
                    if (PACK == 0) begin
                        assert ((lsx & {1'b0, v[LANES-1:0] >> 1}) == 0);   // no kept slot after a last
                        if (v != 0 && !(&v)) assert ((ls & v & ~(v >> 1)) != 0);   // ends in its last kept slot
                    end
                end
            end
        end
    endgenerate
    // after the presented beat: R has the rest of span r_id, from pixel r_run on (r_run = 0: no span half-way)
    assign r_id = q_id[NP*LANES];
    assign r_run = q_run[NP*LANES];
    wire [L_W-1:0] r_l = f_l[r_id];
    wire r_mid = r_run != {(L_W + 1) {1'b0}};               // a span half-way after the presented beat
    wire [IW-1:0] p_id = r_id + {{(IW - 1) {1'b0}}, r_mid}; // prep's span
    wire [IW-1:0] h_id = p_id + prep_v;                    // the head's
    wire [IW-1:0] t_id = h_id + head_v;                    // the tail's
    wire [IW-1:0] e_next = t_id + tail_v;                  // after all: the next descriptor's number
    wire [L_W-1:0] p_l = f_l[p_id];
    wire [L_W-1:0] t_l = tail[2 * `SPEC_ANG_W + NG +: L_W];
    wire [NG-1:0] t_zg = tail[2 * `SPEC_ANG_W +: NG];
    wire [QW-1:0] p_lq = p_l[L_W-1:SH];
    wire [1:0] p_lr = (LANES == 1) ? 2'd0 : (LANES == 2) ? {1'b0, p_l[0]} : p_l[1:0];
    wire [QW-1:0] r_lq = r_l[L_W-1:SH];
    // the zero flags of l's 4-bit groups above its low four bits (spec_spangen's d_zg)
    function [NG-1:0] zg_of(input [L_W-1:0] lv);
        integer g;
        begin
            for (g = 0; g < NG; g = g + 1) zg_of[g] = (L_W > 4) ? ((lv >> (4 + 4 * g)) & 4'hf) == 0 : 1'b1;
        end
    endfunction
    // cycles of a ready sink until a beat is offered: from the oldest valid position
    wire [WW:0] nr[0:NP];
    assign nr[NP] = prep_v ? NC + 2 : head_v ? NC + 3 : {(WW + 1) {1'b1}};
    generate
        for (p = 0; p < NP; p = p + 1) begin : g_near
            assign nr[p] = pv[p*LANES] ? p + 1 : nr[p + 1];
        end
    endgenerate
    wire [WW:0] near = m_axis_tvalid ? 0 : nr[0];

    always @(*) begin
        if (f_hp) begin
            // the state a reset edge leaves (the first cycle has rst_n = 0)
            if (!f_past_2) assert (!f_rst_q);
            if (!f_rst_q) begin
                assert (!head_v && !tail_v && !prep_v && !r_v && !r_ntk && bv == 0 && ctl_v == 0 && !skid_v);
                assert (!have_q && ce && f_acc == 0 && f_ended == 0 && f_run == 0 && f_wait == 0);
            end
            // the output register and the skid buffer
            if (f_rst_q) assert (s_axis_tready == !tail_v);
            assert (ce == !skid_v);
            assert (have_q == (skid_v | pv[0]));
            if (skid_v) assert (m_axis_tvalid);
            if (m_axis_tvalid) assert (!b_over);
            if (skid_v) begin
                assert (skeep_ok && !k_extra && !k_over);
                if (PACK == 0) begin
                    assert (!k_ends_mid && skid_last == k_ends_last);
                    if (!(&skid_keep)) assert (k_ends_last);
                end else begin
                    assert (skid_last == k_ends);
                end
            end
            if (f_run != 0 && !m_axis_tvalid) assert (f_run <= {1'b0, f_l[f_ended]});
            // the span generator's enables
            assert (tk == (ce & room & prep_v) && pl == (~prep_v | tk) && pl_n == ~pl);
            assert (!r_ntk || r_v);
            // the descriptor buffer
            if (tail_v) assert (head_v);
            if (head_v) assert (head_l == f_l[h_id] && head_zg == zg_of(head_l));
            if (tail_v) assert (t_l == f_l[t_id] && t_zg == zg_of(t_l));
            if (prep_v) begin
                assert (prep_lr == p_lr && prep_lq0 == (p_lq == 0) && prep_lq1 == (p_lq == 1) &&
                        prep_lq2p == (p_lq >= 2));
                assert (prep_nlqm1 == ~(p_lq - 1'b1) && prep_nlqm2 == ~(p_lq - 2'd2));
            end
            // every accepted descriptor is somewhere: numbers from f_ended to f_acc - 1 without a gap
            assert (e_next == f_acc);
`ifndef FV_NO_WAIT
            // how long the sink can wait: the oldest pixel gets one stage closer every cycle
            if (f_acc != f_ended) assert (near <= NC + 3);
            if (f_wait != 0) assert ({1'b0, f_wait} + near <= NC + 3);
`endif
        end
    end
    // the running span R (one slot per beat)
    generate
        if (LANES == 1) begin : g_r1
            always @(*) begin
                if (f_hp) begin
                    assert (r_v == r_mid);
                    if (r_v) begin
                        assert (bv[0] && r_run <= {1'b0, r_l});
                        assert (bc == r_run - 1'b1 && r_nt2 == ~(r_lq - 2'd2));
                        assert ((r_ntk ? r_last1_bc : 1'b1) == (r_run == {1'b0, r_l}));
                        if (!r_ntk) assert (!r_last1_bc);
                    end
                end
            end
        end
    endgenerate

    // ---- covers ----------------------------------------------------------------------------------------------
    reg [IW-1:0] f_ended_q;
    reg f_stall_last = 1'b0;     // the sink stalled on a beat with tlast
    always @(posedge clk) begin
        f_ended_q <= f_ended;
        if (!rst_n) f_stall_last <= 1'b0;
        else if (m_axis_tvalid && m_axis_tlast && !m_axis_tready) f_stall_last <= 1'b1;
    end
    always @(*) begin
        if (f_past && rst_n) begin
            cover (beat && m_axis_tlast && f_l[f_ended] == {L_W{1'b1}} && f_stall_last);  // longest span, stalled
            cover (f_ended == 3 && f_ended_q == 2);               // three spans through
            cover (f_acc - f_ended >= 6);                         // six spans in flight
        end
        if (f_past && !rst_n) cover (f_acc - f_ended >= 3);      // reset with three spans in flight
    end
    generate
        if (PACK != 0) begin : g_cover_pack
            always @(*) if (f_past && rst_n) cover (beat && e_id - f_ended >= 2);   // two spans end in one beat
        end
    endgenerate
endmodule
`default_nettype wire
