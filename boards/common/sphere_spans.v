// sphere_spans - the spans of one scanline: for each sphere the chord the line cuts, split into sub-spans,
// with the exact sphere normal at each sub-span's two end pixels (docs/boards.md, "Spans").
//
// Geometry in half-pixel units, orthographic view along -z: pixel (x, y) has its centre at
// DX = 2x + 1 - 2cx, DY = 2y + 1 - 2cy from the sphere's centre (cx, cy) (whole pixels), radius R2 = 2r.
// Per sphere and line:  W2 = R2^2 - DY^2 (nothing when |DY| >= R2);  s = floor(sqrt(W2)) and m = the largest
// odd number <= s: the chord is the m + 1 pixels with odd DX in [-m, m] (nothing when s = 0), its first
// pixel x0 = cx - (m + 1) / 2. Split points p_j = (m * v_j + 2^(F-1)) >> F, j = 0..K, from the table v
// (v_0 = 0, v_K = 2^F, non-decreasing: SPLIT_FILE); repeated points are skipped. Sub-span j runs from pixel
// p_j to p_(j+1) of the chord, both included: neighbours share their end pixel (written twice, the later
// wins), so each split point needs one square root. At a point, DX = 2p - m and the normal is
// n = (DX, DY, Z) * 2^ZF with Z = sqrt(W2 - DX^2), computed as floor(sqrt((W2 - DX^2) << 2ZF)); |n| = R2 * 2^ZF
// up to that rounding.
// Scene (SCENE_FILE, one 48-bit word per sphere, N_OBJ words): {cx[10:0], cy[9:0], r2sq[17:0], r2[8:0]},
// r2 = 2r, r2sq = r2^2. The scene generator (boardgen) checks that every sphere lies inside the picture.
// Output: one beat per sub-span, AXI4-Stream rules (valid held, data stable until ready).
// Handshake: start (with y) is taken while busy = 0; busy stays 1 until the line's last sub-span has been
// accepted. Three stages overlap: the point generator (a shift-and-add multiplier, MUL_STEPS bits per
// clock: m * v_j and DX^2), the square root (digit by digit, SQRT_STEPS bits per clock) and the emitter.
// A split point costs about max(2 (9 / MUL_STEPS + 2), 14 / SQRT_STEPS + 2) clocks; a sphere's line adds a
// square root for its chord.
// SERIAL = 1 (where logic cells are short: the iCEBreaker, whose shader takes thousands of clocks a sub-span):
// stage A1 starts a sphere or a split point only when the stages after it are empty, so a token's x0, DY, p, DX
// and W2 stay in A1's registers while it runs, and the stages read them there instead of carrying copies
// (about 5 x 50 flip-flops fewer). The same sub-spans, a few clocks more per point. Nor does A1 start one while
// the output holds a sub-span (m_valid): the sub-span's last point then stays in stage C's registers and A1's
// until it is taken, so m_n2 and m_obj are read there (no output register), and m_n1, the point before, is
// loaded from there once the sub-span is taken (or at a chord's first point).
// Reset: rst_n is synchronous, active low: idle, no output.
`timescale 1ns / 1ps
`default_nettype none
module sphere_spans #(
    parameter N_OBJ = 5,
    parameter OBJ_W = 3,
    parameter K = 16,                  // split intervals per chord (table of K + 1 points)
    parameter ZF = 5,                  // fraction bits of the normals
    parameter X_W = 11,
    parameter Y_W = 10,
    parameter MUL_STEPS = 1,
    parameter SQRT_STEPS = 1,
    parameter SERIAL = 0,              // 1: one token in the stages at a time (see above)
    parameter SCENE_FILE = "",
    parameter SPLIT_FILE = ""
) (
    input  wire             clk,
    input  wire             rst_n,
    input  wire             start,
    input  wire [Y_W-1:0]   y,
    output reg              busy,      // (combinational: any stage holds work)
    output reg              m_valid,
    input  wire             m_ready,
    output wire [OBJ_W-1:0] m_obj,
    output reg  [X_W-1:0]   m_x0,      // first pixel
    output reg  [9:0]       m_l,       // intervals: pixels m_x0 .. m_x0 + m_l
    output reg  [47:0]      m_n1,      // {z, y, x} at the first pixel, signed 16 bits each
    output wire [47:0]      m_n2       // ... at the last pixel
);
    localparam R_W = 9;                // r2 = 2r <= 510
    localparam F = 8;                  // fraction bits of the split table: v_j in 0 .. 256, R_W bits
    localparam RAD_W = 2 * R_W + 2 * ZF;
    localparam Z_W = RAD_W / 2;
    localparam J_W = $clog2(K + 1);

    generate
        if (N_OBJ < 1 || N_OBJ > (1 << OBJ_W) || K < 1 || ZF < 0 || ZF > 6 || Y_W > 10 || X_W != 11 ||
            (SERIAL != 0 && SERIAL != 1))
        begin : g_bad_params
            initial begin
                $display("sphere_spans: parameters out of range (%m)");
                $finish;
            end
            sphere_spans_parameters_out_of_range u_error ();
        end
    endgenerate

    // scene and split table (small: logic, read asynchronously)
    reg [47:0] scene[0:N_OBJ-1];
    reg [R_W-1:0] split[0:K];
    initial begin
        $readmemh(SCENE_FILE, scene);
        $readmemh(SPLIT_FILE, split);
    end

    // ---- stage A1: spheres and split points -----------------------------------------------------------------
    reg mul_start;
    reg [R_W-1:0] mul_a, mul_b;
    wire mul_busy, mul_done;
    wire [2*R_W-1:0] mul_p;
    seq_mul #(.A_W(R_W), .B_W(R_W), .STEPS_PER_CLK(MUL_STEPS)) u_mul (
        .clk(clk), .rst_n(rst_n), .start(mul_start), .a(mul_a), .b(mul_b), .busy(mul_busy), .done(mul_done),
        .p(mul_p)
    );
    // tokens toward the square root: a chord (radicand W2 << 2ZF, gives s) or a split point (gives Z).
    // A1 -> A2: {is_point, first, obj, x0, dy, p, dx, w2}; A2 -> B: the same with the radicand for w2.
    localparam TOK_W = 1 + 1 + OBJ_W + X_W + 13 + R_W + (R_W + 2) + RAD_W;
    localparam A2_W = TOK_W - RAD_W + 2 * R_W;
    reg a2_v;                          // stage A2's input register holds a token
    reg [A2_W-1:0] a2_tok;
    wire a2_take;                      // A2 is done with its token this cycle
    wire a2_free = !a2_v;              // (not || a2_take: no combinational path back through the stages)
    reg s_v;                           // stage B has returned the chord's s to stage A1
    reg [R_W-1:0] s_q;
    reg s_zero;                        // s = 0: the chord has no pixel

    // at most one carry chain between registers in each state (for the iCE40's clock)
    localparam A_IDLE = 4'd0, A_OBJ = 4'd1, A_DY = 4'd2, A_ABS = 4'd3, A_CMP = 4'd4, A_DY2 = 4'd5, A_S = 4'd6,
               A_X0 = 4'd7, A_P = 4'd8, A_P2 = 4'd9, A_P3 = 4'd10, A_HAND = 4'd11, A_MISS = 4'd12;
    reg miss;                          // the line misses the sphere: |DY| >= R2
    reg [3:0] st;
    reg [47:0] cur;                    // the sphere's scene word
    reg [R_W+3:0] ady;                 // |DY|
    reg [Y_W-1:0] y_q;
    reg [OBJ_W:0] obj;
    reg signed [12:0] dy;              // 2y + 1 - 2cy
    reg [2*R_W-1:0] w2;                // R2^2 - DY^2
    reg [R_W-1:0] m;                   // odd; chord = m + 1 pixels
    reg [X_W-1:0] x0;
    reg [J_W-1:0] j;
    reg [R_W-1:0] p, p_prev;
    reg first;                         // the next point is the chord's first
    reg signed [R_W+1:0] dx;
    reg m_chord_pending;               // A_HAND hands the chord's token (else a point's)

    wire [10:0] cur_cx = cur[47:37];
    wire [9:0] cur_cy = cur[36:27];
    wire [17:0] cur_r2sq = cur[26:9];
    wire [8:0] cur_r2 = cur[8:0];
    wire signed [12:0] dy_d = $signed({2'b00, y_q, 1'b1}) - $signed({2'b00, cur_cy, 1'b0});
    wire [12:0] ady_d = dy[12] ? -dy : dy;
    wire [R_W-1:0] m_d = s_q[0] ? s_q : s_q - {{(R_W - 1) {1'b0}}, 1'b1};
    wire [R_W+F-1:0] pv = mul_p[R_W+F-1:0] + {{(R_W) {1'b0}}, 1'b1, {(F - 1) {1'b0}}};
    wire [R_W-1:0] p_d = pv[R_W+F-1:F];
    wire signed [R_W+1:0] dx_d = $signed({1'b0, p, 1'b0}) - $signed({2'b00, m});
    localparam integer LAST_OBJ = N_OBJ - 1;
    localparam integer LAST_J = K - 1;
    // "this is the last sphere / split point", kept as flags beside the counters (shallow next-state logic)
    reg last_obj, last_j;
    wire [OBJ_W:0] obj_inc = obj + {{OBJ_W{1'b0}}, 1'b1};
    wire [J_W-1:0] j_inc = j + {{(J_W - 1) {1'b0}}, 1'b1};
    wire obj_inc_last = (obj == LAST_OBJ[OBJ_W:0] - 1'b1);
    wire j_inc_last = (j == LAST_J[J_W-1:0]);
    wire unused_a;
    assign unused_a = &{1'b0, mul_busy, mul_p[2*R_W-1:R_W+F], pv[F-1:0]};

    // SERIAL: a sphere (A_OBJ) or a point (A_P) starts only when no token is in the stages after A1: x0, dy, w2
    // (set after A_OBJ), p and dx (set after A_P) then hold while their token runs
    // (and, with the output read in place, not while the output holds a sub-span: m_valid)
    wire a1_hold = (SERIAL != 0) && (a2_v || b_v || sq_run || c_v || m_valid);
    always @(posedge clk) begin
        mul_start <= 1'b0;
        if (!rst_n) begin
            st <= A_IDLE;
            a2_v <= 1'b0;
        end else begin
            if (a2_take) a2_v <= 1'b0;
            case (st)
                A_IDLE: if (start && !busy) begin
                    y_q <= y;
                    obj <= {(OBJ_W + 1) {1'b0}};
                    last_obj <= (N_OBJ == 1);
                    st <= A_OBJ;
                end
                A_OBJ: if (!a1_hold) begin
                    cur <= scene[obj[OBJ_W-1:0]];
                    st <= A_DY;
                end
                A_DY: begin
                    dy <= dy_d;
                    st <= A_ABS;
                end
                A_ABS: begin
                    ady <= ady_d;
                    st <= A_CMP;
                end
                A_CMP: begin
                    miss <= (ady >= {4'd0, cur_r2});
                    st <= A_MISS;
                end
                A_MISS: begin
                    if (miss) begin
                        if (last_obj) st <= A_IDLE;
                        else begin
                            obj <= obj_inc;
                            last_obj <= obj_inc_last;
                            st <= A_OBJ;
                        end
                    end else begin
                        mul_a <= ady[R_W-1:0];
                        mul_b <= ady[R_W-1:0];
                        mul_start <= 1'b1;
                        st <= A_DY2;
                    end
                end
                A_DY2: if (mul_done) begin
                    w2 <= cur_r2sq - mul_p;
                    st <= A_HAND;          // the chord's token goes to the square root for s
                end
                A_S: if (s_v) begin
                    if (s_zero) begin
                        if (last_obj) st <= A_IDLE;
                        else begin
                            obj <= obj_inc;
                            last_obj <= obj_inc_last;
                            st <= A_OBJ;
                        end
                    end else begin
                        m <= m_d;
                        st <= A_X0;
                    end
                end
                A_X0: begin
                    // x0 = cx - (m + 1) / 2 = cx + ~(m >> 1) (m odd)
                    x0 <= cur_cx + ~{{(X_W - R_W + 1) {1'b0}}, m[R_W-1:1]};
                    j <= {J_W{1'b0}};
                    last_j <= (K == 0);
                    first <= 1'b1;
                    st <= A_P;
                end
                A_P: if (!a1_hold) begin
                    mul_a <= m;
                    mul_b <= split[j];
                    mul_start <= 1'b1;
                    st <= A_P2;
                end
                A_P2: if (mul_done) begin
                    p <= p_d;
                    st <= A_P3;
                end
                A_P3: begin
                    dx <= dx_d;
                    if (!first && p == p_prev) begin
                        // the same pixel as the previous point: no sub-span
                        if (last_j) begin
                            if (last_obj) st <= A_IDLE;
                            else begin
                                obj <= obj_inc;
                                last_obj <= obj_inc_last;
                                st <= A_OBJ;
                            end
                        end else begin
                            j <= j_inc;
                            last_j <= j_inc_last;
                            st <= A_P;
                        end
                    end else st <= A_HAND;
                end
                A_HAND: if (a2_free) begin
                    // hand the chord (after A_DY2) or the point (after A_P2) to A2
                    a2_v <= 1'b1;
                    if (m_chord_pending) begin
                        a2_tok <= {1'b0, 1'b0, {OBJ_W{1'b0}}, {X_W{1'b0}}, 13'd0, {R_W{1'b0}}, {(R_W + 2) {1'b0}}, w2};
                        st <= A_S;
                    end else begin
                        a2_tok <= {1'b1, first, obj[OBJ_W-1:0], x0, dy, p, dx, w2};
                        p_prev <= p;
                        first <= 1'b0;
                        if (last_j) begin
                            if (last_obj) st <= A_IDLE;
                            else begin
                                obj <= obj_inc;
                                last_obj <= obj_inc_last;
                                st <= A_OBJ;
                            end
                        end else begin
                            j <= j_inc;
                            last_j <= j_inc_last;
                            st <= A_P;
                        end
                    end
                end
                default: st <= A_IDLE;
            endcase
        end
    end
    // A_HAND after A_DY2 hands the chord, after A_P2 a point
    always @(posedge clk) begin
        if (st == A_DY2) m_chord_pending <= 1'b1;
        else if (st == A_P3) m_chord_pending <= 1'b0;
    end

    // ---- stage A2: DX^2 for a point's radicand --------------------------------------------------------------
    reg b_v;                           // stage B's input register holds a token
    reg [TOK_W-1:0] b_tok;             // {is_point, first, obj, x0, dy, p, dx, radicand}
    wire b_take;                       // stage B takes its token into the square root
    wire b_free = !b_v;
    reg mul2_start;
    wire mul2_busy, mul2_done;
    wire [2*R_W-1:0] mul2_p;
    wire a2_point = a2_tok[A2_W-1];
    wire signed [R_W+1:0] a2_dx = (SERIAL != 0) ? dx : a2_tok[2*R_W +: R_W + 2];
    wire [R_W+1:0] a2_adx_d = a2_dx[R_W+1] ? -a2_dx : a2_dx;
    reg [R_W+1:0] a2_adx;              // |DX|, registered before the multiplier
    wire [2*R_W-1:0] a2_w2 = (SERIAL != 0) ? w2 : a2_tok[2*R_W-1:0];
    seq_mul #(.A_W(R_W), .B_W(R_W), .STEPS_PER_CLK(MUL_STEPS)) u_mul2 (
        .clk(clk), .rst_n(rst_n), .start(mul2_start), .a(a2_adx[R_W-1:0]), .b(a2_adx[R_W-1:0]), .busy(mul2_busy),
        .done(mul2_done), .p(mul2_p)
    );
    reg a2_sq;                         // the token's DX^2 is ready (or not needed: a chord)
    assign a2_take = a2_v && a2_sq && b_free;
    reg a2_new;                        // a point arrived last cycle: its |DX| is registered now
    always @(posedge clk) begin
        mul2_start <= 1'b0;
        a2_adx <= a2_adx_d;
        if (!rst_n) begin
            a2_sq <= 1'b0;
            a2_new <= 1'b0;
            b_v <= 1'b0;
        end else begin
            if (b_take) b_v <= 1'b0;
            // a token arrives: a chord needs nothing, a point starts its DX^2 once |DX| is registered
            a2_new <= a2_free && st == A_HAND && !m_chord_pending;
            mul2_start <= a2_new;
            if (a2_free && st == A_HAND) a2_sq <= m_chord_pending;
            else if (mul2_done) a2_sq <= 1'b1;
            if (a2_take) begin
                b_v <= 1'b1;
                b_tok <= {a2_tok[A2_W-1:2*R_W], a2_point ? a2_w2 - mul2_p : a2_w2, {(2 * ZF) {1'b0}}};
            end
        end
    end
    wire unused_a2;
    assign unused_a2 = &{1'b0, mul2_busy, a2_adx[R_W+1:R_W]};

    // ---- stage B: the square root ----------------------------------------------------------------------
    wire sq_busy, sq_done;
    wire [Z_W-1:0] sq_root;
    reg [TOK_W-RAD_W-1:0] sq_tag;      // the token's fields other than the radicand, while its root runs
    reg sq_run;                        // a token is in the square root
    assign b_take = b_v && !sq_run;
    isqrt #(.X_W(RAD_W), .STEPS_PER_CLK(SQRT_STEPS)) u_sqrt (
        .clk(clk), .rst_n(rst_n), .start(b_take), .x(b_tok[RAD_W-1:0]), .busy(sq_busy), .done(sq_done),
        .root(sq_root)
    );
    // stage C's input register: {first, obj, x0, dy, p, dx, z}
    localparam C_W = 1 + OBJ_W + X_W + 13 + R_W + (R_W + 2) + Z_W;
    reg c_v;
    reg [C_W-1:0] c_tok;
    wire c_take;
    wire tag_point = sq_tag[TOK_W-RAD_W-1];
    // a finished root leaves when its destination is free: stage A (s) always, stage C (z) when c_v is free
    wire sq_leave = sq_run && sq_done_q && (!tag_point || !c_v);
    reg sq_done_q;                     // the root is ready (held until it leaves)
    always @(posedge clk) begin
        if (!rst_n) begin
            sq_run <= 1'b0;
            sq_done_q <= 1'b0;
            s_v <= 1'b0;
            c_v <= 1'b0;
        end else begin
            s_v <= 1'b0;
            if (c_take) c_v <= 1'b0;
            if (b_take) begin
                sq_run <= 1'b1;
                sq_tag <= b_tok[TOK_W-1:RAD_W];
            end
            if (sq_done) sq_done_q <= 1'b1;
            if (sq_leave) begin
                sq_run <= 1'b0;
                sq_done_q <= 1'b0;
                if (tag_point) begin
                    c_v <= 1'b1;
                    c_tok <= {sq_tag[TOK_W-RAD_W-2:0], sq_root};
                end else begin
                    s_v <= 1'b1;
                    s_q <= sq_root[Z_W-1:ZF];
                    s_zero <= (sq_root[Z_W-1:ZF] == {R_W{1'b0}});
                end
            end
        end
    end
    wire unused_b;
    assign unused_b = &{1'b0, sq_busy};

    // ---- stage C: sub-spans from consecutive points -----------------------------------------------------
    wire c_first = c_tok[C_W-1];
    wire [OBJ_W-1:0] c_obj = c_tok[C_W-2 -: OBJ_W];
    wire [X_W-1:0] c_x0 = (SERIAL != 0) ? x0 : c_tok[C_W-2-OBJ_W -: X_W];
    wire signed [12:0] c_dy = (SERIAL != 0) ? dy : c_tok[C_W-2-OBJ_W-X_W -: 13];
    wire [R_W-1:0] c_p = (SERIAL != 0) ? p : c_tok[Z_W+R_W+2 +: R_W];
    wire signed [R_W+1:0] c_dx = (SERIAL != 0) ? dx : c_tok[Z_W +: R_W + 2];
    // (SERIAL: the tokens' copies of x0, dy, p, dx and w2 are not read; synthesis removes them)
    wire unused_c;
    assign unused_c = &{1'b0, a2_tok, c_tok};
    wire [Z_W-1:0] c_z = c_tok[Z_W-1:0];
    // the normal at the point: (dx, dy, z) * 2^ZF, 16 bits each
    wire signed [15:0] dx16 = {{(16 - R_W - 2) {c_dx[R_W+1]}}, c_dx};
    wire signed [15:0] dy16 = {{3{c_dy[12]}}, c_dy};
    wire [47:0] n_cur = {{(16 - Z_W) {1'b0}}, c_z, dy16 <<< ZF, dx16 <<< ZF};
    // SERIAL = 0: the previous point's normal is the output register n2_q: every take loads it (a chord's first
    // point too, while m_valid = 0), and m_n1 takes it with the next point. SERIAL = 1: the point stays in stage
    // C and A1 while the sub-span is held (a1_hold), so m_n2 is n_cur and m_obj c_obj, read there; m_n1 loads
    // n_cur at a chord's first point and when a sub-span is taken (its last point is the next one's first)
    reg [R_W-1:0] cp_prev;
    reg [47:0] n2_q;
    reg [OBJ_W-1:0] obj_q;
    assign m_n2 = (SERIAL != 0) ? n_cur : n2_q;
    assign m_obj = (SERIAL != 0) ? c_obj : obj_q;
    assign c_take = c_v && !m_valid;   // the output register is empty (m_ready does not reach further back)
    always @(posedge clk) begin
        if (!rst_n) begin
            m_valid <= 1'b0;
        end else begin
            if (m_valid && m_ready) begin
                m_valid <= 1'b0;
                if (SERIAL != 0) m_n1 <= n_cur;
            end
            if (c_take) begin
                cp_prev <= c_p;
                if (SERIAL == 0) n2_q <= n_cur;
                else if (c_first) m_n1 <= n_cur;
                if (!c_first) begin
                    m_valid <= 1'b1;
                    obj_q <= c_obj;
                    m_x0 <= c_x0 + {{(X_W - R_W) {1'b0}}, cp_prev};
                    m_l <= {{(10 - R_W) {1'b0}}, c_p - cp_prev};
                    if (SERIAL == 0) m_n1 <= n2_q;
                end
            end
        end
    end

    always @(*) busy = (st != A_IDLE) || a2_v || b_v || sq_run || c_v || m_valid;
endmodule
`default_nettype wire
