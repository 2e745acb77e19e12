// board_shader - one shader pass of a sub-span: end normals as sphere_spans gives them, a light vector, the
// exponent, the strength and the length in; the span's pixels out (AXI4-Stream, tlast on the last).
// SCAFFOLD (until spec_shader lands from issue 13): the span is sent to spec_stream flat, n = 0, C =
// strength, so every pixel is the strength; the vectors are ignored. The C++ model mirrors it
// (sim/board/board_shaders.cpp, flat_shader).
`timescale 1ns / 1ps
`default_nettype none
module board_shader #(
    parameter SMALL = 1,
    parameter ROM9_FILE = "",
    parameter ROM12_FILE = ""
) (
    input  wire        clk,
    input  wire        rst_n,
    input  wire        s_valid,
    output wire        s_ready,
    input  wire [47:0] s_n1,
    input  wire [47:0] s_n2,
    input  wire [47:0] s_light,
    input  wire [9:0]  s_n,
    input  wire [15:0] s_strength,
    input  wire [9:0]  s_l,
    output wire        m_valid,
    input  wire        m_ready,
    output wire [15:0] m_data,
    output wire        m_last
);
    wire [127:0] desc = {32'd0, 32'd0, 16'd0, 6'd0, s_l, 6'd0, 10'd0, s_strength};
    spec_stream #(
        .TBL_AW(8), .INTERP(1), .INTERP_FRAC(10), .DELTA_W(10), .SCALE_W(16), .SCALE_FRAC(13),
        .ROM9_FILE(ROM9_FILE), .ROM12_FILE(ROM12_FILE)
    ) u_stream (
        .clk(clk), .rst_n(rst_n), .s_axis_tvalid(s_valid), .s_axis_tready(s_ready), .s_axis_tdata(desc),
        .m_axis_tvalid(m_valid), .m_axis_tready(m_ready), .m_axis_tdata(m_data), .m_axis_tlast(m_last)
    );
    wire unused;
    assign unused = &{1'b0, s_n1, s_n2, s_light, s_n, SMALL[0]};
endmodule
`default_nettype wire
