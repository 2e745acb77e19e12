// compose_seq - compose's colour (compose.v, docs/boards.md "Colour") one channel after the other through one
// shift-and-add multiplier, for a device whose DSPs are all taken by the shader (the iCE40 UP5K): the same
// integer operations as compose, so the same pixels bit for bit, at MUL_STEPS bits of Cd_c per clock
// (about 3 (9 / MUL_STEPS + 3) clocks a pixel).
//
//   e = min(65535, ka + dif);  s_c = min(65535, (e * Cd_c >> 8) + spc);  out_c = (s_c (2^OUT_BITS - 1) + 2^15) >> 16
//
// An item carries a tag (passed through); an item with bypass = 1 is passed through untouched (its rgb 0),
// in order with the others. AXI4-Stream on both sides (valid held, data stable until ready); one item in the
// module at a time. Per-object constants from OBJ_FILE as compose's ({ka[15:0], cd_r, cd_g, cd_b[8:0]}).
// HOLD = 1 (where logic cells are short: the iCEBreaker, whose source is a queue's head): the input item is
// read where it is, not copied: it is taken (s_ready) only in the clock its result is taken (m_valid & m_ready),
// so s_tag, s_bypass, s_obj, s_dif and s_spc stay put while it is worked on and m_tag / m_bypass are s_tag /
// s_bypass themselves. The same items and results in the same order; s_ready then depends on m_ready.
// Reset: rst_n is synchronous, active low: empty.
`timescale 1ns / 1ps
`default_nettype none
module compose_seq #(
    parameter N_OBJ = 5,
    parameter OBJ_W = 3,
    parameter OUT_BITS = 4,
    parameter TAG_W = 18,
    parameter MUL_STEPS = 3,     // must divide 9
    parameter HOLD = 0,          // 1: the input item read in place, taken with its result (see above)
    parameter OBJ_FILE = ""
) (
    input  wire                  clk,
    input  wire                  rst_n,
    input  wire                  s_valid,
    output wire                  s_ready,
    input  wire                  s_bypass,
    input  wire [TAG_W-1:0]      s_tag,
    input  wire [OBJ_W-1:0]      s_obj,
    input  wire [15:0]           s_dif,
    input  wire [15:0]           s_spc,
    output reg                   m_valid,
    input  wire                  m_ready,
    output wire                  m_bypass,
    output wire [TAG_W-1:0]      m_tag,
    output reg  [3*OUT_BITS-1:0] m_rgb      // {r, g, b}
);
    generate
        if (OUT_BITS < 1 || OUT_BITS > 8 || N_OBJ < 1 || N_OBJ > (1 << OBJ_W) || (9 % MUL_STEPS) != 0 ||
            (HOLD != 0 && HOLD != 1))
        begin : g_bad_params
            initial begin
                $display("compose_seq: OUT_BITS must be 1..8, N_OBJ must fit OBJ_W, MUL_STEPS divide 9, HOLD 0 or 1 (%m)");
                $finish;
            end
            compose_seq_parameters_out_of_range u_error ();
        end
    endgenerate

    reg [42:0] consts[0:N_OBJ-1];
    initial $readmemh(OBJ_FILE, consts);

    localparam S_IDLE = 2'd0, S_MUL = 2'd1, S_SUM = 2'd2, S_OUT = 2'd3;
    reg [1:0] st;
    reg [1:0] ch;                      // channel: 0 r, 1 g, 2 b
    reg [26:0] cd_q;                   // the object's {cd_r, cd_g, cd_b} (HOLD = 0)
    reg [15:0] e_q, spc_q;             // (HOLD = 0)
    reg [15:0] s;                      // s_c of the channel being finished
    reg mul_start;
    reg bypass_q;                      // (HOLD = 0)
    reg [TAG_W-1:0] tag_q;             // (HOLD = 0)
    wire mul_busy, mul_done;
    wire [24:0] prod;
    wire [42:0] k = consts[s_obj];
    wire [16:0] e_sum = {1'b0, k[42:27]} + {1'b0, s_dif};
    wire [15:0] e_d = e_sum[16] ? 16'hffff : e_sum[15:0];
    // HOLD: the item stays at the input until its result is taken, so its e, spc and Cd are read there
    wire [26:0] cd = (HOLD != 0) ? k[26:0] : cd_q;
    wire [15:0] e = (HOLD != 0) ? e_d : e_q;
    wire [15:0] spc = (HOLD != 0) ? s_spc : spc_q;
    assign m_tag = (HOLD != 0) ? s_tag : tag_q;
    assign m_bypass = (HOLD != 0) ? s_bypass : bypass_q;
    wire [8:0] cd_c = (ch == 2'd0) ? cd[26:18] : (ch == 2'd1) ? cd[17:9] : cd[8:0];
    seq_mul #(.A_W(16), .B_W(9), .STEPS_PER_CLK(MUL_STEPS)) u_mul (
        .clk(clk), .rst_n(rst_n), .start(mul_start), .a(e), .b(cd_c), .busy(mul_busy), .done(mul_done), .p(prod)
    );
    wire [17:0] sum = {1'b0, prod[24:8]} + {2'b00, spc};
    // out = (s * (2^OUT_BITS - 1) + 2^15) >> 16
    wire [OUT_BITS+15:0] t = ({{OUT_BITS{1'b0}}, s} << OUT_BITS) - {{OUT_BITS{1'b0}}, s} + {{OUT_BITS{1'b0}}, 16'h8000};
    // an item starts in S_IDLE with the output empty; HOLD = 0 takes it then, HOLD = 1 when its result goes
    wire start = (st == S_IDLE) && !m_valid && s_valid;
    assign s_ready = (HOLD != 0) ? (m_valid && m_ready) : ((st == S_IDLE) && !m_valid);
    wire unused;
    assign unused = &{1'b0, mul_busy, prod[7:0], t[15:0]};

    always @(posedge clk) begin
        mul_start <= 1'b0;
        if (!rst_n) begin
            st <= S_IDLE;
            m_valid <= 1'b0;
        end else begin
            if (m_valid && m_ready) m_valid <= 1'b0;
            case (st)
                S_IDLE: if (start) begin
                    tag_q <= s_tag;
                    bypass_q <= s_bypass;
                    m_rgb <= {(3 * OUT_BITS) {1'b0}};
                    if (s_bypass) begin
                        m_valid <= 1'b1;
                    end else begin
                        e_q <= e_d;
                        spc_q <= s_spc;
                        cd_q <= k[26:0];
                        ch <= 2'd0;
                        mul_start <= 1'b1;
                        st <= S_MUL;
                    end
                end
                S_MUL: if (mul_done) begin
                    s <= (sum[17:16] != 2'b00) ? 16'hffff : sum[15:0];
                    st <= S_SUM;
                end
                S_SUM: begin
                    m_rgb <= {m_rgb[2*OUT_BITS-1:0], t[OUT_BITS+15:16]};
                    if (ch == 2'd2) begin
                        st <= S_OUT;
                    end else begin
                        ch <= ch + 2'd1;
                        mul_start <= 1'b1;
                        st <= S_MUL;
                    end
                end
                default: begin
                    m_valid <= 1'b1;
                    st <= S_IDLE;
                end
            endcase
        end
    end
endmodule
`default_nettype wire
