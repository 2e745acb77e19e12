// parallax_wrap - a place-and-route harness for parallax_iter (make synth; docs/methods.md). The UP5K in SG48
// has far fewer pins than the unit's ports, so a fragment is shifted in serially and the result is XOR-reduced;
// the height memory is a 256 x 16 block RAM (registered read, written from the shift register) answering every
// request two clocks later, so the timing report sees the unit's own register-to-register paths and a real
// fetch loop. Not a usable top level: only for area and Fmax.
`timescale 1ns / 1ps
`default_nettype none
module parallax_wrap (
    input  wire clk,
    input  wire rst_n,
    input  wire din,
    input  wire strobe,
    input  wire we,
    output reg  dout,
    output reg  flag
);
    localparam UV_W = 24, H_W = 16, V_W = 16, ITER_W = 6, TAG_W = 8, SLOTS = 4, ID_W = 2;
    localparam FRAG_W = 2 * UV_W + 5 * H_W + ITER_W + TAG_W;  // u, v, hv0, vu, vv, vh, threshold, max_iter, tag

    reg [FRAG_W-1:0] sh;
    reg strobe_q, we_q, rst_q, m_ready;
    always @(posedge clk) begin
        sh <= {sh[FRAG_W-2:0], din};
        strobe_q <= strobe;
        we_q <= we;
        rst_q <= ~rst_n;
        m_ready <= sh[0] | strobe_q;
    end

    wire              s_ready, req_valid, m_valid, m_converged, busy;
    wire [UV_W-1:0]   req_u, req_v, m_u, m_v;
    wire [ID_W-1:0]   req_id;
    wire [ITER_W-1:0] m_iters;
    wire [TAG_W-1:0]  m_tag;
    reg               rsp_valid;
    reg  [ID_W-1:0]   rsp_id;
    wire [H_W-1:0]    rsp_h;
    parallax_iter #(.UV_W(UV_W), .H_W(H_W), .V_W(V_W), .ITER_W(ITER_W), .TAG_W(TAG_W), .SLOTS(SLOTS)) u_iter (
        .clk(clk), .rst(rst_q),
        .s_valid(strobe_q), .s_ready(s_ready),
        .s_u(sh[0 +: UV_W]), .s_v(sh[UV_W +: UV_W]), .s_hv0(sh[2 * UV_W +: H_W]),
        .s_vu(sh[2 * UV_W + H_W +: V_W]), .s_vv(sh[2 * UV_W + H_W + V_W +: V_W]),
        .s_vh(sh[2 * UV_W + H_W + 2 * V_W +: V_W]), .s_threshold(sh[2 * UV_W + H_W + 3 * V_W +: H_W]),
        .s_max_iter(sh[2 * UV_W + 2 * H_W + 3 * V_W +: ITER_W]),
        .s_tag(sh[2 * UV_W + 2 * H_W + 3 * V_W + ITER_W +: TAG_W]),
        .req_valid(req_valid), .req_ready(1'b1), .req_u(req_u), .req_v(req_v), .req_id(req_id),
        .rsp_valid(rsp_valid), .rsp_id(rsp_id), .rsp_h(rsp_h),
        .m_valid(m_valid), .m_ready(m_ready), .m_u(m_u), .m_v(m_v), .m_iters(m_iters), .m_converged(m_converged),
        .m_tag(m_tag), .busy(busy)
    );

    // the height memory: texel (u, v) of a 16 x 16 map (the top four fraction bits of each coordinate)
    reg [H_W-1:0] mem[0:255];
    reg [H_W-1:0] rd;
    reg           v1;
    reg [ID_W-1:0] id1;
    always @(posedge clk) begin
        if (we_q) mem[sh[7:0]] <= sh[8 +: H_W];
        rd <= mem[{req_v[15:12], req_u[15:12]}];
        v1 <= req_valid;
        id1 <= req_id;
        rsp_valid <= v1;
        rsp_id <= id1;
    end
    reg [H_W-1:0] rd_q;
    always @(posedge clk) rd_q <= rd;
    assign rsp_h = rd_q;

    always @(posedge clk) begin
        dout <= ^{m_u, m_v, m_iters, m_converged, m_tag, m_valid};
        flag <= s_ready ^ busy;
    end

    wire unused = &{1'b0, req_u[UV_W-1:16], req_u[11:0], req_v[UV_W-1:16], req_v[11:0]};
endmodule
`default_nettype wire
