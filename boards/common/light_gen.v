// light_gen - the light of frame f: it turns about the viewing axis, one step of 2 pi / 256 per frame, at a
// fixed angle E from it (docs/boards.md, "Light"):
//
//   L = (sin E cos t, sin E sin t, cos E),   H = (L + V) / |L + V| = (sin(E/2) cos t, sin(E/2) sin t, cos(E/2))
//
// with t = 2 pi f / 256 and V = (0, 0, 1) the viewer at infinity (screen x right, y down, z toward the
// viewer). Components are signed Q1.14 (16384 = 1.0). The x and y components are read from a table of the
// products over a quarter wave (LIGHT_FILE, 256 words of 16 bits; boardsim gen writes it): word i (0..64) =
// round(s_i sin E), word 128 + i = round(s_i sin(E/2)), with s_i = round(16384 sin(pi i / 128)) and sin E,
// sin(E/2) in Q1.14, each product rounded half up (/ 2^14) as board_model's light_q rounds it; the other words
// are 0, and no word exceeds 16384. cos t = sin(t + 64) and the sign of each quadrant are applied here. The z components are COS_E and COS_HALF_E themselves.
// TABLE_BRAM = 0 asks synthesis to build the table from logic instead (rom_style = "logic": the ULX3S, whose
// frame buffer and shader take every block RAM of the ECP5-25F); the same words, read the same way.
// Handshake: start (with f) is taken while busy = 0; busy stays 1 for 5 cycles; l_x, l_y, h_x, h_y take their
// new values one after the other while busy = 1 (l_z and h_z are constants) and hold while busy = 0. The
// callers do not read them while busy.
// Reset: rst_n is synchronous, active low: idle; the outputs are the light of no frame until the first run.
`timescale 1ns / 1ps
`default_nettype none
module light_gen #(
    parameter COS_E = 12551,       // round(16384 cos 40 deg)
    parameter COS_HALF_E = 15396,
    parameter LIGHT_FILE = "",
    parameter TABLE_BRAM = 1
) (
    input  wire        clk,
    input  wire        rst_n,
    input  wire        start,
    input  wire [7:0]  f,
    output reg         busy,
    output reg  signed [15:0] l_x, l_y, l_z,
    output reg  signed [15:0] h_x, h_y, h_z
);

    // cos t = sin(t + 64); sin over four quadrants from the quarter wave
    reg [7:0] t;
    wire [7:0] tc = t + 8'd64;
    wire [6:0] i_s = t[6] ? 7'd64 - {1'b0, t[5:0]} : {1'b0, t[5:0]};
    wire [6:0] i_c = tc[6] ? 7'd64 - {1'b0, tc[5:0]} : {1'b0, tc[5:0]};
    reg [2:0] step;                // 0..3: the read of l_x, l_y, h_x, h_y; 1..4: its word is written
    // the read of step s: cos t (s even) or sin t (s odd), times sin E (s < 2) or sin(E/2)
    wire [7:0] addr = {step[1], step[0] ? i_s : i_c};
    reg [15:0] word;               // the table's read register
    generate
        if (TABLE_BRAM != 0) begin : g_bram
            reg [15:0] tab[0:255];
            initial $readmemh(LIGHT_FILE, tab);
            always @(posedge clk) word <= tab[addr];
        end else begin : g_logic
            (* rom_style = "logic" *) reg [15:0] tab[0:255];
            initial $readmemh(LIGHT_FILE, tab);
            always @(posedge clk) word <= tab[addr];
        end
    endgenerate
    reg neg;                       // the word's sign, read beside it
    wire signed [15:0] res = neg ? -$signed(word) : $signed(word);

    always @(posedge clk) begin
        if (!rst_n) begin
            busy <= 1'b0;
            step <= 3'd0;
        end else if (!busy) begin
            step <= 3'd0;
            if (start) begin
                busy <= 1'b1;
                t <= f;
            end
        end else begin
            neg <= step[0] ? t[7] : tc[7];
            case (step)
                3'd1: l_x <= res;
                3'd2: l_y <= res;
                3'd3: h_x <= res;
                3'd4: begin
                    h_y <= res;
                    l_z <= COS_E;
                    h_z <= COS_HALF_E;
                    busy <= 1'b0;
                end
                default: ;
            endcase
            step <= step + 3'd1;
        end
    end
endmodule
`default_nettype wire
