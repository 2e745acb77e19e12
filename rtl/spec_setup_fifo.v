// spec_setup_fifo - the descriptor FIFO behind spec_setup's pipelined arithmetic: pushed without a handshake
// (spec_setup's credits guarantee room: at most 2^AW + 2 entries are ever in it), popped through an
// AXI4-Stream source whose tvalid and tdata are registers, as spec_stream's are. The memory has a registered
// read (block RAM); the read stage advances only while the output's skid buffer is empty (a register, so no
// combinational path runs from m_tready into the memory), and the skid buffer catches the one word in flight
// when the sink stalls. Capacity: 2^AW words in the memory, one in the read stage, one in the skid buffer, one
// in the output register.
`timescale 1ns / 1ps
`default_nettype none
module spec_setup_fifo #(
    parameter W = 8,
    parameter AW = 9
) (
    input  wire         clk,
    input  wire         rst,
    input  wire         push,
    input  wire [W-1:0] push_data,
    output reg          m_tvalid,
    input  wire         m_tready,
    output reg  [W-1:0] m_tdata
);
    reg [W-1:0] mem[0:(1 << AW) - 1];
    reg [AW-1:0] wp, rp;
    reg [AW:0] cm;                       // words in the memory
    reg skid_v;
    reg [W-1:0] skid_d;
    wire ce = ~skid_v;                   // the read stage advances
    wire re = ce && (cm != {(AW + 1) {1'b0}});
    reg rv;                              // the read stage holds a word
    reg [W-1:0] rd;
    always @(posedge clk) begin
        if (push) mem[wp] <= push_data;
        if (re) rd <= mem[rp];
    end
    always @(posedge clk) begin
        if (rst) begin
            wp <= {AW{1'b0}};
            rp <= {AW{1'b0}};
            cm <= {(AW + 1) {1'b0}};
            rv <= 1'b0;
        end else begin
            if (push) wp <= wp + 1'b1;
            if (re) rp <= rp + 1'b1;
            cm <= cm + {{AW{1'b0}}, push} - {{AW{1'b0}}, re};
            if (ce) rv <= re;
        end
    end
    // output register and skid buffer (as spec_stream's)
    wire o_load = skid_v ? m_tready : (rv & ce & (~m_tvalid | m_tready));
    always @(posedge clk) begin
        if (rst) begin
            m_tvalid <= 1'b0;
            skid_v <= 1'b0;
        end else begin
            m_tvalid <= skid_v | (rv & ce) | (m_tvalid & ~m_tready);
            skid_v <= skid_v ? ~m_tready : (rv & ce & m_tvalid & ~m_tready);
        end
        if (~skid_v) skid_d <= rd;
        if (o_load) m_tdata <= skid_v ? skid_d : rd;
    end
endmodule
`default_nettype wire
