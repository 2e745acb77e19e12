// tb_spec_stream - self-checking Icarus Verilog testbench for spec_stream (SEQ = 1: spec_stream_seq, the
// compact back end, LANES = 1).
// Reads +vectors=FILE (written by `specsim vectors` from the bit-exact C++ model; the same file as
// tb_spec_unit), sends every span as a descriptor with random gaps on s_axis_tvalid, takes the pixels with
// random m_axis_tready, and compares each pixel and tlast in order; any mismatch, a lost or extra pixel or a
// hang ends with $fatal (exit 1). +stall=P sets the stall probability in percent (default 30).
// LANES and PACK (iverilog -P) as spec_stream's: each beat's kept slots (m_axis_tkeep, slots 0 .. k-1) are
// compared in order; with PACK = 0 a beat ends at its span's last pixel, with tlast there and only there and
// empty slots only after it; with PACK = 1 tlast is set exactly on the beats that hold a span's last pixel.
// Widths and the descriptor layout come from the configuration's spec_params.vh (the include path picks it);
// ROM9_FILE/ROM12_FILE can be set with iverilog -P. 4-state: rst_n is low for exactly one clock at the start,
// and from then on every output must be 0 or 1 in every cycle.
`timescale 1ns / 1ps
`default_nettype none
`include "spec_params.vh"
module tb_spec_stream #(
    parameter ROM9_FILE = `SPEC_ROM9_FILE,
    parameter ROM12_FILE = `SPEC_ROM12_FILE,
    parameter LANES = 1,
    parameter PACK = 0,
    parameter SEQ = 0
);
    localparam VMAX = 65536;
    localparam C_W = `SPEC_C_W, ANG_W = `SPEC_ANG_W, N_W = `SPEC_N_W, L_W = `SPEC_L_W, OUT_W = `SPEC_OUT_W;
    localparam DESC_W = `SPEC_DESC_W;
    reg clk = 1'b0;
    always #5 clk = ~clk;

    reg rst_n = 1'b0;
    reg s_valid = 1'b0;
    reg [DESC_W-1:0] s_data = {DESC_W{1'b0}};
    wire s_ready;
    wire m_valid, m_last;
    wire [LANES*OUT_W-1:0] m_data;
    wire [LANES-1:0] m_keep;
    reg m_ready = 1'b0;

    generate
        if (SEQ == 0) begin : g_stream
            spec_stream #(.ROM9_FILE(ROM9_FILE), .ROM12_FILE(ROM12_FILE), .LANES(LANES), .PACK(PACK)) dut (
                .clk(clk), .rst_n(rst_n), .s_axis_tvalid(s_valid), .s_axis_tready(s_ready), .s_axis_tdata(s_data),
                .m_axis_tvalid(m_valid), .m_axis_tready(m_ready), .m_axis_tdata(m_data), .m_axis_tkeep(m_keep),
                .m_axis_tlast(m_last)
            );
        end else begin : g_seq
            spec_stream_seq #(.ROM9_FILE(ROM9_FILE), .ROM12_FILE(ROM12_FILE)) dut (
                .clk(clk), .rst_n(rst_n), .s_axis_tvalid(s_valid), .s_axis_tready(s_ready), .s_axis_tdata(s_data),
                .m_axis_tvalid(m_valid), .m_axis_tready(m_ready), .m_axis_tdata(m_data), .m_axis_tkeep(m_keep),
                .m_axis_tlast(m_last)
            );
        end
    endgenerate

    // after the one rst_n pulse, no output is ever X or Z
    reg reset_done = 1'b0;
    always @(negedge clk) begin
        if (reset_done && ^{s_ready, m_valid, m_data, m_keep, m_last} === 1'bx) begin
            $display("tb_spec_stream: an output is X or Z after reset at %0t: tready %b tvalid %b tdata %b tlast %b",
                     $time, s_ready, m_valid, m_data, m_last);
            $fatal(1);
        end
    end

    // the descriptor of span s (its registers in the vector file from word p), laid out as spec_params.vh says
    function [DESC_W-1:0] descriptor;
        input integer p;
        begin
            descriptor = {DESC_W{1'b0}};
            descriptor[`SPEC_DESC_C_LSB +: C_W] = vec[p][C_W-1:0];
            descriptor[`SPEC_DESC_N_LSB +: N_W] = vec[p + 3][N_W-1:0];
            descriptor[`SPEC_DESC_L_LSB +: L_W] = vec[p + 4][L_W-1:0];
            descriptor[`SPEC_DESC_ZETA0_LSB +: ANG_W] = vec[p + 2][ANG_W-1:0];
            descriptor[`SPEC_DESC_DZETA_LSB +: ANG_W] = vec[p + 1][ANG_W-1:0];
        end
    endfunction

    reg [31:0] vec[0:VMAX-1];
    reg [31:0] expect_px[0:VMAX-1];
    reg expect_last[0:VMAX-1];
    reg [1023:0] path;
    integer p, s, nspans, i, npx, got, sent, cycles, stall, seed, len, j, kept, ends, ends_at_last;
    integer span_at[0:8191];

    initial begin
        if (!$value$plusargs("vectors=%s", path)) begin
            $display("tb_spec_stream: +vectors=FILE missing");
            $fatal(1);
        end
        if (!$value$plusargs("stall=%d", stall)) stall = 30;
        seed = 12345;
        for (i = 0; i < VMAX; i = i + 1) vec[i] = 32'hxxxxxxxx;
        $readmemh(path, vec);
        if (^vec[0] === 1'bx) begin
            $display("tb_spec_stream: cannot read vectors from %0s", path);
            $fatal(1);
        end
        // index the spans and the expected pixel stream
        nspans = vec[0];
        p = 1;
        npx = 0;
        for (s = 0; s < nspans; s = s + 1) begin
            span_at[s] = p;
            len = vec[p + 4];
            for (i = 0; i <= len; i = i + 1) begin
                expect_px[npx] = vec[p + 5 + i];
                expect_last[npx] = (i == len);
                npx = npx + 1;
            end
            p = p + 5 + len + 1;
        end
    end

    // source: descriptors in order, valid held until accepted
    initial begin
        sent = 0;
        @(posedge clk);          // the one reset edge
        rst_n <= 1'b1;
        reset_done <= 1'b1;
        @(posedge clk);
        while (sent < nspans) begin
            if (!s_valid && (($random(seed) & 32'h7fffffff) % 100) >= stall) begin
                p = span_at[sent];
                s_data <= descriptor(p);
                s_valid <= 1'b1;
            end
            @(posedge clk);
            if (s_valid && s_ready) begin
                s_valid <= 1'b0;
                sent = sent + 1;
            end
        end
    end

    // sink: random ready, compare in order
    initial begin
        got = 0;
        cycles = 0;
        @(posedge rst_n);
        while (got < npx) begin
            m_ready <= (($random(seed) & 32'h7fffffff) % 100) >= stall;
            @(posedge clk);
            cycles = cycles + 1;
            if (m_valid && m_ready) begin
                kept = 0;
                while (kept < LANES && m_keep[kept]) kept = kept + 1;
                if (kept == 0 || (m_keep >> kept) != 0) begin
                    $display("beat at pixel %0d: tkeep %b is not slots 0 .. k-1", got, m_keep);
                    $fatal(1);
                end
                ends = 0;
                ends_at_last = 0;
                for (j = 0; j < kept; j = j + 1) begin
                    if (got >= npx) begin
                        $display("tb_spec_stream: extra pixel in a beat (slot %0d)", j);
                        $fatal(1);
                    end
                    if (m_data[j*OUT_W +: OUT_W] !== expect_px[got][OUT_W-1:0]) begin
                        $display("pixel %0d (slot %0d): got %h, model %h", got, j, m_data[j*OUT_W +: OUT_W],
                                 expect_px[got][OUT_W-1:0]);
                        $fatal(1);
                    end
                    if (expect_last[got]) begin
                        ends = 1;
                        ends_at_last = (j == kept - 1);
                        if (PACK == 0 && j != kept - 1) begin
                            $display("pixel %0d: a beat goes on after its span's last pixel", got);
                            $fatal(1);
                        end
                    end
                    got = got + 1;
                end
                if (m_last !== ends[0] || (PACK == 0 && kept < LANES && !ends_at_last)) begin
                    $display("beat ending at pixel %0d: tlast %b, tkeep %b, a span ends in it: %0d", got - 1,
                             m_last, m_keep, ends);
                    $fatal(1);
                end
            end
            if (cycles > 20 * npx + 1000) begin
                $display("tb_spec_stream: no progress after %0d cycles (%0d of %0d pixels)", cycles, got, npx);
                $fatal(1);
            end
        end
        m_ready <= 1'b1;
        repeat (40) begin
            @(posedge clk);
            if (m_valid) begin
                $display("tb_spec_stream: extra pixel after the last one");
                $fatal(1);
            end
        end
        $display("PASS: %0d spans, %0d pixels equal to the bit-exact model in %0d cycles (stall %0d %%)",
                 nspans, npx, cycles, stall);
        $finish;
    end
endmodule
`default_nettype wire
