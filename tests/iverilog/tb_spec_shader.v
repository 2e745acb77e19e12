// tb_spec_shader - self-checking Icarus Verilog testbench for spec_shader in either configuration.
// Reads +beats=FILE and +pixels=FILE (written by `specsim setup-vectors` from the bit-exact models) and
// +spans=S +npixels=P, sends every beat with random gaps on s_axis_tvalid, takes the pixels with random
// m_axis_tready, and compares each pixel's value, tlast and tuser in order; a mismatch, a lost or extra pixel
// or a hang ends with $fatal (exit 1). +stall=P: stall probability in percent (default 30). ITERATIVE and BACKEND
// pick the configuration (up5k: ITERATIVE = 1, BACKEND = 1, with spec_stream's up5k header and ROM images).
// 4-state: rst_n is low for exactly one clock at the start; from then on no output is X or Z.
`timescale 1ns / 1ps
`default_nettype none
`include "spec_params.vh"
`include "setup_params.vh"
`include "setup_small_params.vh"
module tb_spec_shader #(
    parameter ITERATIVE = 0,
    parameter BACKEND = 0,      // spec_shader's back end: 0 = spec_stream, 1 = spec_stream_seq
    parameter ROM9_FILE = `SPEC_ROM9_FILE,
    parameter ROM12_FILE = `SPEC_ROM12_FILE,
    parameter EFU_FILE = `SETUP_EFU_FILE,
    parameter EXP2_FILE = `SETUP_EXP2_FILE,
    parameter UC_FILE = `SETUP_UC_FILE,
    parameter SMALL_LOG2_FILE = `SMALL_LOG2_FILE,
    parameter SMALL_EXP2_FILE = `SMALL_EXP2_FILE
);
    localparam SMAX = 4096, PMAX = 65536;
    localparam BEAT_W = `SETUP_BEAT_W, OUT_W = `SPEC_OUT_W;
    reg clk = 1'b0;
    always #5 clk = ~clk;

    reg rst_n = 1'b0;
    reg s_valid = 1'b0;
    reg [BEAT_W-1:0] s_data = {BEAT_W{1'b0}};
    wire s_ready;
    wire m_valid, m_last;
    wire [OUT_W-1:0] m_data;
    wire [6:0] m_user;
    reg m_ready = 1'b0;

    spec_shader #(.ITERATIVE(ITERATIVE), .BACKEND(BACKEND), .ROM9_FILE(ROM9_FILE), .ROM12_FILE(ROM12_FILE),
                  .EFU_FILE(EFU_FILE), .EXP2_FILE(EXP2_FILE), .UC_FILE(UC_FILE), .SMALL_LOG2_FILE(SMALL_LOG2_FILE),
                  .SMALL_EXP2_FILE(SMALL_EXP2_FILE)) dut (
        .clk(clk), .rst_n(rst_n), .s_axis_tvalid(s_valid), .s_axis_tready(s_ready), .s_axis_tdata(s_data),
        .m_axis_tvalid(m_valid), .m_axis_tready(m_ready), .m_axis_tdata(m_data), .m_axis_tlast(m_last),
        .m_axis_tuser(m_user)
    );

    reg [BEAT_W-1:0] beats [0:SMAX-1];
    reg [23:0] pixels [0:PMAX-1];
    integer nspans, npixels, stall, sent, got, cycles, limit;
    reg reset_done = 1'b0;
    reg taken;

    always @(negedge clk) begin
        if (reset_done && ^{s_ready, m_valid, m_data, m_last, m_user} === 1'bx) begin
            $display("tb_spec_shader: an output is X or Z after reset at %0t: tready %b tvalid %b tdata %h tlast %b tuser %b", $time, s_ready, m_valid, m_data, m_last, m_user);
            $fatal(1);
        end
    end

    reg [1023:0] fb, fp;
    initial begin
        if (!$value$plusargs("beats=%s", fb) || !$value$plusargs("pixels=%s", fp) ||
            !$value$plusargs("spans=%d", nspans) || !$value$plusargs("npixels=%d", npixels)) begin
            $display("tb_spec_shader: +beats=FILE +pixels=FILE +spans=S +npixels=P are required");
            $fatal(1);
        end
        if (nspans > SMAX || npixels > PMAX) begin
            $display("tb_spec_shader: at most %0d spans and %0d pixels", SMAX, PMAX);
            $fatal(1);
        end
        if (!$value$plusargs("stall=%d", stall)) stall = 30;
        $readmemh(fb, beats, 0, nspans - 1);
        $readmemh(fp, pixels, 0, npixels - 1);
        sent = 0;
        got = 0;
        cycles = 0;
        limit = 2000 + nspans * (ITERATIVE ? 4000 : 40) + npixels * 4;
        // rst_n low through the first rising edge; from then on inputs change on falling edges only
        @(negedge clk);
        rst_n = 1'b1;
        reset_done = 1'b1;
        taken = 1'b0;
        while (got < npixels) begin
            @(negedge clk);
            // a beat taken at the last rising edge leaves; offer the next with probability 1 - stall
            if (taken) s_valid = 1'b0;
            if (!s_valid && sent < nspans && ($unsigned($random) % 100) >= stall) begin
                s_valid = 1'b1;
                s_data = beats[sent];
            end
            m_ready = ($unsigned($random) % 100) >= stall;
            #1;
            // the handshakes of the coming rising edge
            taken = s_valid && s_ready;
            if (taken) sent = sent + 1;
            if (m_valid && m_ready) begin
                if ({m_user, m_last, m_data} !== pixels[got]) begin
                    $display("tb_spec_shader: pixel %0d: got flags %h last %b value %h, want flags %h last %b value %h",
                             got, m_user, m_last, m_data, pixels[got][23:17], pixels[got][16], pixels[got][15:0]);
                    $fatal(1);
                end
                got = got + 1;
            end
            cycles = cycles + 1;
            if (cycles > limit) begin
                $display("tb_spec_shader: no progress after %0d cycles (%0d spans sent, %0d pixels)", cycles, sent, got);
                $fatal(1);
            end
        end
        // no pixel after the last
        @(negedge clk);
        s_valid = 1'b0;
        m_ready = 1'b1;
        repeat (50) begin
            #1;
            if (m_valid) begin
                $display("tb_spec_shader: a pixel after the last one");
                $fatal(1);
            end
            @(negedge clk);
        end
        $display("tb_spec_shader: PASS (%0d spans, %0d pixels, %0d cycles)", nspans, npixels, cycles);
        $finish;
    end
endmodule
`default_nettype wire
