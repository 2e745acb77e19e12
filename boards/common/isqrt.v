// isqrt - integer square root by the restoring digit-by-digit method: root = floor(sqrt(x)) for an
// unsigned X_W-bit x, STEPS_PER_CLK result bits per clock (X_W / 2 result bits in all).
//
// Each step brings down the next two bits of x into the partial remainder and subtracts (4 * root + 1)
// when it fits, appending a 1 to the root (else a 0). After all X_W / 2 steps, root^2 <= x < (root + 1)^2.
// Handshake: start (with x) is taken while busy = 0; busy is 1 from the next cycle for
// X_W / 2 / STEPS_PER_CLK cycles, and root is valid (and held) once busy has fallen again (done pulses
// for one cycle then). start while busy is ignored.
// Reset: rst_n is synchronous, active low: idle, no done.
`timescale 1ns / 1ps
`default_nettype none
module isqrt #(
    parameter X_W = 28,            // radicand width, even
    parameter STEPS_PER_CLK = 1    // must divide X_W / 2
) (
    input  wire             clk,
    input  wire             rst_n,
    input  wire             start,
    input  wire [X_W-1:0]   x,
    output reg              busy,
    output reg              done,
    output reg  [X_W/2-1:0] root
);
    localparam R_W = X_W / 2;
    localparam CYCLES = R_W / STEPS_PER_CLK;
    localparam C_W = (CYCLES < 2) ? 1 : $clog2(CYCLES + 1);

    generate
        if (X_W < 2 || (X_W % 2) != 0 || STEPS_PER_CLK < 1 || (R_W % STEPS_PER_CLK) != 0) begin : g_bad_params
            initial begin
                $display("isqrt: X_W must be even and STEPS_PER_CLK must divide X_W / 2 (%m)");
                $finish;
            end
            isqrt_parameters_out_of_range u_error ();
        end
    endgenerate

    reg [X_W-1:0] xs;           // radicand bits not yet brought down, most significant first
    reg [R_W+1:0] rem;          // partial remainder: < 2 * root + 1 <= 2^(R_W + 1)
    reg [C_W-1:0] left;         // cycles left

    // STEPS_PER_CLK steps of the method, unrolled
    reg [X_W-1:0] xs_n;
    reg [R_W+1:0] rem_n;
    reg [R_W-1:0] root_n;
    reg [R_W+1:0] trial;
    reg [R_W+3:0] acc;
    integer k;
    always @* begin
        xs_n = xs;
        rem_n = rem;
        root_n = root;
        for (k = 0; k < STEPS_PER_CLK; k = k + 1) begin
            acc = {rem_n, xs_n[X_W-1:X_W-2]};
            trial = {root_n, 2'b01};
            xs_n = {xs_n[X_W-3:0], 2'b00};
            if (acc >= {2'b00, trial}) begin
                acc = acc - {2'b00, trial};
                root_n = {root_n[R_W-2:0], 1'b1};
            end else begin
                root_n = {root_n[R_W-2:0], 1'b0};
            end
            rem_n = acc[R_W+1:0];
        end
    end

    always @(posedge clk) begin
        if (!rst_n) begin
            busy <= 1'b0;
            done <= 1'b0;
        end else begin
            done <= 1'b0;
            if (!busy) begin
                if (start) begin
                    busy <= 1'b1;
                    left <= CYCLES[C_W-1:0];
                    xs <= x;
                    rem <= {(R_W + 2) {1'b0}};
                    root <= {R_W{1'b0}};
                end
            end else begin
                xs <= xs_n;
                rem <= rem_n;
                root <= root_n;
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
