// tmds_serializer - the TMDS bit clock domain: three 10-bit characters per pixel (from the pixel clock domain)
// and the clock channel's character 0000011111 (five ones sent first), two bits per clock for double-data-rate output registers
// (5 clocks per pixel: clk = 5 x the pixel clock, phase-locked to it, from the same PLL).
//
// Clock-domain crossing: the pixel domain writes chars and toggles load_tgl in the same pixel clock edge,
// once per pixel. Here load_tgl passes through a two-flop synchronizer; its first change after reset sets
// the phase of a free-running modulo-5 counter, which then loads chars every 5 clocks, two or three clocks
// after they changed and two or three before they change again (the clocks are locked, so the phase
// holds). chars itself is never sampled while it may change. out_of_step is a sticky flag: a toggle arrived
// in a cycle other than the one the counter expects, or did not arrive when expected (the clocks are not
// locked, or were reset apart).
// Output: lane k's bits (2k, 2k+1) = its next two bits, the first to be sent first (DDR: D0 then D1).
// Lanes 0..2 = chars[9:0], [19:10], [29:20] (blue, green, red on DVI), lane 3 = the clock channel.
// Reset: rst_n (synchronous to clk; bring a reset from another domain through cdc_sync) restarts the
// phase search; lanes send the clock pattern's idle value 0 until the first load.
`timescale 1ns / 1ps
`default_nettype none
module tmds_serializer (
    input  wire        clk,            // 5 x pixel clock
    input  wire        rst_n,
    input  wire [29:0] chars,          // pixel clock domain, stable between toggles
    input  wire        load_tgl,       // pixel clock domain: toggles when chars change
    output reg  [7:0]  pairs,          // {lane3[1:0], lane2[1:0], lane1[1:0], lane0[1:0]}, bit 0 of a pair first
    output reg         out_of_step
);
    wire tgl_s;
    cdc_sync #(.STAGES(2)) u_sync (.clk(clk), .rst_n(rst_n), .d(load_tgl), .q(tgl_s));
    reg tgl_q;
    reg locked;
    reg [2:0] phase;             // 0..4; chars are loaded when phase wraps to 0
    reg [29:0] sh;               // the three lanes' bits not yet sent, two per clock from the bottom
    reg [9:0] clk_sh;            // the clock channel
    localparam [9:0] CLOCK_CHAR = 10'b0000011111;
    wire edge_seen = tgl_s ^ tgl_q;
    wire load = locked ? (phase == 3'd4) : edge_seen;

    always @(posedge clk) begin
        if (!rst_n) begin
            tgl_q <= 1'b0;
            locked <= 1'b0;
            phase <= 3'd0;
            out_of_step <= 1'b0;
            sh <= 30'd0;
            clk_sh <= 10'd0;
            pairs <= 8'd0;
        end else begin
            tgl_q <= tgl_s;
            if (edge_seen) locked <= 1'b1;
            if (locked && (edge_seen != (phase == 3'd4))) out_of_step <= 1'b1;
            phase <= load ? 3'd0 : (phase == 3'd4 ? 3'd0 : phase + 3'd1);
            if (load) begin
                sh <= {2'b00, chars[29:22], 2'b00, chars[19:12], 2'b00, chars[9:2]};
                clk_sh <= {2'b00, CLOCK_CHAR[9:2]};
                pairs <= {CLOCK_CHAR[1:0], chars[21:20], chars[11:10], chars[1:0]};
            end else begin
                sh <= {2'b00, sh[29:22], 2'b00, sh[19:12], 2'b00, sh[9:2]};
                clk_sh <= {2'b00, clk_sh[9:2]};
                pairs <= {clk_sh[1:0], sh[21:20], sh[11:10], sh[1:0]};
            end
        end
    end
endmodule
`default_nettype wire
