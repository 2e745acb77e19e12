// spec_ctrl - control block 14 of UA 71489 (Fig. 2), translated to one clock with enables.
//
// The patent clocks its flip-flops from Start, from the pulse generator 40 and from strobe 37. Here every
// flip-flop is clocked by `clk` and the patent's clock edges become enables, so the observable sequence of
// Fig. 11 on 28, 34, 36, 37 is kept cycle for cycle:
//   39  set by Start (26); its output is 28 ("End", busy)
//   40  the pulse generator: a phase bit that toggles every clock while 39 is set (held at 0 otherwise,
//       so the latency from Start is fixed); one generator period = two clocks = one pixel
//   41  takes 39 on the generator's first phase: the run starts in step with the generator
//   42  AND of 41 and the generator's second phase -> strobe 37 (write register 8) and data valid 29
//   43  set after the first strobe on 37 (its trailing edge, through inverter 45) -> select 36
//   44  set by the first strobe on 37; NAND 46 of 44 and the generator's first phase -> count 34
//   38  AND of init_n (25) and borrow_n (35), active low: clears 39, 41, 43, 44 and 40
// For a span of l intervals, 37 pulses l + 1 times, 36 is 0 for the first pulse and 1 for the rest, 34
// pulses once after each 37, and the (l + 1)-th count pulse finds counter 5 at 0, whose borrow 35 ends the
// run (Fig. 11 for l = 3). Pulses are active-high one-clock enables here (34 is active low in the patent).
`timescale 1ns / 1ps
`default_nettype none
module spec_ctrl (
    input  wire clk,
    input  wire init_n,     // 25: initial set, active low (synchronous)
    input  wire start,      // 26: Start (already gated by the top level while busy)
    input  wire borrow_n,   // 35: counter 5's borrow, active low
    output wire sig28,      // 28: run in progress (flip-flop 39)
    output wire sig34,      // 34: count pulse to counter 5
    output wire sig36,      // 36: multiplexer 7 select (flip-flop 43)
    output wire sig37       // 37: write register 8 (and data valid 29, before the datapath's latency)
);
    reg ff39, gen40, ff41, ff43, ff44;
    wire clear38_n = init_n & borrow_n;   // AND 38

    assign sig37 = ff41 & gen40;          // AND 42
    assign sig34 = ff44 & ~gen40;         // NAND 46 (active high here)
    assign sig36 = ff43;
    assign sig28 = ff39;

    always @(posedge clk) begin
        if (!clear38_n) begin
            ff39  <= 1'b0;
            gen40 <= 1'b0;
            ff41  <= 1'b0;
            ff43  <= 1'b0;
            ff44  <= 1'b0;
        end else begin
            if (start) ff39 <= 1'b1;
            gen40 <= ff39 & ~gen40;
            if (!gen40) ff41 <= ff39;
            if (sig37) begin
                ff43 <= ff41;   // trailing edge of 37 (inverter 45); 41's output is 43's D and clear
                ff44 <= 1'b1;
            end
        end
    end
endmodule
`default_nettype wire
