// tmds_encoder - DVI 1.0 TMDS encoding of one channel: 8 data bits to a 10-bit, transition-minimised,
// DC-balanced character while de = 1; one of the four control characters (c1, c0) while de = 0.
//
// Data (DVI 1.0 section 3.2.2): stage 1 chains the bits with XOR, or with XNOR when that gives fewer
// transitions (more than four ones, or exactly four with d[0] = 0); bit 8 records which (1 = XOR). Stage 2
// keeps the running disparity (ones minus zeros sent so far, in bits): bit 9 = 1 inverts bits 7:0 when that
// moves the disparity toward zero. Control characters reset the disparity to zero.
// Bit 0 of q is transmitted first.
// Timing: q is a register, loaded in every clock with ce = 1 from that cycle's de, c and d (latency 1).
// Reset: rst_n is synchronous, active low: disparity 0 and q = the control character for c = 00.
`timescale 1ns / 1ps
`default_nettype none
module tmds_encoder (
    input  wire       clk,
    input  wire       rst_n,
    input  wire       ce,
    input  wire       de,
    input  wire [1:0] c,      // {c1, c0}: on the blue channel {vsync, hsync}, 00 on the others (DVI 1.0)
    input  wire [7:0] d,
    output reg  [9:0] q
);
    // ---- stage 1: transition minimisation ----------------------------------------------------------------
    function [3:0] ones8;
        input [7:0] x;
        integer i;
        begin
            ones8 = 4'd0;
            for (i = 0; i < 8; i = i + 1) ones8 = ones8 + {3'd0, x[i]};
        end
    endfunction

    wire [3:0] n1_d = ones8(d);
    wire use_xnor = (n1_d > 4'd4) || (n1_d == 4'd4 && !d[0]);
    reg [8:0] qm;
    integer k;
    always @* begin
        qm[0] = d[0];
        for (k = 1; k < 8; k = k + 1) qm[k] = use_xnor ? ~(qm[k - 1] ^ d[k]) : (qm[k - 1] ^ d[k]);
        qm[8] = ~use_xnor;
    end

    // ---- stage 2: DC balance ------------------------------------------------------------------------------
    // disparity of qm[7:0] in bits: ones - zeros = 2 * ones - 8, in [-8, 8]
    wire [3:0] n1_qm = ones8(qm[7:0]);
    wire signed [4:0] half = $signed({1'b0, n1_qm}) - 5'sd4;   // ones - 4, in [-4, 4]
    wire signed [4:0] diff = half <<< 1;
    reg signed [4:0] cnt;          // running disparity of the characters sent, even, within [-8, 8]
    reg [9:0] q_d;
    reg signed [4:0] cnt_d;
    always @* begin
        if (cnt == 5'sd0 || diff == 5'sd0) begin
            q_d = {~qm[8], qm[8], qm[8] ? qm[7:0] : ~qm[7:0]};
            cnt_d = qm[8] ? cnt + diff : cnt - diff;
        end else if ((cnt > 5'sd0 && diff > 5'sd0) || (cnt < 5'sd0 && diff < 5'sd0)) begin
            q_d = {1'b1, qm[8], ~qm[7:0]};
            cnt_d = cnt - diff + (qm[8] ? 5'sd2 : 5'sd0);
        end else begin
            q_d = {1'b0, qm[8], qm[7:0]};
            cnt_d = cnt + diff - (qm[8] ? 5'sd0 : 5'sd2);
        end
    end

    // control characters (DVI 1.0 section 3.3.3)
    reg [9:0] ctl;
    always @* begin
        case (c)
            2'b00: ctl = 10'b1101010100;
            2'b01: ctl = 10'b0010101011;
            2'b10: ctl = 10'b0101010100;
            default: ctl = 10'b1010101011;
        endcase
    end

    always @(posedge clk) begin
        if (!rst_n) begin
            cnt <= 5'sd0;
            q <= 10'b1101010100;
        end else if (ce) begin
            if (de) begin
                q <= q_d;
                cnt <= cnt_d;
            end else begin
                q <= ctl;
                cnt <= 5'sd0;
            end
        end
    end
endmodule
`default_nettype wire
