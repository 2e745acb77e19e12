// seq_mul - unsigned multiplier by shift and add: p = a * b, STEPS_PER_CLK bits of b per clock
// (B_W / STEPS_PER_CLK cycles). Small where multipliers are scarce (iCE40 UP5K: 8 DSPs, all wanted by
// the shader); set STEPS_PER_CLK = B_W for a single-cycle array.
// Handshake: start (with a, b) is taken while busy = 0, and the first STEPS_PER_CLK bits are used in that
// cycle; the caller holds a from start until done (every caller's a is a register that does: no copy here); busy is 1 for the B_W / STEPS_PER_CLK - 1 cycles after it; done pulses in the cycle after the last
// step (the cycle after start when STEPS_PER_CLK = B_W), when p is the product; p is held until the next
// start.
// Reset: rst_n is synchronous, active low: idle, no done.
`timescale 1ns / 1ps
`default_nettype none
module seq_mul #(
    parameter A_W = 10,
    parameter B_W = 13,
    parameter STEPS_PER_CLK = 1   // must divide B_W
) (
    input  wire               clk,
    input  wire               rst_n,
    input  wire               start,
    input  wire [A_W-1:0]     a,
    input  wire [B_W-1:0]     b,
    output reg                busy,
    output reg                done,
    output reg  [A_W+B_W-1:0] p
);
    localparam CYCLES = B_W / STEPS_PER_CLK;
    localparam C_W = (CYCLES < 2) ? 1 : $clog2(CYCLES + 1);

    generate
        if (A_W < 1 || B_W < 2 || STEPS_PER_CLK < 1 || (B_W % STEPS_PER_CLK) != 0) begin : g_bad_params
            initial begin
                $display("seq_mul: B_W must be >= 2 and STEPS_PER_CLK must divide it (%m)");
                $finish;
            end
            seq_mul_parameters_out_of_range u_error ();
        end
    endgenerate

    reg [B_W-1:0] b_q;          // multiplier bits not yet used, most significant first
    reg [C_W-1:0] left;
    // STEPS_PER_CLK steps of shift and add, from (p_i, a, b_i): at start from (0, a, b), later from the
    // registers
    wire [B_W-1:0] b_i = busy ? b_q : b;
    wire [A_W+B_W-1:0] p_i = busy ? p : {(A_W + B_W) {1'b0}};
    reg [A_W+B_W-1:0] p_n;
    reg [B_W-1:0] b_n;
    integer k;
    always @* begin
        p_n = p_i;
        b_n = b_i;
        for (k = 0; k < STEPS_PER_CLK; k = k + 1) begin
            p_n = {p_n[A_W+B_W-2:0], 1'b0} + (b_n[B_W-1] ? {{B_W{1'b0}}, a} : {(A_W + B_W) {1'b0}});
            b_n = {b_n[B_W-2:0], 1'b0};
        end
    end

    // STEPS_PER_CLK = B_W: the whole product at once, as a multiplier the synthesis maps (a DSP block)
    wire [A_W+B_W-1:0] p_full = a * b;

    always @(posedge clk) begin
        if (!rst_n) begin
            busy <= 1'b0;
            done <= 1'b0;
        end else begin
            done <= 1'b0;
            if (!busy) begin
                if (start) begin
                    b_q <= b_n;
                    p <= (CYCLES == 1) ? p_full : p_n;
                    left <= CYCLES[C_W-1:0] - {{(C_W - 1) {1'b0}}, 1'b1};
                    if (CYCLES == 1) done <= 1'b1;
                    else busy <= 1'b1;
                end
            end else begin
                p <= p_n;
                b_q <= b_n;
                left <= left - {{(C_W - 1) {1'b0}}, 1'b1};
                if (left == {{(C_W - 1) {1'b0}}, 1'b1}) begin
                    busy <= 1'b0;
                    done <= 1'b1;
                end
            end
        end
    end
endmodule
`default_nettype wire
