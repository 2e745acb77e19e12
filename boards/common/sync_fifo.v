// sync_fifo - a first-in first-out queue in one clock domain, AXI4-Stream on both sides, one item per clock
// in and out. The storage has a registered read (block RAM on iCE40 / ECP5 for 2^AW x W large enough); a
// three-entry output queue behind it keeps m_valid / m_data registers and hides the read latency, and the
// read decision depends on registers only (not on this cycle's m_ready: no combinational path from the
// sink through the FIFO).
// Capacity 2^AW + 3. s_ready is a register from the registered count alone: 1 while the storage held at most
// 2^AW - 2 items in the previous cycle (so a push in this cycle and the next still fit).
// QUEUE = 1 (where logic cells are short: the iCEBreaker): one output register instead of the three-entry
// queue; the storage's read register holds its item until the output register takes it, and the read decision
// still depends on registers only. Same order and contents, capacity 2^AW + 2, at most two items every three
// clocks out (one a clock with QUEUE = 3); W x 2 flip-flops and their multiplexers fewer.
// QUEUE = 0 (the smallest): no output register; the storage's read register is the head (m_data), and the
// next item is read in the clock the head is taken, so the read decision depends on this cycle's m_ready (a
// combinational path from the sink into the block RAM's read enable). One item a clock, capacity 2^AW + 1.
// Reset: rst_n is synchronous, active low: empty; s_ready is 0 in the cycle after reset.
`timescale 1ns / 1ps
`default_nettype none
module sync_fifo #(
    parameter W = 16,
    parameter AW = 8,         // storage depth 2^AW
    parameter LUTRAM = 0,     // 1: the storage in distributed RAM (ram_style), where block RAM is short
    parameter QUEUE = 3       // output queue entries: 3 (one item a clock), 1 (two items in three clocks), 0 (see above)
) (
    input  wire         clk,
    input  wire         rst_n,
    input  wire         s_valid,
    output wire         s_ready,
    input  wire [W-1:0] s_data,
    output wire         m_valid,
    input  wire         m_ready,
    output wire [W-1:0] m_data
);
    reg [AW:0] wptr, rptr;               // storage pointers, one extra bit tells full from empty
    reg [W-1:0] rdata;
    reg ready_q;
    reg [AW:0] cnt;                      // items in the storage
    assign s_ready = ready_q;
    wire push = s_valid & s_ready;
    wire rd;                             // read the storage (registers only decide it)
    reg st_full;                         // the storage is not empty (a register: keeps rd shallow)
    wire inc = push & ~rd, dec = rd & ~push;
    wire [AW:0] cnt_n = cnt + {{AW{dec}}, inc | dec};
    wire cnt_is1 = (cnt == {{AW{1'b0}}, 1'b1});
    wire cnt_gt1 = (cnt[AW:1] != {AW{1'b0}});
    localparam [AW:0] ROOM_LAST = (1 << AW) - 2;

    generate
        if (LUTRAM != 0) begin : g_lutram
            (* ram_style = "distributed" *) reg [W-1:0] mem[0:(1 << AW) - 1];
            always @(posedge clk) begin
                if (push) mem[wptr[AW-1:0]] <= s_data;
                if (rd) rdata <= mem[rptr[AW-1:0]];
            end
        end else begin : g_ram
            // no_rw_check: the storage is never read at the address written in the same clock (a read needs
            // 1 .. 2^AW - 1 items stored, when wptr and rptr differ; a push needs room, so never at 2^AW). Without
            // it Yosys adds a collision bypass: a second register stage on the write port and the read register
            // outside the block RAM (W + AW + ... flip-flops with no LUT in front). The check below stops a
            // simulation that breaks the rule.
            (* no_rw_check *) reg [W-1:0] mem[0:(1 << AW) - 1];
            always @(posedge clk) begin
                if (push) mem[wptr[AW-1:0]] <= s_data;
                if (rd) rdata <= mem[rptr[AW-1:0]];
            end
        end
    endgenerate

    always @(posedge clk) begin
        if (!rst_n) begin
            wptr <= {(AW + 1) {1'b0}};
            rptr <= {(AW + 1) {1'b0}};
            ready_q <= 1'b0;
            cnt <= {(AW + 1) {1'b0}};
            st_full <= 1'b0;
        end else begin
            if (push) wptr <= wptr + {{AW{1'b0}}, 1'b1};
            if (rd) rptr <= rptr + {{AW{1'b0}}, 1'b1};
            cnt <= cnt_n;
            // not empty next: more than one now, or one not read, or a push (no carry chain in the way)
            st_full <= cnt_gt1 | (cnt_is1 & ~dec) | inc;
            ready_q <= (cnt <= ROOM_LAST);
        end
    end

`ifndef SYNTHESIS
    always @(posedge clk) begin
        if (rst_n && push && rd && wptr[AW-1:0] == rptr[AW-1:0]) begin
            $display("sync_fifo: a read at the address written in the same clock (%m): an RTL bug");
            $fatal(1);
        end
    end
`endif

    generate
        if (QUEUE != 0 && QUEUE != 1 && QUEUE != 3) begin : g_bad_queue
            sync_fifo_parameter_error_QUEUE_must_be_0_1_or_3 check_the_QUEUE_parameter ();
        end
        if (QUEUE == 0) begin : g_q0
            reg head_v;                          // rdata holds the head item
            assign rd = st_full && (!head_v || m_ready);
            always @(posedge clk) begin
                if (!rst_n) head_v <= 1'b0;
                else head_v <= rd | (head_v & ~m_ready);
            end
            assign m_valid = head_v;
            assign m_data = rdata;
        end else if (QUEUE == 1) begin : g_q1
            reg rd_pending;                      // rdata holds an item read from the storage
            // rd_pending: rdata holds an item not yet taken (it stays there while the output register is full)
            reg [W-1:0] q0;
            reg q0_v;
            wire pop = q0_v & m_ready;
            wire move = rd_pending & (~q0_v | pop);
            // read when rdata's slot is free, or the output register is empty (then rdata moves at this edge)
            assign rd = st_full && (!rd_pending || !q0_v);
            always @(posedge clk) begin
                if (!rst_n) begin
                    rd_pending <= 1'b0;
                    q0_v <= 1'b0;
                end else begin
                    rd_pending <= rd | (rd_pending & ~move);
                    q0_v <= move | (q0_v & ~pop);
                end
                if (move) q0 <= rdata;
            end
            assign m_valid = q0_v;
            assign m_data = q0;
        end else begin : g_q3
            reg rd_pending;                      // rdata holds an item read from the storage
            reg [W-1:0] q0, q1, q2;              // output queue: q0 is the head
            reg q0_v, q1_v, q2_v;
            wire pop = q0_v & m_ready;
            // read when the queue, with the item in flight, holds at most 2 (whatever this cycle's pop); the
            // queue fills from q0 up, so that is: q2 empty, and not q1 full with an item in flight
            assign rd = st_full && !q2_v && !(q1_v && rd_pending);
            // the queue after this cycle's pop, then the arriving item (rd_pending) joins at the end
            wire [W-1:0] p0 = pop ? q1 : q0, p1 = pop ? q2 : q1;
            wire p0_v = pop ? q1_v : q0_v, p1_v = pop ? q2_v : q1_v, p2_v = pop ? 1'b0 : q2_v;
            always @(posedge clk) begin
                if (!rst_n) begin
                    rd_pending <= 1'b0;
                    q0_v <= 1'b0;
                    q1_v <= 1'b0;
                    q2_v <= 1'b0;
                end else begin
                    rd_pending <= rd;
                    q0 <= p0_v ? p0 : rdata;
                    q1 <= p1_v ? p1 : rdata;
                    q2 <= p2_v ? q2 : rdata;
                    q0_v <= p0_v | rd_pending;
                    q1_v <= p1_v | (p0_v & rd_pending);
                    q2_v <= p2_v | (p1_v & rd_pending);
                end
            end
            assign m_valid = q0_v;
            assign m_data = q0;
        end
    endgenerate
endmodule
`default_nettype wire
