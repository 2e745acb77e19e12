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
        if (SLOTS < 1 || (1 << ID_W) < SLOTS || UV_W < 2 || H_W < 2 || V_W < 2 || V_F < 0 || V_F >= H_W + V_W ||
            ITER_W < 1 || TAG_W < 1) begin
            $display("parallax_iter: bad parameters SLOTS=%0d ID_W=%0d UV_W=%0d H_W=%0d V_W=%0d V_F=%0d ITER_W=%0d TAG_W=%0d (%m)",
                     SLOTS, ID_W, UV_W, H_W, V_W, V_F, ITER_W, TAG_W);
            $fatal(1);
        end
    end
`endif

    // ---- the slots ----
    reg [3*SLOTS-1:0] st;                // the slots' states, 3 bits each
    reg [UV_W-1:0]   sl_u  [0:SLOTS-1];
    reg [UV_W-1:0]   sl_v  [0:SLOTS-1];
    reg [H_W-1:0]    sl_hv [0:SLOTS-1];  // hV_(i-1)
    reg [H_W-1:0]    sl_d  [0:SLOTS-1];  // d_(i-1)
    reg [V_W-1:0]    sl_vu [0:SLOTS-1];
    reg [V_W-1:0]    sl_vv [0:SLOTS-1];
    reg [V_W-1:0]    sl_vh [0:SLOTS-1];
    reg [H_W-1:0]    sl_thr[0:SLOTS-1];
    reg [ITER_W-1:0] sl_max[0:SLOTS-1];
    reg [ITER_W-1:0] sl_it [0:SLOTS-1];  // steps done
    reg              sl_cv [0:SLOTS-1];
    reg [TAG_W-1:0]  sl_tag[0:SLOTS-1];

    // the lowest-numbered slot in each state of interest
    reg            free_any, fetch_any, done_any, busy_slots;
    reg [SL_W-1:0] free_idx, fetch_idx, done_idx;
    integer k;
    always @* begin
        free_any = 1'b0;
        fetch_any = 1'b0;
        done_any = 1'b0;
        busy_slots = 1'b0;
        free_idx = {SL_W{1'b0}};
        fetch_idx = {SL_W{1'b0}};
        done_idx = {SL_W{1'b0}};
        for (k = SLOTS - 1; k >= 0; k = k - 1) begin
            if (st[3 * k +: 3] == S_FREE) begin
                free_any = 1'b1;
                free_idx = k[SL_W-1:0];
            end
            if (st[3 * k +: 3] == S_FETCH) begin
                fetch_any = 1'b1;
                fetch_idx = k[SL_W-1:0];
            end
            if (st[3 * k +: 3] == S_DONE) begin
                done_any = 1'b1;
                done_idx = k[SL_W-1:0];
            end
            if (st[3 * k +: 3] != S_FREE) busy_slots = 1'b1;
        end
    end

    assign s_ready = free_any;
    assign busy = busy_slots | m_valid;
    wire accept = s_valid & free_any;
    wire req_load = (~req_valid | req_ready) & fetch_any;

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
    wire rsp_ok = rsp_valid & rsp_in_range & (st[3 * rsp_idx +: 3] == S_WAIT);

    wire            step_valid;
    wire [UV_W-1:0] step_u, step_v;
    wire [H_W-1:0]  step_hv, step_d;
    parallax_step #(.UV_W(UV_W), .H_W(H_W), .V_W(V_W), .V_F(V_F)) u_step (
        .clk(clk), .rst(rst), .in_valid(rsp_ok),
        .u_i(sl_u[rsp_idx]), .v_i(sl_v[rsp_idx]), .h_i(rsp_h), .hv_prev_i(sl_hv[rsp_idx]),
        .d_prev_i(sl_d[rsp_idx]), .vu_i(sl_vu[rsp_idx]), .vv_i(sl_vv[rsp_idx]), .vh_i(sl_vh[rsp_idx]),
        .out_valid(step_valid), .u_o(step_u), .v_o(step_v), .hv_o(step_hv), .d_o(step_d)
    );
    // the slot number travels beside the step's two stages
    reg [SL_W-1:0] id1, id2;
    always @(posedge clk) begin
        id1 <= rsp_idx;
        id2 <= id1;
    end

    // ---- the step's result: stop or go on ----
    wire [H_W-1:0]    abs_d = step_d[H_W-1] ? (~step_d + {{(H_W - 1) {1'b0}}, 1'b1}) : step_d;
    wire              wb_conv = abs_d <= sl_thr[id2];
    wire [ITER_W-1:0] wb_it = sl_it[id2] + {{(ITER_W - 1) {1'b0}}, 1'b1};
    wire              wb_cap = wb_it == sl_max[id2];

    always @(posedge clk) begin
        if (rst) begin
            for (k = 0; k < SLOTS; k = k + 1) st[3 * k +: 3] <= S_FREE;
            req_valid <= 1'b0;
            m_valid <= 1'b0;
        end else begin
            // a new fragment into the lowest free slot
            if (accept) begin
                st[3 * free_idx +: 3] <= s_max_iter == {ITER_W{1'b0}} ? S_DONE : S_FETCH;
                sl_u[free_idx] <= s_u;
                sl_v[free_idx] <= s_v;
                sl_hv[free_idx] <= s_hv0;
                sl_d[free_idx] <= {H_W{1'b0}};
                sl_vu[free_idx] <= s_vu;
                sl_vv[free_idx] <= s_vv;
                sl_vh[free_idx] <= s_vh;
                sl_thr[free_idx] <= s_threshold;
                sl_max[free_idx] <= s_max_iter;
                sl_it[free_idx] <= {ITER_W{1'b0}};
                sl_cv[free_idx] <= 1'b0;
                sl_tag[free_idx] <= s_tag;
            end
            // the request register: the held request leaves, the next one is loaded
            if (req_valid && req_ready) st[3 * req_id +: 3] <= S_WAIT;
            if (req_load) begin
                st[3 * fetch_idx +: 3] <= S_REQ;
                req_valid <= 1'b1;
                req_u <= sl_u[fetch_idx];
                req_v <= sl_v[fetch_idx];
                req_id <= fetch_idx;
            end else if (req_ready) begin
                req_valid <= 1'b0;
            end
            if (rsp_ok) st[3 * rsp_idx +: 3] <= S_STEP;
            // the step's write-back
            if (step_valid) begin
                sl_it[id2] <= wb_it;
                if (wb_conv) begin
                    sl_cv[id2] <= 1'b1;
                    st[3 * id2 +: 3] <= S_DONE;
                end else begin
                    sl_u[id2] <= step_u;
                    sl_v[id2] <= step_v;
                    sl_hv[id2] <= step_hv;
                    sl_d[id2] <= step_d;
                    st[3 * id2 +: 3] <= wb_cap ? S_DONE : S_FETCH;
                end
            end
            // the result register
            if ((~m_valid | m_ready) & done_any) begin
                st[3 * done_idx +: 3] <= S_FREE;
                m_valid <= 1'b1;
                m_u <= sl_u[done_idx];
                m_v <= sl_v[done_idx];
                m_iters <= sl_it[done_idx];
                m_converged <= sl_cv[done_idx];
                m_tag <= sl_tag[done_idx];
            end else if (m_ready) begin
                m_valid <= 1'b0;
            end
        end
    end
endmodule
`default_nettype wire
