// fv_spec_shader - formal properties of spec_shader (spec_setup -> spec_stream, the span flags beside the
// pixels), checked by formal/formal.py (make formal) with yosys-smtbmc and z3 at the reduced widths of formal.py.
//
// The core is `fv_core_shader`: rtl/spec_shader.v (the multiplier setup, ITERATIVE = 0, with a 4-word descriptor
// FIFO; a 4-entry flags FIFO) with the setup's arithmetic left out as in the spec_setup job (formal/fv_setup_stub.v
// at formal.py's FV_SCHED, II = 2 and LATENCY = 3: a started span's n and l passed on, its flags
// {invalid, rule, 0, n[3:0]}) and spec_stream's pixel value cut off (free). spec_setup's and spec_stream's own
// proofs (jobs spec_setup, spec_stream) hold for any source and sink; what this job adds is the composition: the
// flags FIFO, its gating of spec_stream's descriptor input, and tuser.
//
// The source numbers its span beats (n = beats accepted so far, mod 2^N_W) and gives span k the length
// l = k mod 2^L_W, rule bit k[1] and a zero vector exactly when k[0] ^ k[2], so that every pixel's span, its place
// in it and its flags are known from the counts at the output.
// Specification (docs/setup.md):
//   - AXI4-Stream source rules on the pixel side: m_axis_tvalid held until m_axis_tready, with m_axis_tdata,
//     m_axis_tlast and m_axis_tuser unchanged (a reset may drop it);
//   - every accepted span beat gives exactly l + 1 pixels, spans in order, m_axis_tlast on the last pixel of
//     each only, no pixel without an accepted beat;
//   - every pixel carries its own span's flags on m_axis_tuser, and so does tuser whenever a span is in the
//     flags FIFO (fcnt, exposed): the oldest span's;
//   - no deadlock: while spans are outstanding and the sink is ready, a pixel comes within RESP cycles;
//   - reset: no pixel and no s_axis_tready in the cycle after a reset edge.
// These are proved for the first `bmc` cycles after reset (formal.py: base case only; an induction would need
// the shadow of every stage, as fv_spec_stream.v has for the stream).
`default_nettype none
`include "spec_params.vh"
`include "setup_params.vh"
module fv_spec_shader (
    input wire                       clk,
    input wire                       rst_n,
    input wire                       s_axis_tvalid,
    input wire [`SETUP_BEAT_W-1:0]   s_axis_tdata,
    input wire                       m_axis_tready,
    input wire [`SPEC_OUT_W-1:0]     f_px     // free: spec_stream's pixel value (cut off)
);
    localparam N_W = `SPEC_N_W;
    localparam L_W = `SPEC_L_W;
    localparam OUT_W = `SPEC_OUT_W;
    localparam VEC_W = `SETUP_VEC_W;
    localparam RESP = 40;

    wire s_axis_tready, m_axis_tvalid, m_axis_tlast;
    wire [OUT_W-1:0] m_axis_tdata;
    wire [6:0] m_axis_tuser;
    wire [2:0] fcnt;                      // exposed: spans in the flags FIFO (FLAGS_AW + 1 bits)
    fv_core_shader dut (
        .clk(clk), .rst_n(rst_n), .s_axis_tvalid(s_axis_tvalid), .s_axis_tready(s_axis_tready),
        .s_axis_tdata(s_axis_tdata), .m_axis_tvalid(m_axis_tvalid), .m_axis_tready(m_axis_tready),
        .m_axis_tdata(m_axis_tdata), .m_axis_tlast(m_axis_tlast), .m_axis_tuser(m_axis_tuser),
        .\g_stream.u_stream.dp_out.i (f_px), .\g_stream.u_stream.dp_out (),
        .fcnt(fcnt)
    );

    reg f_past = 1'b0, f_rst_q = 1'b0, f_rst_q2 = 1'b0;
    always @(posedge clk) begin
        f_past <= 1'b1;
        f_rst_q <= rst_n;
        f_rst_q2 <= f_rst_q;
    end
    always @(*) if (!f_past) assume (!rst_n);

    wire accept = s_axis_tvalid & s_axis_tready & rst_n;
    wire beat = m_axis_tvalid & m_axis_tready & rst_n;
    reg [N_W-1:0] f_acc, f_ended;       // beats accepted, spans ended (tlast beats), mod 2^N_W
    reg [L_W:0] f_run;                  // pixels of the span now out so far
    reg [N_W+1:0] f_inflight;           // spans accepted and not ended (not wrapped)
    reg [6:0] f_wait;
    always @(posedge clk) begin
        if (!rst_n) begin
            f_acc <= 0;
            f_ended <= 0;
            f_run <= 0;
            f_inflight <= 0;
            f_wait <= 0;
        end else begin
            f_acc <= f_acc + accept;
            f_inflight <= f_inflight + accept - (beat & m_axis_tlast);
            if (beat & m_axis_tlast) begin
                f_ended <= f_ended + 1'b1;
                f_run <= 0;
            end else if (beat) f_run <= f_run + 1'b1;
            f_wait <= (f_inflight != 0 && m_axis_tready && !m_axis_tvalid) ? f_wait + 1'b1 : 0;
        end
    end
    // the source numbers its beats and gives span k the length k mod 2^L_W, rule k[1], a zero vector iff k[0] ^ k[2]
    function [6:0] flags_of(input [N_W-1:0] k);   // the stub's flags
        flags_of = {k[0] ^ k[2], k[1], 1'b0, k[3:0]};
    endfunction
    wire [12*VEC_W-1:0] bvec;
    genvar g;
    generate
        for (g = 0; g < 12; g = g + 1) begin : g_vec
            assign bvec[g*VEC_W +: VEC_W] = s_axis_tdata[`SETUP_BEAT_VEC_LSB + 16 * g +: VEC_W];
        end
    endgenerate
    wire b_zero = ~|bvec[0 +: 3*VEC_W] | ~|bvec[3*VEC_W +: 3*VEC_W] | ~|bvec[6*VEC_W +: 3*VEC_W] |
                  ~|bvec[9*VEC_W +: 3*VEC_W];
    always @(*) begin
        if (s_axis_tvalid) begin
            assume (s_axis_tdata[`SETUP_BEAT_N_LSB +: N_W] == f_acc);
            assume (s_axis_tdata[`SETUP_BEAT_L_LSB +: L_W] == f_acc[L_W-1:0]);
            assume (s_axis_tdata[`SETUP_BEAT_RULE_BIT] == f_acc[1]);
            assume (b_zero == (f_acc[0] ^ f_acc[2]));
        end
    end

    reg f_stall_q = 1'b0;
    reg [OUT_W-1:0] f_data_q;
    reg f_last_q;
    reg [6:0] f_user_q;
    always @(posedge clk) begin
        f_stall_q <= rst_n & m_axis_tvalid & ~m_axis_tready;
        f_data_q <= m_axis_tdata;
        f_last_q <= m_axis_tlast;
        f_user_q <= m_axis_tuser;
    end
    always @(*) begin
        if (f_past) begin
            if (f_stall_q) assert (m_axis_tvalid && m_axis_tdata == f_data_q && m_axis_tlast == f_last_q &&
                                   m_axis_tuser == f_user_q);
            if (!f_rst_q) assert (!m_axis_tvalid && !s_axis_tready);
            if (m_axis_tvalid) begin
                assert (f_inflight != 0);
                // the f_run-th pixel of span f_ended (l = f_ended mod 2^L_W), with that span's flags
                assert (m_axis_tlast == (f_run == {1'b0, f_ended[L_W-1:0]}));
                assert (m_axis_tuser == flags_of(f_ended));
            end
            assert (f_wait < RESP);
            // tuser is the oldest span's flags as soon as that span is in the flags FIFO, before its first pixel
            // (a stale word loaded there would otherwise show only on pixels far past the bound)
            if (f_rst_q && fcnt != 0) assert (m_axis_tuser == flags_of(f_ended));
        end
    end

    always @(*) begin
        if (f_past && rst_n) begin
            cover (beat && f_ended == 1 && f_run == 1);
            cover (beat && m_axis_tlast && f_ended == 2 && f_stall_q);
        end
    end
endmodule
`default_nettype wire
