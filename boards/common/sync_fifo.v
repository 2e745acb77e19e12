// sync_fifo - a first-in first-out queue in one clock domain, AXI4-Stream on both sides, one item per clock
// in and out. The storage has a registered read (block RAM on iCE40 / ECP5 for DEPTH x W large enough);
// a two-entry output queue behind it keeps m_axis_tvalid / tdata registers and hides the read latency.
// Capacity DEPTH + 2. s_axis_tready = 1 while the storage has room (a register-free compare of the counts).
// Reset: rst_n is synchronous, active low: empty.
`timescale 1ns / 1ps
`default_nettype none
module sync_fifo #(
    parameter W = 16,
    parameter AW = 8          // storage depth 2^AW
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
    reg [W-1:0] mem[0:(1 << AW) - 1];
    reg [AW:0] wptr, rptr;               // storage pointers, one extra bit tells full from empty
    reg [W-1:0] rdata;
    reg rd_pending;                      // rdata is being read this cycle (valid next cycle)
    reg [W-1:0] q0, q1;                  // output queue: q0 is the head
    reg q0_v, q1_v;

    wire st_empty = (wptr == rptr);
    assign s_ready = (wptr - rptr) != {1'b1, {AW{1'b0}}};
    wire push = s_valid & s_ready;
    wire pop = q0_v & m_ready;
    // read from the storage when the output queue will have room for the item when it arrives:
    // queue items after this cycle's pop, plus the one in flight, plus this one, at most 2
    wire [1:0] queued = {1'b0, q0_v} + {1'b0, q1_v} - {1'b0, pop} + {1'b0, rd_pending};
    wire rd = !st_empty && (queued < 2'd2);

    always @(posedge clk) begin
        if (push) mem[wptr[AW-1:0]] <= s_data;
        if (rd) rdata <= mem[rptr[AW-1:0]];
    end

    // the output queue: items leave from q0; an arriving item (rd_pending) joins at the end
    always @(posedge clk) begin
        if (!rst_n) begin
            wptr <= {(AW + 1) {1'b0}};
            rptr <= {(AW + 1) {1'b0}};
            rd_pending <= 1'b0;
            q0_v <= 1'b0;
            q1_v <= 1'b0;
        end else begin
            if (push) wptr <= wptr + {{AW{1'b0}}, 1'b1};
            if (rd) rptr <= rptr + {{AW{1'b0}}, 1'b1};
            rd_pending <= rd;
            case ({pop, rd_pending})
                2'b00: ;
                2'b01: begin           // arrival only
                    if (!q0_v) begin
                        q0 <= rdata;
                        q0_v <= 1'b1;
                    end else begin
                        q1 <= rdata;
                        q1_v <= 1'b1;
                    end
                end
                2'b10: begin           // pop only
                    q0 <= q1;
                    q0_v <= q1_v;
                    q1_v <= 1'b0;
                end
                default: begin         // pop and arrival
                    if (q1_v) begin
                        q0 <= q1;
                        q1 <= rdata;
                    end else begin
                        q0 <= rdata;
                    end
                end
            endcase
        end
    end
    assign m_valid = q0_v;
    assign m_data = q0;
endmodule
`default_nettype wire
