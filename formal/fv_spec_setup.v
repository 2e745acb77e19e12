// fv_spec_setup - formal properties of spec_setup's handshake, holding register, credits and descriptor FIFO,
// proved by formal/formal.py (make formal) with yosys-smtbmc and z3, for traces of any length by induction.
//
// The core is `fv_core_setup`: rtl/spec_setup.v unchanged, with the arithmetic left out (formal/fv_setup_stub.v:
// spec_setup_machine keeps its slot and span counters, so tau0 comes every II clocks; spec_setup_finish gives a
// started span's descriptor LATENCY clocks later, in order, with the span's n, l, rule and invalid flag and the
// other fields a fixed function of them), flattened, its memories mapped to registers, the holding register,
// the credit counter, the stub's pipeline, the slot and the FIFO's pointers, stages and words made ports by
// Yosys `expose`. The descriptor's widths are formal.py's reduced ones (n 4 bits, l 3 bits).
//
// The reduction: formal.py puts a setup_params.vh on the include path before the generated one, the same but
// for II = 2 and LATENCY = 3 (FV_SCHED; the ecp5 configuration has II = 28, LATENCY = 470). spec_setup sizes
// its FIFO from them as always (FLY = LATENCY / II + 3 = 4: FIFO_AW = 2, 2^FIFO_AW + 2 = 6 credits), so two
// spans are in the stub's pipeline at once, a held beat waits up to II - 1 clocks for tau0, and the FIFO and
// the credits fill as they do at full size; what the small numbers leave out is only more of the same stages.
//
// Every input is free in every cycle (the source need not keep s_axis_tvalid or its data; the sink's
// m_axis_tready and rst_n are anything after a reset in the first cycle) but for the numbering: the beat offered
// carries its number k (beats accepted since reset, mod 2^N_W) in the n field, l = k mod 2^L_W, rule bit k[1],
// and a zero vector among N1, N2, H1, H2 exactly when k[0] ^ k[2] (the pre-stage's invalid flag); so every
// descriptor out says whose it is, and every bit of it is known.
//
// Specification (spec_setup.v's header, docs/setup.md):
//   - AXI4-Stream source rules on the descriptor side: once m_axis_tvalid is 1 it stays 1, with m_axis_tdata
//     and m_axis_tuser unchanged, until m_axis_tready (a reset may drop it); s_axis_tready is a register (the
//     sink side has no rule to keep: any source is allowed);
//   - order, no loss, no duplication: the descriptor offered is the f_out-th accepted beat's, every bit of it
//     (n, l, rule and invalid flag, the fields the stub makes of them, zeros between the fields), and none is
//     offered without an accepted beat outstanding; the FIFO is never pushed while full;
//   - no deadlock: m_axis_tvalid rises within II - 1 + LATENCY + 3 clocks of a span being outstanding with no
//     descriptor offered, whatever the sink does;
//   - reset: m_axis_tvalid = 0 and s_axis_tready = 0 in the cycle after a reset edge, s_axis_tready in the one
//     after; nothing accepted before the reset comes out after it.
// The helper invariants below (where every outstanding beat is: the output register, the skid buffer, the read
// stage, the FIFO's memory word by word, the stub's pipeline stage by stage, the holding register; the credits;
// a ranking for the response time) make the properties inductive with k = 1. The covers and the mutants
// (formal.py) run on the model without them (FV_NO_HELPERS).
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
    localparam N_W = `SPEC_N_W, L_W = `SPEC_L_W, C_W = `SPEC_C_W, ANG_W = `SPEC_ANG_W, DESC_W = `SPEC_DESC_W;
    localparam VEC_W = `SETUP_VEC_W;
    localparam II = `SETUP_II, LAT = `SETUP_LATENCY;
    // spec_setup's sizing (docs/setup.md): the FIFO and the credits
    localparam FLY = LAT / II + 3;
    localparam AW = (FLY > 64) ? 7 : (FLY > 32) ? 6 : (FLY > 16) ? 5 : (FLY > 8) ? 4 : (FLY > 4) ? 3 : 2;
    localparam DEPTH = (1 << AW) + 2;
    localparam SIW = 2 + N_W + L_W;                  // the stub's side word {invalid, rule, n, l}
    localparam DW = 7 + 2 * ANG_W + L_W + N_W + C_W; // a FIFO word {flags, dzeta, zeta0, l, n, C}
    localparam TAUW = (II > 16) ? 5 : 4;             // spec_setup_machine's slot width (II <= 32 here)
    localparam ETA_MAX = II - 1 + LAT + 3;           // the longest wait for m_axis_tvalid (the ranking below)
    generate
        if (AW != 2 || II > 32 || LAT < 2 || LAT > 8) begin : g_check
            fv_spec_setup_is_written_for_a_4_word_fifo_and_II_up_to_32 see_FV_SCHED_in_formal_py ();
        end
    endgenerate

    wire s_axis_tready, m_axis_tvalid;
    wire [DESC_W-1:0] m_axis_tdata;
    wire [6:0] m_axis_tuser;
    // internals (Yosys `expose`)
    wire held, ready_q, h_rule, h_inv;
    wire [N_W-1:0] h_n;
    wire [L_W-1:0] h_l;
    wire [AW+1:0] credit;
    wire [TAUW-1:0] tau;                             // the machine stub's slot
    wire [LAT-1:0] pv;                               // the finish stub's pipeline: valid flags, side words
    wire [LAT*SIW-1:0] psd;
    wire [AW:0] cm;                                  // the FIFO: words in the memory, pointers, stages
    wire [AW-1:0] wp, rp;
    wire rv, skid_v;
    wire [DW-1:0] rd, skid_d;
    wire [DW-1:0] mem0, mem1, mem2, mem3;            // the memory's words (mapped to registers)
    wire [4*DW-1:0] memv = {mem3, mem2, mem1, mem0};

    fv_core_setup dut (
        .clk(clk), .rst_n(rst_n), .s_axis_tvalid(s_axis_tvalid), .s_axis_tready(s_axis_tready),
        .s_axis_tdata(s_axis_tdata), .m_axis_tvalid(m_axis_tvalid), .m_axis_tready(m_axis_tready),
        .m_axis_tdata(m_axis_tdata), .m_axis_tuser(m_axis_tuser),
        .held(held), .ready_q(ready_q), .credit(credit), .h_n(h_n), .h_l(h_l), .h_rule(h_rule), .h_inv(h_inv),
        .\u_mach.tau (tau), .\u_fin.v (pv), .\u_fin.sd (psd),
        .\u_fifo.cm (cm), .\u_fifo.wp (wp), .\u_fifo.rp (rp), .\u_fifo.rv (rv), .\u_fifo.rd (rd),
        .\u_fifo.skid_v (skid_v), .\u_fifo.skid_d (skid_d),
        .\u_fifo.mem[0] (mem0), .\u_fifo.mem[1] (mem1), .\u_fifo.mem[2] (mem2), .\u_fifo.mem[3] (mem3)
    );

    // ---- what span k is: the source's numbering, and the descriptor the stub makes of it -------------------------
    function [L_W-1:0] l_of(input [N_W-1:0] k);
        l_of = k[L_W-1:0];
    endfunction
    function rule_of(input [N_W-1:0] k);
        rule_of = k[1];
    endfunction
    function inv_of(input [N_W-1:0] k);
        inv_of = k[0] ^ k[2];
    endfunction
    function [SIW-1:0] side_of(input [N_W-1:0] k);
        side_of = {inv_of(k), rule_of(k), k, l_of(k)};
    endfunction
    function [6:0] flags_of(input [N_W-1:0] k);
        flags_of = {inv_of(k), rule_of(k), 1'b0, k[3:0]};
    endfunction
    function [DW-1:0] word_of(input [N_W-1:0] k);   // as spec_setup pushes it: {flags, dzeta, zeta0, l, n, C}
        reg [C_W-1:0] c;
        reg [ANG_W-1:0] z0, dz;
        begin
            c = ~k;
            z0 = k;
            dz = l_of(k);
            word_of = {flags_of(k), dz, z0, l_of(k), k, c};
        end
    endfunction
    function [DESC_W-1:0] desc_of(input [N_W-1:0] k);   // spec_stream's descriptor layout (spec_params.vh)
        reg [C_W-1:0] c;
        begin
            c = ~k;
            desc_of = ({{(DESC_W - C_W) {1'b0}}, c} << `SPEC_DESC_C_LSB) |
                      ({{(DESC_W - N_W) {1'b0}}, k} << `SPEC_DESC_N_LSB) |
                      ({{(DESC_W - L_W) {1'b0}}, l_of(k)} << `SPEC_DESC_L_LSB) |
                      ({{(DESC_W - N_W) {1'b0}}, k} << `SPEC_DESC_ZETA0_LSB) |
                      ({{(DESC_W - L_W) {1'b0}}, l_of(k)} << `SPEC_DESC_DZETA_LSB);
        end
    endfunction

    // ---- the interface's model ---------------------------------------------------------------------------------
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
    wire [N_W-1:0] inflight;
    wire busy = inflight != 0;
    wire waiting = rst_n & busy & ~m_axis_tvalid;      // a beat outstanding, no descriptor offered
    reg [N_W-1:0] f_acc, f_out;                       // beats accepted, descriptors handed over (mod 2^N_W)
    reg [4:0] f_wait;                                 // cycles of waiting before this one (in a row)
    always @(posedge clk) begin
        if (!rst_n) begin
            f_acc <= 0;
            f_out <= 0;
            f_wait <= 0;
        end else begin
            f_acc <= f_acc + accept;
            f_out <= f_out + hand;
            f_wait <= waiting ? f_wait + 1'b1 : 5'd0;
        end
    end
    assign inflight = f_acc - f_out;

    // the source numbers its beats
    wire [12*VEC_W-1:0] bvec;
    genvar g;
    generate
        for (g = 0; g < 12; g = g + 1) begin : g_vec
            assign bvec[g*VEC_W +: VEC_W] = s_axis_tdata[`SETUP_BEAT_VEC_LSB + 16 * g +: VEC_W];
        end
    endgenerate
    wire b_zero = ~|bvec[0 +: 3*VEC_W] | ~|bvec[3*VEC_W +: 3*VEC_W] | ~|bvec[6*VEC_W +: 3*VEC_W] |
                  ~|bvec[9*VEC_W +: 3*VEC_W];
    always @(*) begin
        if (s_axis_tvalid) begin
            assume (s_axis_tdata[`SETUP_BEAT_N_LSB +: N_W] == f_acc);
            assume (s_axis_tdata[`SETUP_BEAT_L_LSB +: L_W] == l_of(f_acc));
            assume (s_axis_tdata[`SETUP_BEAT_RULE_BIT] == rule_of(f_acc));
            assume (b_zero == inv_of(f_acc));
        end
    end

    // ---- properties ----------------------------------------------------------------------------------------------
    reg f_stall_q = 1'b0;
    reg [DESC_W-1:0] f_data_q;
    reg [6:0] f_user_q;
    always @(posedge clk) begin
        f_stall_q <= rst_n & m_axis_tvalid & ~m_axis_tready;
        f_data_q <= m_axis_tdata;
        f_user_q <= m_axis_tuser;
    end
    wire push = pv[LAT-1];                            // the stub's d_valid: spec_setup pushes the FIFO
    wire re = ~skid_v & (cm != 0);                    // spec_setup_fifo's read
    always @(*) begin
        if (f_past) begin
            if (f_stall_q) assert (m_axis_tvalid && m_axis_tdata == f_data_q && m_axis_tuser == f_user_q);
            if (!f_rst_q) assert (!m_axis_tvalid && !s_axis_tready);
            if (f_rst_q && !f_rst_q2) assert (s_axis_tready);
            if (m_axis_tvalid) assert (busy && m_axis_tdata == desc_of(f_out) && m_axis_tuser == flags_of(f_out));
            if (rst_n && push && cm == (1 << AW)) assert (re);
            if (waiting) assert (f_wait < ETA_MAX);
        end
    end

`ifndef FV_NO_HELPERS
    // ---- helper invariants (for the induction step) -------------------------------------------------------------
    // spans started and not handed over: the FIFO's output register, skid buffer, read stage and memory, and the
    // stub's pipeline; with the held beat, all that is outstanding
    reg [3:0] npv;
    reg [3:0] top;                                    // the oldest stage of the pipeline with a span in it
    integer i;
    always @(*) begin
        npv = 0;
        top = 0;
        for (i = 0; i < LAT; i = i + 1) begin
            npv = npv + pv[i];
            if (pv[i]) top = i;
        end
    end
    wire [3:0] down = m_axis_tvalid + skid_v + rv + cm + npv;
    // the ranking: clocks until m_axis_tvalid at the latest (no descriptor offered); it falls in every such clock
    wire [TAUW-1:0] to_tau0 = (tau == 0) ? {TAUW{1'b0}} : II - tau;
    wire [4:0] eta = rv ? 5'd1 : (cm != 0) ? 5'd2 : (pv != 0) ? LAT + 2 - top : held ? to_tau0 + LAT + 3 : 5'd0;
    reg [N_W-1:0] k;
    reg [AW-1:0] a;
    always @(*) begin
        a = 0;
        k = 0;
        if (f_past) begin
            if (!f_past_2) assert (!f_rst_q);
            if (!f_rst_q) assert (f_acc == 0 && f_out == 0 && f_wait == 0 && !held && down == 0 && tau == 0);
            assert (tau < II);
            assert (down <= DEPTH && credit == DEPTH - down && {1'b0, inflight} == down + held);
            if (f_rst_q) assert (ready_q == !held);
            if (skid_v) assert (m_axis_tvalid);
            assert (cm <= (1 << AW) && wp == rp + cm[AW-1:0]);
            if (waiting) assert (eta != 0 && f_wait + eta <= ETA_MAX);
            // each outstanding beat where it is, in order from the oldest (f_out)
            k = f_out + m_axis_tvalid;
            if (skid_v) assert (skid_d == word_of(k));
            k = k + skid_v;
            if (rv) assert (rd == word_of(k));
            k = k + rv;
            for (i = 0; i < 4; i = i + 1) begin
                a = rp + i[AW-1:0];
                if (i < cm) assert (memv[a*DW +: DW] == word_of(k + i[N_W-1:0]));
            end
            k = k + cm;
            for (i = LAT - 1; i >= 0; i = i - 1) begin
                if (pv[i]) begin
                    assert (psd[i*SIW +: SIW] == side_of(k));
                    k = k + 1'b1;
                end
            end
            if (held) assert ({h_inv, h_rule, h_n, h_l} == side_of(k) && k == f_acc - 1'b1);
        end
    end
`endif

    // covers: the memory full behind a stalled sink (the state that makes 2^FIFO_AW + 2 the most credits), a beat
    // held with the credits used up, descriptors handed over back to back, a reset with spans in flight
    reg f_hand_q = 1'b0;
    always @(posedge clk) f_hand_q <= hand;
    always @(*) begin
        if (f_past && rst_n) begin
            cover (cm == (1 << AW) && skid_v && m_axis_tvalid);
            cover (held && credit == 0 && f_rst_q);
            cover (hand && f_hand_q && f_out == 7);
        end
        if (f_past && !rst_n) cover (inflight >= 3);
    end
endmodule
`default_nettype wire
