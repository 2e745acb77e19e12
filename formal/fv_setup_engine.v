// fv_setup_engine - formal properties of the small setup (spec_setup_small, the up5k configuration's:
// rtl/spec_setup_engine.v and rtl/spec_setup_backend.v, one span at a time), proved by formal/formal.py (make formal,
// make formal-shader) with yosys-smtbmc and z3.
//
// The core is `fv_core_setup_small`: rtl/spec_setup_small.v at formal.py's reduced widths of the job (setup_engine:
// the descriptor's fields as for the other jobs but n 10 bits, as the back end's program needs, and the smallest
// small-setup format the generator allows, setuprom --config up5k: 8 micro-rotations, 22-bit coordinates),
// flattened, with the engine's and the back end's control registers made ports by Yosys `expose`; rtl/ is not
// edited. Every input is free but for the numbering: the source writes the number of the beat it offers (beats
// accepted so far, mod 2^N_W) into the n field, and the properties follow the numbers.
//
// Specification (header comments of spec_setup_engine.v and spec_setup_backend.v, docs/setup.md):
//   - AXI4-Stream source rules on the descriptor side: once m_axis_tvalid is 1 it stays 1, with m_axis_tdata
//     (C, n, l, zeta0, dzeta) and m_axis_tuser unchanged, until m_axis_tready (a reset may drop it);
//   - one span at a time: s_axis_tready only while no span is in flight (idle, the previous descriptor handed
//     over); every accepted beat gives exactly one descriptor, and it is that beat's (its n and l), so none is
//     lost, duplicated or reordered; no descriptor without an accepted beat;
//   - no deadlock: while a span is in flight and its descriptor is not yet offered, a ranking key (below) grows
//     in every cycle; the key takes finitely many values, so m_axis_tvalid rises after finitely many cycles,
//     whatever the data (the engine's and the back end's loops are all bounded by their counters); after the
//     handover s_axis_tready is back within 2 cycles;
//   - reset: m_axis_tvalid = 0 and s_axis_tready = 0 in the cycle after a reset edge, s_axis_tready in the one
//     after; nothing accepted before the reset comes out after it.
// All are proved for traces of any length by k-induction (formal.py's setup_engine job) with the helper
// invariants below (where the engine and the back end are in their programs, and how the two are linked).
// The arithmetic is in the model (only the two multipliers' products are cut off and left free: they feed
// data only); what is not proved here is the values of C, zeta0 and dzeta (the bit-exact simulation tests).
`default_nettype none
`include "spec_params.vh"
`include "setup_params.vh"
`include "setup_small_params.vh"
module fv_setup_engine (
    input wire                       clk,
    input wire                       rst_n,
    input wire                       s_axis_tvalid,
    input wire [`SETUP_BEAT_W-1:0]   s_axis_tdata,
    input wire                       m_axis_tready,
    input wire [`SMALL_W+9:0]        f_rho,    // free: the opposite test's product (cut off)
    input wire [`SMALL_EF+`SMALL_RB:0] f_tprod // free: the interpolation product (cut off)
);
    localparam N_W = `SPEC_N_W;
    localparam L_W = `SPEC_L_W;
    localparam C_W = `SPEC_C_W;
    localparam DESC_W = `SPEC_DESC_W;
    localparam ITERS = `SMALL_ITERS;
    localparam ZW = `SMALL_ZW;
    localparam NRUN = 24;
    // spec_setup_engine's states, spec_setup_backend's program counters and step kinds (their localparams)
    localparam ST_IDLE = 3'd0, ST_LOAD = 3'd1, ST_RD = 3'd2, ST_ROT = 3'd3, ST_WR = 3'd4, ST_BE = 3'd5;
    localparam [6:0] PC_IDLE = 7'd1, PC_DIV = 7'd4, PC_NORM1 = 7'd19, PC_NORM2 = 7'd35, PC_TABE = 7'd58,
                     PC_SHIFT = 7'd66, PC_OUT = 7'd69;   // pc1 (the program counter plus one) of the steps
    localparam [3:0] X_IDLE = 4'd11, X_OUT = 4'd10, X_NORM = 4'd4, X_SHIFT = 4'd9, X_DIV = 4'd1, X_LGX = 4'd2,
                     X_LGS = 4'd3, X_TABE = 4'd6;

    wire s_axis_tready, m_axis_tvalid;
    wire [DESC_W-1:0] m_axis_tdata;
    wire [6:0] m_axis_tuser;
    // internals (Yosys `expose`): the engine
    wire [2:0] st, ld_v;
    wire [3:0] ph;
    wire [4:0] it, run, run_tests;
    wire [1:0] rph, qt, ld_c;
    wire be_start, bad, rule_reg, opp, v_we;
    wire [4:0] v_ra;
    wire [N_W-1:0] n_reg;
    wire [L_W-1:0] l_reg;
    // the back end
    wire [6:0] pc1;
    wire [1:0] bph;
    wire ph2, lam_q, a_fast, a_idle, a_div, a_norm, a_shift, a_out, done, lge_nz, sc_nz, div_done, out_rdy;
    wire acc_en_pre, c_rw, zero_c, sat, nohl, flat;
    wire [3:0] c_act;
    wire [2:0] c_fl, c_cd;
    wire [5:0] lg_e, sc, dcnt;
    wire [C_W-1:0] ccode, c_out;
    wire [6:0] bf_out;

    fv_core_setup_small dut (
        .clk(clk), .rst_n(rst_n), .s_axis_tvalid(s_axis_tvalid), .s_axis_tready(s_axis_tready),
        .s_axis_tdata(s_axis_tdata), .m_axis_tvalid(m_axis_tvalid), .m_axis_tready(m_axis_tready),
        .m_axis_tdata(m_axis_tdata), .m_axis_tuser(m_axis_tuser),
        .\u_engine.rho2k.i (f_rho), .\u_engine.rho2k (),
        .\u_engine.u_back.tprod.i (f_tprod), .\u_engine.u_back.tprod (),
        .\u_engine.st (st), .\u_engine.ph (ph), .\u_engine.it (it),
        .\u_engine.rph (rph), .\u_engine.qt (qt), .\u_engine.run (run),
        .\u_engine.run_tests (run_tests), .\u_engine.ld_v (ld_v), .\u_engine.ld_c (ld_c),
        .\u_engine.be_start (be_start), .\u_engine.bad (bad),
        .\u_engine.rule_reg (rule_reg), .\u_engine.opp (opp),
        .\u_engine.v_ra (v_ra), .\u_engine.v_we (v_we), .\u_engine.n_reg (n_reg), .\u_engine.l_reg (l_reg),
        .\u_engine.u_back.pc1 (pc1), .\u_engine.u_back.bph (bph),
        .\u_engine.u_back.ph2 (ph2), .\u_engine.u_back.lam_q (lam_q),
        .\u_engine.u_back.a_fast (a_fast), .\u_engine.u_back.a_idle (a_idle),
        .\u_engine.u_back.a_div (a_div), .\u_engine.u_back.a_norm (a_norm),
        .\u_engine.u_back.a_shift (a_shift), .\u_engine.u_back.a_out (a_out),
        .\u_engine.u_back.done (done), .\u_engine.u_back.lge_nz (lge_nz),
        .\u_engine.u_back.sc_nz (sc_nz), .\u_engine.u_back.div_done (div_done),
        .\u_engine.u_back.out_rdy (out_rdy), .\u_engine.u_back.acc_en_pre (acc_en_pre),
        .\u_engine.u_back.c_rw (c_rw), .\u_engine.u_back.c_act (c_act),
        .\u_engine.u_back.c_fl (c_fl), .\u_engine.u_back.c_cd (c_cd),
        .\u_engine.u_back.lg_e (lg_e), .\u_engine.u_back.sc (sc),
        .\u_engine.u_back.dcnt (dcnt), .\u_engine.u_back.zero_c (zero_c),
        .\u_engine.u_back.sat (sat), .\u_engine.u_back.nohl (nohl),
        .\u_engine.u_back.flat (flat), .\u_engine.u_back.ccode (ccode),
        .\u_engine.u_back.c_out (c_out), .\u_engine.u_back.f_out (bf_out)
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
    reg [L_W-1:0] f_l;                    // l of the beat accepted last
    reg [1:0] f_rwait;                    // cycles without a span in flight and without s_axis_tready
    always @(posedge clk) begin
        if (accept) f_l <= s_axis_tdata[`SETUP_BEAT_L_LSB +: L_W];
        if (!rst_n) begin
            f_acc <= 0;
            f_out <= 0;
            f_rwait <= 0;
        end else begin
            f_acc <= f_acc + accept;
            f_out <= f_out + hand;
            f_rwait <= (f_acc == f_out && !s_axis_tready && f_rwait != 2'd3) ? f_rwait + 1'b1 : 2'd0;
        end
    end
    // the source numbers its beats
    always @(*) if (s_axis_tvalid) assume (s_axis_tdata[`SETUP_BEAT_N_LSB +: N_W] == f_acc);
    wire [N_W-1:0] inflight = f_acc - f_out;
    wire busy = inflight != 0;

    // ---- the ranking key: the engine's place in its program (LOAD, then run by run RD, ROT, WR, then BE),
    // then the back end's (its step, lam_q, the step's clock, the loop counters of the normalization and the
    // shift, the divider, out_rdy); compared as one unsigned number (lexicographic order)
    reg [1:0] k_stage, k_sub;
    reg [4:0] k_run, k_a;
    reg [3:0] k_b, k_c;
    always @(*) begin
        {k_stage, k_run, k_sub, k_a, k_b, k_c} = 0;
        case (st)
            ST_LOAD: begin
                k_stage = 2'd1;
                k_a = {2'b00, ld_v};
                k_b = {2'b00, ld_c};
                k_c = ph;
            end
            ST_RD, ST_ROT, ST_WR: begin
                k_stage = 2'd2;
                k_run = run;
                k_sub = (st == ST_RD) ? 2'd0 : (st == ST_ROT) ? 2'd1 : 2'd2;
                k_a = (st == ST_ROT) ? it : 5'd0;
                k_b = (st == ST_ROT) ? {2'b00, ~qt} : 4'd0;
                k_c = (st == ST_ROT) ? {2'b00, rph} : ph;
            end
            ST_BE: k_stage = 2'd3;
            default: ;
        endcase
    end
    wire [21:0] ekey = {k_stage, k_run, k_sub, k_a, k_b, k_c};
    wire [29:0] bkey = {pc1, lam_q, bph, ~lg_e, ~sc, div_done, dcnt, out_rdy};
    wire [51:0] key = {ekey, bkey};
    reg [51:0] f_key_q;
    reg f_prog_q = 1'b0;                  // the previous cycle: a span in flight, not offered yet, no reset
    always @(posedge clk) begin
        f_key_q <= key;
        f_prog_q <= rst_n && busy && !m_axis_tvalid;
    end

    // ---- properties --------------------------------------------------------------------------------------------
    reg f_stall_q = 1'b0;
    reg [DESC_W-1:0] f_data_q;
    reg [6:0] f_user_q;
    always @(posedge clk) begin
        f_stall_q <= rst_n & m_axis_tvalid & ~m_axis_tready;
        f_data_q <= m_axis_tdata;
        f_user_q <= m_axis_tuser;
    end
    wire [N_W-1:0] out_n = m_axis_tdata[`SPEC_DESC_N_LSB +: N_W];
    wire [L_W-1:0] out_l = m_axis_tdata[`SPEC_DESC_L_LSB +: L_W];
    always @(*) begin
        if (f_past) begin
            if (f_stall_q) assert (m_axis_tvalid && m_axis_tdata == f_data_q && m_axis_tuser == f_user_q);
            if (!f_rst_q) assert (!m_axis_tvalid && !s_axis_tready);
            if (f_rst_q && !f_rst_q2) assert (s_axis_tready);
            assert (inflight <= 1);
            if (s_axis_tready) assert (!busy);
            if (m_axis_tvalid) assert (busy && out_n == f_out && out_l == f_l);
            // no deadlock: the key grows while the descriptor is not offered; s_axis_tready soon after a handover
            if (f_prog_q && !m_axis_tvalid) assert (key > f_key_q);
            assert (f_rwait < 2'd3);
        end
    end

    // ---- helper invariants (for the induction step) ------------------------------------------------------------
    function [4:0] tests_of(input [4:0] r);   // spec_setup_engine's run tests
        tests_of = {r == 5'd6, r == 5'd9, r == 5'd10, r == 5'd22, r == NRUN - 1};
    endfunction
    function [5:0] kind_of(input [3:0] act);   // spec_setup_backend's step kinds
        kind_of = {act == X_IDLE || act == X_NORM || act == X_SHIFT || act == X_OUT, act == X_IDLE, act == X_DIV,
                   act == X_NORM, act == X_SHIFT, act == X_OUT};
    endfunction
    wire in_runs = st == ST_RD || st == ST_ROT || st == ST_WR;
    // the engine before the back end starts (gamma's run writes its first word), at the start, and after
    wire e_pre = st == ST_IDLE || st == ST_LOAD ||
                 (in_runs && (run < 5'd22 || (run == 5'd22 && (st != ST_WR || ph == 4'd0))));
    wire e_start = st == ST_WR && run == 5'd22 && ph == 4'd1;
    wire e_mid = in_runs && (run == 5'd23 || (run == 5'd22 && st == ST_WR && ph >= 4'd2));
    always @(*) begin
        if (f_past) begin
            if (!f_past_2) assert (!f_rst_q);
            // the engine's program
            assert (st <= ST_BE);
            if (st == ST_LOAD) begin
                assert (ld_v <= 3'd5 && ph <= 4'd5);
                if (ld_v != 3'd4) assert (ld_c == 2'd0 ? ph <= 4'd4 : ph == 4'd0);
            end
            if (st == ST_RD) assert (ph <= 4'd7 && (ph == 4'd0 || it == 5'd0));
            if (st == ST_ROT) assert (it < ITERS && rph <= 2'd2);
            if (st == ST_WR) assert (ph <= 4'd4);
            if (in_runs) assert (run < NRUN && run_tests == tests_of(run));
            if (st != ST_IDLE) assert (!s_axis_tready);
            if (st != ST_IDLE && st != ST_BE) assert (!lam_q);
            // the back end's program
            assert (pc1 >= PC_IDLE && pc1 <= PC_OUT && bph <= 2'd2 && ph2 == (bph == 2'd2));
            if (a_fast) assert (bph == 2'd0);
            assert ({a_fast, a_idle, a_div, a_norm, a_shift, a_out} == kind_of(c_act));
            assert (a_idle == (pc1 == PC_IDLE) && a_div == (pc1 == PC_DIV) && a_shift == (pc1 == PC_SHIFT) &&
                    a_norm == (pc1 == PC_NORM1 || pc1 == PC_NORM2) && a_out == (pc1 == PC_OUT));
            // the steps that load the loop counters (log2 x, log2 Is: the normalization's; exp2: the shift's)
            assert ((c_act == X_LGX) == (pc1 == PC_NORM1 - 7'd1) && (c_act == X_LGS) == (pc1 == PC_NORM2 - 7'd1) &&
                    (c_act == X_TABE) == (pc1 == PC_TABE));
            if (a_norm) assert (lge_nz == (lg_e != 6'd0));
            if (pc1 > PC_TABE && pc1 <= PC_SHIFT) assert (sc_nz == (sc != 6'd0));
            if (!div_done) assert (dcnt < ZW);
            if (done) assert (a_idle && !m_axis_tvalid && st == ST_BE);
            if (m_axis_tvalid) assert (a_out && div_done && st == ST_BE);
            if (a_out) assert (c_fl == 3'd0 && c_cd == 3'd0 && !c_rw && !acc_en_pre && lam_q);
            // the back end past the division: the engine waits in BE, its vector memory read at M1.z, not written
            if (pc1 > PC_DIV) assert (st == ST_BE && lam_q && v_ra == {3'd5, 2'd2} && !v_we);
            // the output words: free-running registers of inputs that hold from the output step on
            if (a_out && out_rdy) begin
                assert (c_out == (zero_c ? {C_W{1'b0}} : sat ? {C_W{1'b1}} : ccode));
                assert (bf_out == (bad ? {1'b1, 2'b00, l_reg == {L_W{1'b0}}, 3'b000}
                                      : {1'b0, rule_reg, nohl, l_reg == {L_W{1'b0}}, !zero_c && sat, opp, flat}));
            end
            // the two linked: the back end starts with gamma's run, waits for lambda (BE) at the division
            if (e_pre) assert (a_idle && !be_start && !m_axis_tvalid);
            if (e_start) assert (a_idle && be_start);
            if (e_mid) assert (pc1 >= 7'd2 && pc1 <= PC_DIV && !be_start);
            if (st == ST_BE) begin
                if (!lam_q) assert (pc1 <= PC_DIV);
                if (be_start) assert (a_idle && bad);
                if (a_idle) assert (be_start || done);
            end
            // the span in flight
            assert (busy == (st != ST_IDLE && !done));
            if (busy) assert (n_reg == f_out && l_reg == f_l);
            if (!f_rst_q) assert (st == ST_IDLE && a_idle && !done && div_done && !be_start);
        end
    end

    // covers: a span accepted and its first vector loaded, a reset while loading; a descriptor offered is beyond
    // the bounded checks (over a thousand cycles a span at these widths; the first run starts after 48)
    always @(*) begin
        if (f_past && rst_n) cover (busy && st == ST_LOAD && ld_v == 3'd1);
        if (f_past && !rst_n) cover (busy && st == ST_LOAD);
    end
endmodule
`default_nettype wire
