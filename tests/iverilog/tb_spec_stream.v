// tb_spec_stream - self-checking Icarus Verilog testbench for spec_stream.
// Reads +vectors=FILE (written by `specsim vectors` from the bit-exact C++ model; the same file as
// tb_spec_unit), sends every span as a descriptor with random gaps on s_axis_tvalid, takes the pixels with
// random m_axis_tready, and compares each pixel and tlast in order; any mismatch, a lost or extra pixel or a
// hang ends with $fatal (exit 1). +stall=P sets the stall probability in percent (default 30).
`timescale 1ns / 1ps
`default_nettype none
module tb_spec_stream;
    localparam VMAX = 65536;
    reg clk = 1'b0;
    always #5 clk = ~clk;

    reg rst_n = 1'b0;
    reg s_valid = 1'b0;
    reg [127:0] s_data = 128'd0;
    wire s_ready;
    wire m_valid, m_last;
    wire [15:0] m_data;
    reg m_ready = 1'b0;

    spec_stream dut (
        .clk(clk), .rst_n(rst_n), .s_axis_tvalid(s_valid), .s_axis_tready(s_ready), .s_axis_tdata(s_data),
        .m_axis_tvalid(m_valid), .m_axis_tready(m_ready), .m_axis_tdata(m_data), .m_axis_tlast(m_last)
    );

    reg [31:0] vec[0:VMAX-1];
    reg [31:0] expect_px[0:VMAX-1];
    reg expect_last[0:VMAX-1];
    reg [1023:0] path;
    integer p, s, nspans, i, npx, got, sent, cycles, stall, seed, len;
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
        repeat (3) @(posedge clk);
        rst_n <= 1'b1;
        @(posedge clk);
        while (sent < nspans) begin
            if (!s_valid && (($random(seed) & 32'h7fffffff) % 100) >= stall) begin
                p = span_at[sent];
                s_data <= {vec[p + 1], vec[p + 2], 16'd0, vec[p + 4][15:0], 6'd0, vec[p + 3][9:0], vec[p][15:0]};
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
                if (m_data !== expect_px[got][15:0] || m_last !== expect_last[got]) begin
                    $display("pixel %0d: got %h last %b, model %h last %b", got, m_data, m_last,
                             expect_px[got][15:0], expect_last[got]);
                    $fatal(1);
                end
                got = got + 1;
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
