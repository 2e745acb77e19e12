// fv_spec_unit - formal properties of spec_unit (the patent's core with control block 14), proved by
// formal/formal.py (make formal) with yosys-smtbmc and z3 at the reduced widths of formal.py (WIDTHS).
//
// The core is `fv_core_unit`: rtl/spec_unit.v at those widths, flattened by Yosys, with a few internal
// registers made ports (`expose`, listed in formal.py) so that the properties can name them; rtl/ is not
// edited. The ROMs are the generator's real images for the reduced widths; the multipliers are the RTL's,
// small at these widths. Every input of the wrapper is free: the solver picks any sequence of init_n,
// start, write strobes, loads and data, only with init_n = 0 in the first cycle.
//
// Specification (docs/interface.md), checked cycle by cycle:
//   - Start is accepted in cycle t when it rises there (start = 1, and 0 in cycle t-1) with busy_o = 0 and
//     init_n = 1; then busy_o is 1 exactly in cycles t+1 .. t+FIRST+2l and valid_o is 1 exactly in cycles
//     t+FIRST+2i, i = 0..l: l + 1 pulses, busy_o falls the cycle after the last one, for every l, where l is
//     the one loaded with the Start, or else the last one loaded (0 after init_n): Start held high begins one
//     span, and a Start without a new load repeats the last l;
//   - busy_o and valid_o are 0 outside such a window: no pulse while idle, busy never stuck;
//   - registers 1-4 do not change while busy_o is 1 and counter 5 only counts: start, writes and loads
//     while busy are ignored;
//   - init_n = 0 at a clock edge: idle from the next cycle, registers, counter and output 0;
//   - counter 5 holds what the interface promises: the last load, 2^L_W - 1 after a span, 0 after init; the
//     length register holds the last load (0 after init).
// The helper invariants at the end (the control block's flip-flops, counter 5 and the valid pipeline as
// functions of the cycle within the span) make the induction step short; they are proved like the rest.
`default_nettype none
`include "spec_params.vh"
module fv_spec_unit (
    input wire                     clk,
    input wire                     init_n,
    input wire                     start,
    input wire [`SPEC_C_W-1:0]     c_i,
    input wire                     c_we,
    input wire [`SPEC_ANG_W-1:0]   dzeta_i,
    input wire                     dzeta_we,
    input wire [`SPEC_ANG_W-1:0]   zeta0_i,
    input wire                     zeta0_we,
    input wire [`SPEC_N_W-1:0]     n_i,
    input wire                     n_we,
    input wire [`SPEC_L_W-1:0]     len_i,
    input wire                     len_load_n
);
    localparam C_W = `SPEC_C_W;
    localparam ANG_W = `SPEC_ANG_W;
    localparam N_W = `SPEC_N_W;
    localparam L_W = `SPEC_L_W;
    localparam OUT_W = `SPEC_OUT_W;
    localparam FIRST = `SPEC_UNIT_FIRST_PIXEL;  // pixel 0's valid_o, cycles after the accepted Start
    localparam LAT = `SPEC_DATAPATH_LATENCY;    // spec_datapath's stages
    localparam TW = L_W + 7;      // cycle counter within a span: FIRST + 2 * 2^L_W + 2 fits

    wire [OUT_W-1:0] intensity;
    wire busy, valid;
    // internals (Yosys `expose`)
    wire [C_W-1:0] c_q;
    wire [ANG_W-1:0] dzeta_q, zeta0_q;
    wire [N_W-1:0] n_q;
    wire [L_W-1:0] cnt5, len_q;
    wire start_q;
    wire ff39, gen40, ff41, ff43, ff44, fresh8;
    wire [LAT:1] vs;

    fv_core_unit dut (
        .clk(clk), .init_n(init_n), .start(start), .c_i(c_i), .c_we(c_we), .dzeta_i(dzeta_i),
        .dzeta_we(dzeta_we), .zeta0_i(zeta0_i), .zeta0_we(zeta0_we), .n_i(n_i), .n_we(n_we), .len_i(len_i),
        .len_load_n(len_load_n), .intensity_o(intensity), .busy_o(busy), .valid_o(valid),
        .c_q(c_q), .dzeta_q(dzeta_q), .zeta0_q(zeta0_q), .n_q(n_q), .\u_cnt5.q (cnt5),
        .\u_ctrl14.ff39 (ff39), .\u_ctrl14.gen40 (gen40), .\u_ctrl14.ff41 (ff41), .\u_ctrl14.ff43 (ff43),
        .\u_ctrl14.ff44 (ff44), .fresh8(fresh8), .\u_dp.vs (vs), .start_q(start_q), .len_q(len_q)
    );

    // ---- the interface's model -------------------------------------------------------------------------
    reg f_past = 1'b0, f_past2 = 1'b0;
    always @(posedge clk) begin
        f_past <= 1'b1;
        f_past2 <= f_past;
    end
    always @(*) if ($initstate) assume (!init_n);

    reg f_start_q;                                  // Start one cycle ago
    always @(posedge clk) f_start_q <= start;
    wire accept = start & ~f_start_q & ~busy & init_n;   // an accepted Start: a rising edge while idle
    reg [L_W-1:0] f_len;                            // counter 5 as docs/interface.md describes it
    reg [L_W-1:0] f_lenreg;                         // the length register: the last l loaded
    reg f_run;                                      // inside a span's busy window
    reg [TW-1:0] f_t;                               // cycles since the accepted Start
    reg [L_W-1:0] f_l;                              // the span's l
    reg [L_W:0] f_px;                               // valid_o pulses of the span so far
    wire [TW-1:0] f_end = FIRST + 2 * f_l;          // the cycle of the last pixel
    always @(posedge clk) begin
        if (!init_n) begin
            f_len <= {L_W{1'b0}};
            f_lenreg <= {L_W{1'b0}};
            f_run <= 1'b0;
        end else begin
            if (!len_load_n && !busy) f_lenreg <= len_i;
            if (!len_load_n && !busy) f_len <= len_i;
            else if (accept) f_len <= f_lenreg;                     // reloaded from the length register
            else if (f_run && f_t == f_end) f_len <= {L_W{1'b1}};   // the span ends on the 0 -> max step
            if (accept) begin
                f_run <= 1'b1;
                f_t <= 1;
                f_l <= (!len_load_n) ? len_i : f_lenreg;
                f_px <= 0;
            end else if (f_run) begin
                f_t <= f_t + 1'b1;
                f_px <= f_px + valid;
                if (f_t == f_end) f_run <= 1'b0;
            end
        end
    end
    wire [TW-1:0] f_since = f_t - FIRST;
    wire f_pixel = f_run && f_t >= FIRST && !f_since[0];   // pixel cycles are FIRST + 2i

    // ---- properties ------------------------------------------------------------------------------------
    always @(*) begin
        if (f_past) begin
            // busy exactly in t+1 .. t+FIRST+2l, valid exactly in t+FIRST+2i: l + 1 pulses, busy_o falls
            // the cycle after the last, never a pulse or busy while idle
            assert (busy == f_run);
            assert (valid == f_pixel);
            if (valid) assert (busy);
            // the pulses counted: at the last one, l of them have gone before
            if (f_run && f_t == f_end) assert (valid && f_px == f_l);
            // counter 5 as documented, while idle (during a span it counts, below); the length register
            if (!busy) assert (cnt5 == f_len);
            assert (len_q == f_lenreg);
            if (f_past2) assert (start_q == f_start_q);
        end
    end
    always @(posedge clk) begin
        if (f_past && $past(init_n)) begin
            // registers 1-4 do not change while busy: Start, writes and loads are ignored
            if ($past(busy)) begin
                assert (c_q == $past(c_q));
                assert (dzeta_q == $past(dzeta_q));
                assert (zeta0_q == $past(zeta0_q));
                assert (n_q == $past(n_q));
            end
            // what a write while idle does
            if (!$past(busy) && $past(c_we)) assert (c_q == $past(c_i));
            if (!$past(busy) && $past(n_we)) assert (n_q == $past(n_i));
            if (!$past(busy) && $past(dzeta_we)) assert (dzeta_q == $past(dzeta_i));
            if (!$past(busy) && $past(zeta0_we)) assert (zeta0_q == $past(zeta0_i));
        end
        // init_n = 0: idle from the next cycle, everything cleared
        if (f_past && !$past(init_n)) begin
            assert (!busy && !valid);
            assert (intensity == {OUT_W{1'b0}});
            assert (c_q == 0 && dzeta_q == 0 && zeta0_q == 0 && n_q == 0 && cnt5 == 0);
        end
    end

    // ---- helper invariants: the control block, counter 5 and the valid pipeline within a span -------------
    // Start in cycle 0: 39 set from 1; the generator's strobes 37 in 2, 4, .., 2 + 2l; count 34 in 3, 5, ..,
    // 3 + 2l; the last count finds counter 5 at 0 and its borrow clears 39 .. 44 (cycle 4 + 2l).
    wire [TW-1:0] f_stop = 3 + 2 * f_l;
    always @(*) begin
        if (f_past) begin
            if (!f_run) begin
                assert (!ff39 && !gen40 && !ff41 && !ff43 && !ff44 && !fresh8 && vs == 0);
            end else begin
                assert (f_t >= 1 && f_t <= f_end);
                assert (ff39 == (f_t <= f_stop));
                assert (gen40 == (f_t >= 2 && f_t <= f_stop && !f_t[0]));
                assert (ff41 == (f_t >= 2 && f_t <= f_stop));
                assert (ff43 == (f_t >= 3 && f_t <= f_stop));
                assert (ff44 == (f_t >= 3 && f_t <= f_stop));
                assert (fresh8 == (f_t >= 3 && f_t <= f_stop && f_t[0]));
                if (f_t <= 2) assert (cnt5 == f_l);
                else if (f_t <= f_stop) assert (cnt5 == f_l - ((f_t - 2) >> 1));
                else assert (cnt5 == {L_W{1'b1}});
                assert (f_px == ((f_t > FIRST) ? ((f_t - FIRST + 1) >> 1) : 0));
            end
        end
    end
    genvar k;
    generate
        for (k = 1; k <= LAT; k = k + 1) begin : g_vs
            // vs[k] is fresh8 k cycles ago
            always @(*) begin
                if (f_past && f_run)
                    assert (vs[k] == (f_t >= 3 + k && f_t <= f_stop + k && ((f_t - k) & 1)));
            end
        end
    endgenerate

    // ---- covers: the interesting states are reachable ----------------------------------------------------
    reg f_busy_q = 1'b0;
    reg f_noise = 1'b0;       // Start, a write or a load while busy, in the current span
    reg f_chain = 1'b0;       // the current span started in the cycle busy_o fell (back to back)
    reg f_reload = 1'b0;      // the current span's Start came with a load, or after one
    reg f_loaded = 1'b0;      // a load since the last span
    always @(posedge clk) begin
        f_busy_q <= init_n & busy;
        if (!init_n) f_loaded <= 1'b1;                    // init_n clears counter 5: a "load" of 0
        else if (accept) f_loaded <= 1'b0;
        else if (!len_load_n && !busy) f_loaded <= 1'b1;
        if (accept) f_reload <= f_loaded | ~len_load_n;
        if (accept) f_noise <= 1'b0;
        else if (busy && (start || c_we || n_we || zeta0_we || dzeta_we || !len_load_n)) f_noise <= 1'b1;
        if (accept) f_chain <= f_busy_q;
    end
    wire f_done = f_run && f_t == f_end;   // the last pixel of a span
    always @(*) begin
        if (f_past && init_n) begin
            cover (f_done && f_l == 0);                            // a one-pixel span
            cover (f_done && f_l == {L_W{1'b1}});                  // the longest span
            cover (f_done && f_chain);                             // back-to-back spans
            cover (f_done && f_noise && f_l == 2);                 // Start/writes/loads while busy, ignored
            cover (f_done && f_reload == 0 && f_l == 3);           // Start without a load: the last l again
            cover (f_done && f_l == 2 && start);                   // Start still held high at a span's end
        end
        if (f_past && f_run && !init_n) cover (f_t > FIRST);      // init_n low after the first pixel
    end
endmodule
`default_nettype wire
