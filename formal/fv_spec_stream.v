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
// These are checked by bounded model checking from reset (formal.py's bmc cycles) and reached by covers; the
// induction step would need invariants over the core's internal state (as the one-lane core of issue 12 had),
// which are not written for the LANES core (docs/verification.md).
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
    localparam IW = 5;                                    // descriptor numbers (fewer than 2^IW in flight)
    localparam WW = 7;                                    // the no-deadlock counter
    localparam RESP = `SPEC_STREAM_LATENCY + 2;           // bound of the no-deadlock property

    wire s_axis_tready, m_axis_tvalid, m_axis_tlast;
    wire [LANES*OUT_W-1:0] m_axis_tdata;
    wire [LANES-1:0] m_axis_tkeep;
    // internals (Yosys `expose`)
    wire ce, tk, pl, room, prep_v;

    fv_core_stream dut (
        .clk(clk), .rst_n(rst_n), .s_axis_tvalid(s_axis_tvalid), .s_axis_tready(s_axis_tready),
        .s_axis_tdata(s_axis_tdata), .m_axis_tvalid(m_axis_tvalid), .m_axis_tready(m_axis_tready),
        .m_axis_tdata(m_axis_tdata), .m_axis_tkeep(m_axis_tkeep), .m_axis_tlast(m_axis_tlast),
        .\dp_out.i (f_px), .dp_out(), .ce(ce), .\u_gen.tk (tk), .\u_gen.pl (pl), .\u_gen.room (room),
        .\u_gen.prep_v (prep_v)
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
    integer j;
    always @(*) begin
        e_id = f_ended;
        e_run = f_run;
        b_extra = 1'b0;
        b_ends = 1'b0;
        b_ends_mid = 1'b0;
        b_ends_last = 1'b0;
        for (j = 0; j < LANES; j = j + 1) begin
            if (m_axis_tkeep[j]) begin
                if (e_id == f_acc) b_extra = 1'b1;
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
            // no deadlock
            assert (f_wait < RESP);
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
