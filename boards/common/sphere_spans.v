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
// accepted. Cycles: a shift-and-add multiplier and a digit-by-digit square root, shared, MUL_STEPS and
// SQRT_STEPS bits per clock; per split point 9/MUL_STEPS (m * v) + 9/MUL_STEPS (DX^2) + 14/SQRT_STEPS + 4.
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
    parameter SCENE_FILE = "",
    parameter SPLIT_FILE = ""
) (
    input  wire             clk,
    input  wire             rst_n,
    input  wire             start,
    input  wire [Y_W-1:0]   y,
    output reg              busy,
    output reg              m_valid,
    input  wire             m_ready,
    output reg  [OBJ_W-1:0] m_obj,
    output reg  [X_W-1:0]   m_x0,      // first pixel
    output reg  [9:0]       m_l,       // intervals: pixels m_x0 .. m_x0 + m_l
    output reg  [47:0]      m_n1,      // {z, y, x} at the first pixel, signed 16 bits each
    output reg  [47:0]      m_n2       // ... at the last pixel
);
    localparam R_W = 9;                // r2 = 2r <= 510
    localparam F = 8;                  // fraction bits of the split table: v_j in 0 .. 256, R_W bits
    localparam RAD_W = 2 * R_W + 2 * ZF;
    localparam Z_W = RAD_W / 2;
    localparam J_W = $clog2(K + 1);

    generate
        if (N_OBJ < 1 || N_OBJ > (1 << OBJ_W) || K < 1 || ZF < 0 || ZF > 6 || Y_W > 10 || X_W != 11)
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

    // ---- shared arithmetic -------------------------------------------------------------------------------
    reg mul_start;
    reg [R_W-1:0] mul_a, mul_b;
    wire mul_busy, mul_done;
    wire [2*R_W-1:0] mul_p;
    seq_mul #(.A_W(R_W), .B_W(R_W), .STEPS_PER_CLK(MUL_STEPS)) u_mul (
        .clk(clk), .rst_n(rst_n), .start(mul_start), .a(mul_a), .b(mul_b), .busy(mul_busy), .done(mul_done),
        .p(mul_p)
    );
    reg sq_start;
    reg [RAD_W-1:0] sq_x;
    wire sq_busy, sq_done;
    wire [Z_W-1:0] sq_root;
    isqrt #(.X_W(RAD_W), .STEPS_PER_CLK(SQRT_STEPS)) u_sqrt (
        .clk(clk), .rst_n(rst_n), .start(sq_start), .x(sq_x), .busy(sq_busy), .done(sq_done), .root(sq_root)
    );
    wire unused_busy;
    assign unused_busy = mul_busy | sq_busy;

    // ---- sequencer ---------------------------------------------------------------------------------------
    localparam S_IDLE = 4'd0, S_OBJ = 4'd1, S_DY2 = 4'd2, S_S = 4'd3, S_P = 4'd4, S_P2 = 4'd5,
               S_DX2 = 4'd6, S_Z = 4'd7, S_EMIT = 4'd8;
    reg [3:0] st;
    reg [Y_W-1:0] y_q;
    reg [OBJ_W:0] obj;
    reg signed [12:0] dy;              // 2y + 1 - 2cy
    reg [2*R_W-1:0] w2;                // R2^2 - DY^2
    reg [R_W-1:0] m;                   // odd; chord = m + 1 pixels
    reg [X_W-1:0] x0;
    reg [J_W-1:0] j;
    reg [R_W-1:0] p, p_prev;
    reg signed [R_W+1:0] dx;
    reg [47:0] n_prev;

    wire [47:0] cur = scene[obj[OBJ_W-1:0]];
    wire [10:0] cur_cx = cur[47:37];
    wire [9:0] cur_cy = cur[36:27];
    wire [17:0] cur_r2sq = cur[26:9];
    wire [8:0] cur_r2 = cur[8:0];
    wire signed [12:0] dy_d = $signed({2'b00, y_q, 1'b1}) - $signed({2'b00, cur_cy, 1'b0});
    wire [12:0] ady_d = dy_d[12] ? -dy_d : dy_d;
    wire [R_W-1:0] s_root = sq_root[Z_W-1:ZF];
    wire [R_W-1:0] m_d = s_root[0] ? s_root : s_root - {{(R_W - 1) {1'b0}}, 1'b1};
    wire [R_W+F-1:0] pv = mul_p[R_W+F-1:0] + {{(R_W) {1'b0}}, 1'b1, {(F - 1) {1'b0}}};
    wire [R_W-1:0] p_d = pv[R_W+F-1:F];
    wire signed [R_W+1:0] dx_d = $signed({1'b0, p_d, 1'b0}) - $signed({2'b00, m});
    wire [R_W+1:0] adx_d = dx_d[R_W+1] ? -dx_d : dx_d;
    wire last_obj = (obj == N_OBJ - 1);
    wire unused_prod;
    assign unused_prod = &{1'b0, mul_p[2*R_W-1:R_W+F], adx_d[R_W+1:R_W], ady_d[12:R_W], pv[F-1:0]};
    // the normal at the current split point: (dx, dy, z) * 2^ZF, 16 bits each
    wire signed [15:0] dx16 = {{(16 - R_W - 2) {dx[R_W+1]}}, dx};
    wire signed [15:0] dy16 = {{3{dy[12]}}, dy};
    wire [47:0] n_cur = {{(16 - Z_W) {1'b0}}, sq_root, dy16 <<< ZF, dx16 <<< ZF};

    always @(posedge clk) begin
        mul_start <= 1'b0;
        sq_start <= 1'b0;
        if (!rst_n) begin
            st <= S_IDLE;
            busy <= 1'b0;
            m_valid <= 1'b0;
        end else begin
            case (st)
                S_IDLE: if (start) begin
                    busy <= 1'b1;
                    y_q <= y;
                    obj <= {(OBJ_W + 1) {1'b0}};
                    st <= S_OBJ;
                end
                S_OBJ: begin
                    // this sphere's line: DY, and DY^2 if the line meets it
                    dy <= dy_d;
                    if (ady_d >= {4'd0, cur_r2}) begin
                        if (last_obj) begin
                            busy <= 1'b0;
                            st <= S_IDLE;
                        end else obj <= obj + {{OBJ_W{1'b0}}, 1'b1};
                    end else begin
                        mul_a <= ady_d[R_W-1:0];
                        mul_b <= ady_d[R_W-1:0];
                        mul_start <= 1'b1;
                        st <= S_DY2;
                    end
                end
                S_DY2: if (mul_done) begin
                    w2 <= cur_r2sq - mul_p;
                    sq_x <= {cur_r2sq - mul_p, {(2 * ZF) {1'b0}}};
                    sq_start <= 1'b1;
                    st <= S_S;
                end
                S_S: if (sq_done) begin
                    if (s_root == {R_W{1'b0}}) begin
                        if (last_obj) begin
                            busy <= 1'b0;
                            st <= S_IDLE;
                        end else begin
                            obj <= obj + {{OBJ_W{1'b0}}, 1'b1};
                            st <= S_OBJ;
                        end
                    end else begin
                        m <= m_d;
                        x0 <= cur_cx - {{(X_W - R_W) {1'b0}}, (m_d >> 1) + {{(R_W - 1) {1'b0}}, 1'b1}};
                        j <= {J_W{1'b0}};
                        st <= S_P;
                    end
                end
                S_P: begin
                    mul_a <= m;
                    mul_b <= split[j];
                    mul_start <= 1'b1;
                    st <= S_P2;
                end
                S_P2: if (mul_done) begin
                    p <= p_d;
                    dx <= dx_d;
                    if (j != {J_W{1'b0}} && p_d == p_prev) begin
                        // the same pixel as the previous point: no sub-span
                        if (j == K) st <= S_EMIT;
                        else begin
                            j <= j + {{(J_W - 1) {1'b0}}, 1'b1};
                            st <= S_P;
                        end
                    end else begin
                        mul_a <= adx_d[R_W-1:0];
                        mul_b <= adx_d[R_W-1:0];
                        mul_start <= 1'b1;
                        st <= S_DX2;
                    end
                end
                S_DX2: if (mul_done) begin
                    sq_x <= {w2 - mul_p, {(2 * ZF) {1'b0}}};
                    sq_start <= 1'b1;
                    st <= S_Z;
                end
                S_Z: if (sq_done) begin
                    n_prev <= n_cur;
                    p_prev <= p;
                    if (j != {J_W{1'b0}}) begin
                        m_valid <= 1'b1;
                        m_obj <= obj[OBJ_W-1:0];
                        m_x0 <= x0 + {{(X_W - R_W) {1'b0}}, p_prev};
                        m_l <= {{(10 - R_W) {1'b0}}, p - p_prev};
                        m_n1 <= n_prev;
                        m_n2 <= n_cur;
                    end
                    st <= S_EMIT;
                end
                S_EMIT: if (!m_valid || m_ready) begin
                    // (the sub-span, if any, is accepted) next point, next sphere or the end of the line
                    m_valid <= 1'b0;
                    if (j == K) begin
                        if (last_obj) begin
                            busy <= 1'b0;
                            st <= S_IDLE;
                        end else begin
                            obj <= obj + {{OBJ_W{1'b0}}, 1'b1};
                            st <= S_OBJ;
                        end
                    end else begin
                        j <= j + {{(J_W - 1) {1'b0}}, 1'b1};
                        st <= S_P;
                    end
                end
                default: st <= S_IDLE;
            endcase
        end
    end
endmodule
`default_nettype wire
