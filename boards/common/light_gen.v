// light_gen - the light of frame f: it turns about the viewing axis, one step of 2 pi / 256 per frame, at a
// fixed angle E from it (docs/boards.md, "Light"):
//
//   L = (sin E cos t, sin E sin t, cos E),   H = (L + V) / |L + V| = (sin(E/2) cos t, sin(E/2) sin t, cos(E/2))
//
// with t = 2 pi f / 256 and V = (0, 0, 1) the viewer at infinity (screen x right, y down, z toward the
// viewer). Components are signed Q1.14 (16384 = 1.0): cos t and sin t from a quarter-wave table
// (SIN_FILE: 65 words round(16384 sin(pi i / 128)), i = 0..64), times the constants SIN_E, SIN_HALF_E
// (Q1.14) with a shift-and-add multiplier, rounded: round(a * b / 2^14); the z components are COS_E and
// COS_HALF_E themselves.
// One table read and one multiplier serve the four products in turn (the table's index is chosen before the
// read).
// Handshake: start (with f) is taken while busy = 0; busy stays 1 for 4 x 16 cycles or so;
// l_x, l_y, h_x, h_y take their new values one after the other while busy = 1 (each as its product is done;
// l_z and h_z are constants), and hold while busy = 0. The callers do not read them while busy.
// Reset: rst_n is synchronous, active low: idle; the outputs are the light of no frame until the first run.
`timescale 1ns / 1ps
`default_nettype none
module light_gen #(
    parameter SIN_E = 10531,       // round(16384 sin 40 deg)
    parameter COS_E = 12551,
    parameter SIN_HALF_E = 5604,
    parameter COS_HALF_E = 15396,
    parameter SIN_FILE = ""
) (
    input  wire        clk,
    input  wire        rst_n,
    input  wire        start,
    input  wire [7:0]  f,
    output reg         busy,
    output reg  signed [15:0] l_x, l_y, l_z,
    output reg  signed [15:0] h_x, h_y, h_z
);
    reg [14:0] quarter[0:64];
    initial $readmemh(SIN_FILE, quarter);

    // cos t = sin(t + 64); sin over four quadrants from the quarter wave
    reg [7:0] t;
    wire [7:0] tc = t + 8'd64;
    wire [6:0] i_s = t[6] ? 7'd64 - {1'b0, t[5:0]} : {1'b0, t[5:0]};
    wire [6:0] i_c = tc[6] ? 7'd64 - {1'b0, tc[5:0]} : {1'b0, tc[5:0]};
    reg [2:0] step;                // 0: idle, 1..4: the four products
    // the product started at step s (0..3): cos t (s even) or sin t (s odd), one table read
    wire [14:0] mag = quarter[step[0] ? i_s : i_c];
    wire neg_s = t[7];
    wire neg_c = tc[7];

    reg mul_start;
    reg [15:0] mul_a, mul_b;
    wire mul_busy, mul_done;
    wire [31:0] mul_p;
    seq_mul #(.A_W(16), .B_W(16), .STEPS_PER_CLK(1)) u_mul (
        .clk(clk), .rst_n(rst_n), .start(mul_start), .a(mul_a), .b(mul_b), .busy(mul_busy), .done(mul_done),
        .p(mul_p)
    );
    wire unused_mul;
    assign unused_mul = &{1'b0, mul_busy, mul_p[31:30], mul_p[12:0]};
    // round(p / 2^14) with the sign put back; |result| <= 16384
    wire [15:0] mag_r = mul_p[29:14] + {15'd0, mul_p[13]};

    reg neg;
    wire signed [15:0] res = neg ? -$signed(mag_r) : $signed(mag_r);

    always @(posedge clk) begin
        mul_start <= 1'b0;
        if (!rst_n) begin
            busy <= 1'b0;
            step <= 3'd0;
        end else if (!busy) begin
            if (start) begin
                busy <= 1'b1;
                t <= f;
                step <= 3'd0;
            end
        end else begin
            if (step == 3'd0 || mul_done) begin
                case (step)
                    3'd1: l_x <= res;
                    3'd2: l_y <= res;
                    3'd3: h_x <= res;
                    3'd4: h_y <= res;
                    default: ;
                endcase
                if (step == 3'd4) begin
                    l_z <= COS_E;
                    h_z <= COS_HALF_E;
                    busy <= 1'b0;
                end else begin
                    mul_a <= {1'b0, mag};
                    mul_b <= (step < 3'd2) ? SIN_E : SIN_HALF_E;
                    neg <= step[0] ? neg_s : neg_c;
                    mul_start <= 1'b1;
                end
                step <= step + 3'd1;
            end
        end
    end
endmodule
`default_nettype wire
