// parallax_iter - the whole iteration of the companion paper C's parallax mapping (seeds/002, eq. 4-5;
// docs/methods.md), around one parallax_step: fragments come in, height fetches go out to a memory and come
// back after any latency, and each fragment leaves when its step meets the threshold or its cap is spent.
// Up to SLOTS fragments are in flight at once, so one step per clock is possible while fetches are pending.
//
// Per fragment (s_* , accepted on s_valid & s_ready):
//   s_u, s_v      the start point P_0 (UV_W-bit two's complement, F fraction bits, wrapping)
//   s_hv0         the ray's height there, hV_0 (H_W bits, same scaling): 0 with P_0 = the fragment (the
//                 paper), or the relief depth s with P_0 = the fragment + (s / Vh) V(u, v) (the slab's top:
//                 the host's one division; docs/methods.md measures both)
//   s_vu, s_vv, s_vh   the unit view vector, V_W-bit two's complement, V_F fraction bits
//   s_threshold   stop when |d_i| <= s_threshold (H_W bits, unsigned)
//   s_max_iter    at most this many steps (ITER_W bits); 0: the fragment leaves at once, unmoved
//   s_tag         carried to the result
// Step i: fetch h_i = s h(P_i); hV_i = hV_(i-1) + d_(i-1) Vh, d_i = h_i - hV_i (d_(-1) = 0);
// P_(i+1) = P_i + d_i V(u, v) (parallax_step: 3 multiplications, 4 additions).
// Result (m_*, AXI-Stream-like: stable while m_valid & !m_ready):
//   converged (|d_i| <= threshold): m_u, m_v = P_i, the point whose fetch met it, m_iters = i + 1
//   otherwise, after max_iter steps: P_(max_iter), m_iters = max_iter, m_converged = 0
// Results leave in the order they finish, not the order they came in: s_tag tells them apart.
//
// Height fetches: req_* (stable while req_valid & !req_ready) carries P_i and the slot number req_id; the
// memory answers each request exactly once, after any number of cycles and in any order, with rsp_valid,
// rsp_id = req_id and rsp_h = s h(P_i) in the H format (it chooses the filtering and the wrap). A response
// for a slot that is not waiting for one (or rsp_id >= SLOTS) is ignored.
//
// rst (synchronous, active high) empties every slot and both output registers. Bit-exact model:
// spec::methods::iterate_fixed (sim/methods/parallax_fixed.cpp). One clock domain.
`timescale 1ns / 1ps
`default_nettype none
module parallax_iter #(
    parameter UV_W = 24,
    parameter H_W = 16,
    parameter V_W = 16,
    parameter V_F = 14,
    parameter ITER_W = 6,
    parameter TAG_W = 8,
    parameter SLOTS = 4,
    parameter ID_W = SLOTS > 1 ? $clog2(SLOTS) : 1  // slot number width: at least clog2(SLOTS)
) (
    input  wire              clk,
    input  wire              rst,
    // fragments in
    input  wire              s_valid,
    output wire              s_ready,
    input  wire [UV_W-1:0]   s_u,
    input  wire [UV_W-1:0]   s_v,
    input  wire [H_W-1:0]    s_hv0,
    input  wire [V_W-1:0]    s_vu,
    input  wire [V_W-1:0]    s_vv,
    input  wire [V_W-1:0]    s_vh,
    input  wire [H_W-1:0]    s_threshold,
    input  wire [ITER_W-1:0] s_max_iter,
    input  wire [TAG_W-1:0]  s_tag,
    // height fetch requests
    output reg               req_valid,
    input  wire              req_ready,
    output reg  [UV_W-1:0]   req_u,
    output reg  [UV_W-1:0]   req_v,
    output reg  [ID_W-1:0]   req_id,
    // height fetch responses
    input  wire              rsp_valid,
    input  wire [ID_W-1:0]   rsp_id,
    input  wire [H_W-1:0]    rsp_h,
    // results out
    output reg               m_valid,
    input  wire              m_ready,
    output reg  [UV_W-1:0]   m_u,
    output reg  [UV_W-1:0]   m_v,
    output reg  [ITER_W-1:0] m_iters,
    output reg               m_converged,
    output reg  [TAG_W-1:0]  m_tag,
    output wire              busy
);
    localparam SL_W = ID_W;
    // slot states
    localparam [2:0] S_FREE = 3'd0,   // empty
                     S_FETCH = 3'd1,  // its next fetch is to be requested
                     S_REQ = 3'd2,    // its request is in the request register
                     S_WAIT = 3'd3,   // the memory has its request
                     S_STEP = 3'd4,   // its step is in parallax_step
                     S_DONE = 3'd5;   // finished, waiting for the result register

`ifndef SYNTHESIS
    initial begin
        if (SLOTS < 1 || (1 << ID_W) < SLOTS || UV_W < 2 || H_W < 2 || V_W < 2 || V_F < 1 || V_F >= H_W + V_W ||
            ITER_W < 1 || TAG_W < 1) begin
            $display("parallax_iter: bad parameters SLOTS=%0d ID_W=%0d UV_W=%0d H_W=%0d V_W=%0d V_F=%0d ITER_W=%0d TAG_W=%0d (%m)",
                     SLOTS, ID_W, UV_W, H_W, V_W, V_F, ITER_W, TAG_W);
            $fatal(1);
        end
    end
`endif

    // ---- the slots: one generate block each; their fields read back through flat buses ----
    wire [3*SLOTS-1:0]      st_all;
    wire [UV_W*SLOTS-1:0]   u_all, v_all;
    wire [H_W*SLOTS-1:0]    hv_all, d_all, thr_all;  // hV_(i-1), d_(i-1)
    wire [V_W*SLOTS-1:0]    vu_all, vv_all, vh_all;
    wire [ITER_W*SLOTS-1:0] max_all, it_all;         // it: steps done
    wire [SLOTS-1:0]        cv_all;
    wire [TAG_W*SLOTS-1:0]  tag_all;

    // the lowest-numbered slot in each state of interest: one-hot, and its number
    wire [SLOTS-1:0] is_free, is_fetch, is_done;
    genvar g;
    generate
        for (g = 0; g < SLOTS; g = g + 1) begin : g_state
            assign is_free[g] = st_all[3 * g +: 3] == S_FREE;
            assign is_fetch[g] = st_all[3 * g +: 3] == S_FETCH;
            assign is_done[g] = st_all[3 * g +: 3] == S_DONE;
        end
    endgenerate
    reg [SLOTS-1:0] free_first, fetch_first, done_first;
    reg             free_any, fetch_any, done_any;
    reg [SL_W-1:0]  fetch_idx;
    integer k;
    always @* begin
        free_any = 1'b0;
        fetch_any = 1'b0;
        done_any = 1'b0;
        fetch_idx = {SL_W{1'b0}};
        for (k = 0; k < SLOTS; k = k + 1) begin
            free_first[k] = is_free[k] & ~free_any;
            fetch_first[k] = is_fetch[k] & ~fetch_any;
            done_first[k] = is_done[k] & ~done_any;
            free_any = free_any | is_free[k];
            fetch_any = fetch_any | is_fetch[k];
            done_any = done_any | is_done[k];
            fetch_idx = fetch_idx | (fetch_first[k] ? k[SL_W-1:0] : {SL_W{1'b0}});
        end
    end

    assign s_ready = free_any;
    assign busy = (|(~is_free)) | m_valid;
    wire accept = s_valid & free_any;
    wire req_load = (~req_valid | req_ready) & fetch_any;
    wire out_load = (~m_valid | m_ready) & done_any;

    // ---- a response starts the slot's step ----
    wire rsp_in_range;
    generate
        if (SLOTS == (1 << SL_W)) begin : g_pow2
            assign rsp_in_range = 1'b1;
        end else begin : g_npow2
            localparam [SL_W:0] SLOTS_N = SLOTS[SL_W:0];
            assign rsp_in_range = {1'b0, rsp_id} < SLOTS_N;
        end
    endgenerate
    wire [SL_W-1:0] rsp_idx = rsp_in_range ? rsp_id : {SL_W{1'b0}};
    wire [SLOTS-1:0] one = {{(SLOTS - 1) {1'b0}}, 1'b1};
    wire [SLOTS-1:0] rsp_sel = rsp_in_range ? one << rsp_id : {SLOTS{1'b0}};

    // the slots' fields read back: AND-OR multiplexers on one-hot selects (no index arithmetic)
    reg [2:0]        rsp_st;
    reg [UV_W-1:0]   rsp_u, rsp_v, fetch_u, fetch_v, done_u, done_v;
    reg [H_W-1:0]    rsp_hv, rsp_d, rsp_thr;
    reg [V_W-1:0]    rsp_vu, rsp_vv, rsp_vh;
    reg [ITER_W-1:0] rsp_itc, rsp_max, done_it;
    reg              done_cv;
    reg [TAG_W-1:0]  done_tag;
    always @* begin
        rsp_st = 3'd0;
        {rsp_u, rsp_v, fetch_u, fetch_v, done_u, done_v} = {(6 * UV_W) {1'b0}};
        {rsp_hv, rsp_d, rsp_thr} = {(3 * H_W) {1'b0}};
        {rsp_vu, rsp_vv, rsp_vh} = {(3 * V_W) {1'b0}};
        {rsp_itc, rsp_max, done_it} = {(3 * ITER_W) {1'b0}};
        done_cv = 1'b0;
        done_tag = {TAG_W{1'b0}};
        for (k = 0; k < SLOTS; k = k + 1) begin
            if (rsp_sel[k]) begin
                rsp_st = rsp_st | st_all[3 * k +: 3];
                rsp_u = rsp_u | u_all[UV_W * k +: UV_W];
                rsp_v = rsp_v | v_all[UV_W * k +: UV_W];
                rsp_hv = rsp_hv | hv_all[H_W * k +: H_W];
                rsp_d = rsp_d | d_all[H_W * k +: H_W];
                rsp_thr = rsp_thr | thr_all[H_W * k +: H_W];
                rsp_vu = rsp_vu | vu_all[V_W * k +: V_W];
                rsp_vv = rsp_vv | vv_all[V_W * k +: V_W];
                rsp_vh = rsp_vh | vh_all[V_W * k +: V_W];
                rsp_itc = rsp_itc | it_all[ITER_W * k +: ITER_W];
                rsp_max = rsp_max | max_all[ITER_W * k +: ITER_W];
            end
            if (fetch_first[k]) begin
                fetch_u = fetch_u | u_all[UV_W * k +: UV_W];
                fetch_v = fetch_v | v_all[UV_W * k +: UV_W];
            end
            if (done_first[k]) begin
                done_u = done_u | u_all[UV_W * k +: UV_W];
                done_v = done_v | v_all[UV_W * k +: UV_W];
                done_it = done_it | it_all[ITER_W * k +: ITER_W];
                done_cv = done_cv | cv_all[k];
                done_tag = done_tag | tag_all[TAG_W * k +: TAG_W];
            end
        end
    end
    wire rsp_ok = rsp_valid & rsp_in_range & (rsp_st == S_WAIT);

    // ---- stage 0: the slot's operands, captured with the response (the slot mux gets a clock of its own) ----
    reg              op_valid;
    reg [UV_W-1:0]   op_u, op_v;
    reg [H_W-1:0]    op_h, op_hv, op_d;
    reg [V_W-1:0]    op_vu, op_vv, op_vh;
    // what the write-back needs, seven clocks later: the slot, its threshold, its step count and cap
    localparam SIDE_W = SL_W + H_W + 2 * ITER_W;
    reg [SIDE_W-1:0] op_side;
    always @(posedge clk) begin
        if (rst) op_valid <= 1'b0;
        else op_valid <= rsp_ok;
        op_u <= rsp_u;
        op_v <= rsp_v;
        op_h <= rsp_h;
        op_hv <= rsp_hv;
        op_d <= rsp_d;
        op_vu <= rsp_vu;
        op_vv <= rsp_vv;
        op_vh <= rsp_vh;
        op_side <= {rsp_idx, rsp_thr, rsp_itc, rsp_max};
    end

    wire            step_valid;
    wire [UV_W-1:0] step_u, step_v;
    wire [H_W-1:0]  step_hv, step_d;
    parallax_step #(.UV_W(UV_W), .H_W(H_W), .V_W(V_W), .V_F(V_F)) u_step (
        .clk(clk), .rst(rst), .in_valid(op_valid),
        .u_i(op_u), .v_i(op_v), .h_i(op_h), .hv_prev_i(op_hv), .d_prev_i(op_d), .vu_i(op_vu), .vv_i(op_vv),
        .vh_i(op_vh), .out_valid(step_valid), .u_o(step_u), .v_o(step_v), .hv_o(step_hv), .d_o(step_d)
    );
    // the side data travels beside the step's seven stages
    reg [7*SIDE_W-1:0] side;
    always @(posedge clk) side <= {side[6*SIDE_W-1:0], op_side};
    wire [SIDE_W-1:0] wb_side = side[6*SIDE_W +: SIDE_W];
    wire [SL_W-1:0]   wb_id = wb_side[SIDE_W-1 -: SL_W];
    wire [H_W-1:0]    wb_thr = wb_side[2 * ITER_W +: H_W];
    wire [ITER_W-1:0] wb_it = wb_side[ITER_W +: ITER_W] + {{(ITER_W - 1) {1'b0}}, 1'b1};  // steps after this one
    wire              wb_cap = wb_it == wb_side[0 +: ITER_W];                          // the cap is spent

    // ---- the step's result: stop or go on. |d| <= threshold as -threshold <= d <= threshold: two carry
    // chains side by side instead of a negation and a comparison in a row ----
    wire signed [H_W:0] d_x = {step_d[H_W-1], step_d};
    wire signed [H_W:0] thr_x = {1'b0, wb_thr};
    wire signed [H_W+1:0] d_plus_thr = {d_x[H_W], d_x} + {thr_x[H_W], thr_x};
    // registered before it reaches the slots (the write-back gets a clock of its own)
    reg              wbq_valid, wbq_le, wbq_ge, wbq_cap;
    reg [SL_W-1:0]   wbq_id;
    reg [ITER_W-1:0] wbq_it;
    reg [UV_W-1:0]   wbq_u, wbq_v;
    reg [H_W-1:0]    wbq_hv, wbq_d;
    always @(posedge clk) begin
        if (rst) wbq_valid <= 1'b0;
        else wbq_valid <= step_valid;
        wbq_le <= d_x <= thr_x;          // d <= threshold
        wbq_ge <= ~d_plus_thr[H_W+1];    // d >= -threshold
        wbq_cap <= wb_cap;
        wbq_id <= wb_id;
        wbq_it <= wb_it;
        wbq_u <= step_u;
        wbq_v <= step_v;
        wbq_hv <= step_hv;
        wbq_d <= step_d;
    end
    wire wbq_conv = wbq_le & wbq_ge;

    // the slot each event is for, one-hot
    wire [SLOTS-1:0] acc_oh = accept ? free_first : {SLOTS{1'b0}};
    wire [SLOTS-1:0] reqd_oh = (req_valid & req_ready) ? one << req_id : {SLOTS{1'b0}};
    wire [SLOTS-1:0] reql_oh = req_load ? fetch_first : {SLOTS{1'b0}};
    wire [SLOTS-1:0] rsp_oh = rsp_ok ? rsp_sel : {SLOTS{1'b0}};
    wire [SLOTS-1:0] wb_oh = wbq_valid ? one << wbq_id : {SLOTS{1'b0}};
    wire [SLOTS-1:0] out_oh = out_load ? done_first : {SLOTS{1'b0}};

    generate
        for (g = 0; g < SLOTS; g = g + 1) begin : g_slot
            // the events of one clock are for slots in different states, so for different slots
            reg [2:0]        st_q;
            reg [UV_W-1:0]   u_q, v_q;
            reg [H_W-1:0]    hv_q, d_q, thr_q;
            reg [V_W-1:0]    vu_q, vv_q, vh_q;
            reg [ITER_W-1:0] max_q, it_q;
            reg              cv_q;
            reg [TAG_W-1:0]  tag_q;
            always @(posedge clk) begin
                if (rst) st_q <= S_FREE;
                else if (acc_oh[g]) st_q <= s_max_iter == {ITER_W{1'b0}} ? S_DONE : S_FETCH;
                else if (reqd_oh[g]) st_q <= S_WAIT;
                else if (reql_oh[g]) st_q <= S_REQ;
                else if (rsp_oh[g]) st_q <= S_STEP;
                else if (wb_oh[g]) st_q <= (wbq_conv | wbq_cap) ? S_DONE : S_FETCH;
                else if (out_oh[g]) st_q <= S_FREE;
                if (acc_oh[g]) begin
                    u_q <= s_u;
                    v_q <= s_v;
                    hv_q <= s_hv0;
                    d_q <= {H_W{1'b0}};
                    vu_q <= s_vu;
                    vv_q <= s_vv;
                    vh_q <= s_vh;
                    thr_q <= s_threshold;
                    max_q <= s_max_iter;
                    it_q <= {ITER_W{1'b0}};
                    cv_q <= 1'b0;
                    tag_q <= s_tag;
                end else if (wb_oh[g]) begin
                    it_q <= wbq_it;
                    cv_q <= wbq_conv;
                    if (!wbq_conv) begin  // converged: P_i stays the answer
                        u_q <= wbq_u;
                        v_q <= wbq_v;
                        hv_q <= wbq_hv;
                        d_q <= wbq_d;
                    end
                end
            end
            assign st_all[3 * g +: 3] = st_q;
            assign u_all[UV_W * g +: UV_W] = u_q;
            assign v_all[UV_W * g +: UV_W] = v_q;
            assign hv_all[H_W * g +: H_W] = hv_q;
            assign d_all[H_W * g +: H_W] = d_q;
            assign thr_all[H_W * g +: H_W] = thr_q;
            assign vu_all[V_W * g +: V_W] = vu_q;
            assign vv_all[V_W * g +: V_W] = vv_q;
            assign vh_all[V_W * g +: V_W] = vh_q;
            assign max_all[ITER_W * g +: ITER_W] = max_q;
            assign it_all[ITER_W * g +: ITER_W] = it_q;
            assign cv_all[g] = cv_q;
            assign tag_all[TAG_W * g +: TAG_W] = tag_q;
        end
    endgenerate

    // ---- the request and result registers ----
    always @(posedge clk) begin
        if (rst) begin
            req_valid <= 1'b0;
            m_valid <= 1'b0;
        end else begin
            if (req_load) begin
                req_valid <= 1'b1;
                req_u <= fetch_u;
                req_v <= fetch_v;
                req_id <= fetch_idx;
            end else if (req_ready) begin
                req_valid <= 1'b0;
            end
            if (out_load) begin
                m_valid <= 1'b1;
                m_u <= done_u;
                m_v <= done_v;
                m_iters <= done_it;
                m_converged <= done_cv;
                m_tag <= done_tag;
            end else if (m_ready) begin
                m_valid <= 1'b0;
            end
        end
    end
endmodule
`default_nettype wire
