// shade_passes - each sub-span through the shader twice: the diffuse pass (the light L, n = 1, strength
// kd: Lambert's max(0, N.L) as the core's cos^1) and the specular pass (the halfway vector H, the sphere's n,
// strength ks), and the two results paired per pixel (docs/boards.md, "Diffuse through the same core").
//
// SHADERS = 1: one shader takes the passes in turn, diffuse then specular per sub-span; its pixels come back
// in that order, the diffuse ones wait in a FIFO for their specular partners. SHADERS = 2: one shader per
// pass, both fed at once; the diffuse FIFO absorbs their skew.
// Per-object constants (SHADE_FILE, one word per object): {n[9:0], kd[15:0], ks[15:0]}, strengths UQ0.16.
// The light vectors l_* (L) and h_* (H) are the frame's, Q1.14, held by the caller while spans flow.
// Output: one pixel pair per clock at most, no backpressure (compose always takes it): the sphere, the pixel's
// x (x0 + i), both terms UQ0.16, m_last on a sub-span's last pixel.
// OUT_REG = 0 (where logic cells are short: the iCEBreaker, whose sink is a queue's write port): no output
// register; the pair leaves in the clock it is made, read where it is (the diffuse queue's head, the shader's
// output, the sub-span queue's head), a clock earlier and the same pixels. OUT_REG = 1: registered outputs.
// Reset: rst_n is synchronous, active low: empty, no output.
`timescale 1ns / 1ps
`default_nettype none
module shade_passes #(
    parameter N_OBJ = 5,
    parameter OBJ_W = 3,
    parameter X_W = 11,
    parameter SHADERS = 1,
    parameter SMALL = 1,
    parameter BACKEND = 0,             // board_shader's back end: 0 = spec_stream, 1 = spec_stream_seq
    parameter SHADE_FILE = "",
    parameter ROM9_FILE = "",
    parameter ROM12_FILE = "",
    parameter SETUP_DIR = "rom",       // the setups' tables and microcode (rom/setup_*.hex)
    parameter FIFO_LUTRAM = 0,         // sync_fifo's LUTRAM: the queues in distributed RAM
    parameter FIFO_QUEUE = 3,          // sync_fifo's QUEUE: its output queue's entries (0, 1 or 3)
    parameter META_AW = 8,             // the sub-spans' queue (object, x0): 2^META_AW + 2 or + 3 entries
    parameter OUT_REG = 1              // 0: the outputs are not registered (see above)
) (
    input  wire               clk,
    input  wire               rst_n,
    input  wire               s_valid,
    output wire               s_ready,
    input  wire [OBJ_W-1:0]   s_obj,
    input  wire [X_W-1:0]     s_x0,
    input  wire [9:0]         s_l,
    input  wire [47:0]        s_n1,
    input  wire [47:0]        s_n2,
    input  wire signed [15:0] l_x, l_y, l_z,
    input  wire signed [15:0] h_x, h_y, h_z,
    output wire               m_valid,
    output wire [OBJ_W-1:0]   m_obj,
    output wire [X_W-1:0]     m_x,
    output wire [15:0]        m_dif,
    output wire [15:0]        m_spc,
    output wire               m_last
);
    generate
        if (SHADERS != 1 && SHADERS != 2) begin : g_bad_params
            initial begin
                $display("shade_passes: SHADERS must be 1 or 2 (%m)");
                $finish;
            end
            shade_passes_parameters_out_of_range u_error ();
        end
    endgenerate

    reg [41:0] shade[0:N_OBJ-1];
    initial $readmemh(SHADE_FILE, shade);
    wire [41:0] k = shade[s_obj];
    wire [9:0] k_n = k[41:32];
    wire [15:0] k_kd = k[31:16];
    wire [15:0] k_ks = k[15:0];
    wire [47:0] light_l = {l_z, l_y, l_x};
    wire [47:0] light_h = {h_z, h_y, h_x};

    // sub-spans whose specular pixels are still to come: {obj, x0}
    wire meta_ready, meta_valid;
    wire [OBJ_W+X_W-1:0] meta;
    reg meta_pop;
    wire meta_push;

    // ---- the shaders' inputs ---------------------------------------------------------------------------
    wire d_out_valid, d_out_ready, d_out_last, s_out_valid, s_out_ready, s_out_last;
    wire [15:0] d_out_data, s_out_data;
    reg sent_d;                  // this sub-span's diffuse pass has been taken

    generate
        if (SHADERS == 1) begin : g_one
            // diffuse first, then specular, through one shader; its output alternates the same way
            wire in_valid, in_ready, out_valid, out_last;
            wire [15:0] out_data;
            wire out_ready;
            wire second = sent_d;                    // the diffuse pass of this sub-span is in
            assign in_valid = s_valid & meta_ready;
            assign s_ready = in_valid & in_ready & second;
            assign meta_push = s_ready;
            always @(posedge clk) begin
                if (!rst_n) sent_d <= 1'b0;
                else if (in_valid & in_ready) sent_d <= ~sent_d;
            end
            board_shader #(.SMALL(SMALL), .BACKEND(BACKEND), .ROM9_FILE(ROM9_FILE), .ROM12_FILE(ROM12_FILE),
                           .SETUP_DIR(SETUP_DIR)) u_shader (
                .clk(clk), .rst_n(rst_n), .s_valid(in_valid), .s_ready(in_ready), .s_n1(s_n1), .s_n2(s_n2),
                .s_light(second ? light_h : light_l), .s_n(second ? k_n : 10'd1),
                .s_strength(second ? k_ks : k_kd), .s_l(s_l),
                .m_valid(out_valid), .m_ready(out_ready), .m_data(out_data), .m_last(out_last)
            );
            reg out_spec;            // the span coming out is a specular pass
            always @(posedge clk) begin
                if (!rst_n) out_spec <= 1'b0;
                else if (out_valid & out_ready & out_last) out_spec <= ~out_spec;
            end
            assign d_out_valid = out_valid & ~out_spec;
            assign s_out_valid = out_valid & out_spec;
            assign d_out_data = out_data;
            assign s_out_data = out_data;
            assign d_out_last = out_last;
            assign s_out_last = out_last;
            assign out_ready = out_spec ? s_out_ready : d_out_ready;
        end else begin : g_two
            // both passes at once; the sub-span is taken when both shaders have taken theirs
            wire d_in_valid, d_in_ready, s_in_valid, s_in_ready;
            reg sent_s;
            assign d_in_valid = s_valid & meta_ready & ~sent_d;
            assign s_in_valid = s_valid & meta_ready & ~sent_s;
            wire d_done = sent_d | (d_in_valid & d_in_ready);
            wire s_done = sent_s | (s_in_valid & s_in_ready);
            assign s_ready = s_valid & meta_ready & d_done & s_done;
            assign meta_push = s_ready;
            always @(posedge clk) begin
                if (!rst_n || s_ready) begin
                    sent_d <= 1'b0;
                    sent_s <= 1'b0;
                end else begin
                    sent_d <= d_done;
                    sent_s <= s_done;
                end
            end
            board_shader #(.SMALL(SMALL), .BACKEND(BACKEND), .ROM9_FILE(ROM9_FILE), .ROM12_FILE(ROM12_FILE),
                           .SETUP_DIR(SETUP_DIR)) u_diffuse (
                .clk(clk), .rst_n(rst_n), .s_valid(d_in_valid), .s_ready(d_in_ready), .s_n1(s_n1), .s_n2(s_n2),
                .s_light(light_l), .s_n(10'd1), .s_strength(k_kd), .s_l(s_l),
                .m_valid(d_out_valid), .m_ready(d_out_ready), .m_data(d_out_data), .m_last(d_out_last)
            );
            board_shader #(.SMALL(SMALL), .BACKEND(BACKEND), .ROM9_FILE(ROM9_FILE), .ROM12_FILE(ROM12_FILE),
                           .SETUP_DIR(SETUP_DIR)) u_specular (
                .clk(clk), .rst_n(rst_n), .s_valid(s_in_valid), .s_ready(s_in_ready), .s_n1(s_n1), .s_n2(s_n2),
                .s_light(light_h), .s_n(k_n), .s_strength(k_ks), .s_l(s_l),
                .m_valid(s_out_valid), .m_ready(s_out_ready), .m_data(s_out_data), .m_last(s_out_last)
            );
        end
    endgenerate

    sync_fifo #(.W(OBJ_W + X_W), .AW(META_AW), .LUTRAM(FIFO_LUTRAM), .QUEUE(FIFO_QUEUE)) u_meta (
        .clk(clk), .rst_n(rst_n), .s_valid(meta_push), .s_ready(meta_ready), .s_data({s_obj, s_x0}),
        .m_valid(meta_valid), .m_ready(meta_pop), .m_data(meta)
    );

    // ---- pairing: diffuse pixels wait in a FIFO (a sub-span is at most 512 pixels) ----------------------------
    wire dq_valid;
    wire [15:0] dq_data;
    wire dq_pop;
    sync_fifo #(.W(16), .AW(9), .LUTRAM(FIFO_LUTRAM), .QUEUE(FIFO_QUEUE)) u_dfifo (
        .clk(clk), .rst_n(rst_n), .s_valid(d_out_valid), .s_ready(d_out_ready), .s_data(d_out_data),
        .m_valid(dq_valid), .m_ready(dq_pop), .m_data(dq_data)
    );
    wire unused_dlast;
    assign unused_dlast = &{1'b0, d_out_last};
    assign s_out_ready = dq_valid & meta_valid;
    wire pair = s_out_valid & s_out_ready;
    assign dq_pop = pair;
    always @(*) meta_pop = pair & s_out_last;

    reg [9:0] i;                 // pixel of the sub-span
    always @(posedge clk) begin
        if (!rst_n) i <= 10'd0;
        else if (pair) i <= s_out_last ? 10'd0 : i + 10'd1;
    end
    wire [OBJ_W-1:0] obj_d = meta[OBJ_W+X_W-1:X_W];
    wire [X_W-1:0] x_d = meta[X_W-1:0] + {{(X_W - 10) {1'b0}}, i};
    generate
        if (OUT_REG != 0) begin : g_out_reg
            reg v_q, last_q;
            reg [OBJ_W-1:0] obj_q;
            reg [X_W-1:0] x_q;
            reg [15:0] dif_q, spc_q;
            always @(posedge clk) begin
                if (!rst_n) v_q <= 1'b0;
                else v_q <= pair;
                obj_q <= obj_d;
                x_q <= x_d;
                dif_q <= dq_data;
                spc_q <= s_out_data;
                last_q <= s_out_last;
            end
            assign {m_valid, m_obj, m_x, m_dif, m_spc, m_last} = {v_q, obj_q, x_q, dif_q, spc_q, last_q};
        end else begin : g_out_wire
            assign {m_valid, m_obj, m_x, m_dif, m_spc, m_last} = {pair, obj_d, x_d, dq_data, s_out_data, s_out_last};
        end
    endgenerate
endmodule
`default_nettype wire
