// spec_stream - the UA 71489 datapath as a streaming core: one pixel per clock, span descriptors in through
// an AXI4-Stream sink, pixels out through an AXI4-Stream source. Same datapath modules as spec_unit
// (ROM 9, decoder 10, adder 6 / register 8, multiplier 11, ROM 12, multiplier 13), same pixels bit for bit.
//
// Descriptor (s_axis_tdata, DESC_W bits; the layout is the generator's, rom/spec_params.vh; bits outside the
// fields are ignored). Default widths: C [15:0], n [25:16], l [47:32], zeta0 [95:64], dzeta [127:96], 128 bits.
//   [DESC_C_LSB +: C_W]          C       UQ0.C_W                     (register 1)
//   [DESC_N_LSB +: N_W]          n       0 .. 2^N_W - 1              (register 4)
//   [DESC_L_LSB +: L_W]          l       intervals, l + 1 pixels     (counter 5)
//   [DESC_ZETA0_LSB +: ANG_W]    zeta0   start angle, two's complement, ANG_FRAC fraction bits (register 3)
//   [DESC_DZETA_LSB +: ANG_W]    dzeta   angle step, same format     (register 2)
// Fields outside DESC_W or overlapping stop elaboration (spec_parameter_error_... modules, as spec_param_check).
// Pixels (m_axis_tdata, OUT_W bits): intensity UQ0.OUT_W; m_axis_tlast = 1 on a span's last pixel.
//
// Throughput: one pixel per clock while m_axis_tready = 1 and descriptors arrive in time, also across
// span boundaries: the next descriptors wait in a two-entry buffer while the current span runs.
// Latency: a descriptor accepted in cycle a (core idle) gives its first pixel in cycle
// a + 3 + ACC + LAT = a + `SPEC_STREAM_LATENCY (20; 22 with INTERP = 1): buffer, span generator, accumulator (ACC = 5),
// datapath (LAT = 12 or 14), output register. Backpressure: every pipeline stage advances only when the output
// register's skid buffer is empty (a register: no combinational path from m_axis_tready); m_axis_tvalid,
// m_axis_tdata and m_axis_tlast are registers and hold until accepted. s_axis_tready is a register too:
// 1 while the descriptor buffer's second entry is free.
// Reset: rst_n is synchronous, active low. At an edge where it is 0 the buffer, the span generator, the
// pipeline's valid flags and the output registers are cleared: m_axis_tvalid = 0 (and tdata, tlast = 0) from
// the next cycle and no pixel of a span in progress appears later; s_axis_tready is 0 in the cycle after a
// reset edge and 1 from the one after.
// A descriptor handed over in a cycle with rst_n = 0 is dropped.
`timescale 1ns / 1ps
`default_nettype none
`include "spec_params.vh"
module spec_stream #(
    parameter C_W = `SPEC_C_W,
    parameter ANG_W = `SPEC_ANG_W,
    parameter ANG_FRAC = `SPEC_ANG_FRAC,
    parameter N_W = `SPEC_N_W,
    parameter L_W = `SPEC_L_W,
    parameter OUT_W = `SPEC_OUT_W,
    parameter SCALE_W = `SPEC_SCALE_W,
    parameter SCALE_FRAC = `SPEC_SCALE_FRAC,
    parameter TBL_AW = `SPEC_TBL_AW,
    parameter TBL_FRAC = `SPEC_TBL_FRAC,
    parameter INTERP = `SPEC_INTERP,
    parameter INTERP_FRAC = `SPEC_INTERP_FRAC,
    parameter DELTA_W = `SPEC_DELTA_W,
    parameter DECODER_ROM = `SPEC_DECODER_ROM,  // 1: ROM 9's word carries the table (tuned mode); 0: Fig. 10 gates
    parameter TSEL_W = `SPEC_TSEL_W,            // ROM 12 table index width (2 with DECODER_ROM = 0)
    parameter ROM9_FILE = `SPEC_ROM9_FILE,
    parameter ROM12_FILE = `SPEC_ROM12_FILE,
    parameter DESC_W = `SPEC_DESC_W,
    parameter DESC_C_LSB = `SPEC_DESC_C_LSB,
    parameter DESC_N_LSB = `SPEC_DESC_N_LSB,
    parameter DESC_L_LSB = `SPEC_DESC_L_LSB,
    parameter DESC_ZETA0_LSB = `SPEC_DESC_ZETA0_LSB,
    parameter DESC_DZETA_LSB = `SPEC_DESC_DZETA_LSB
) (
    input  wire              clk,
    input  wire              rst_n,
    input  wire              s_axis_tvalid,
    output wire              s_axis_tready,
    input  wire [DESC_W-1:0] s_axis_tdata,
    output reg               m_axis_tvalid,
    input  wire              m_axis_tready,
    output reg  [OUT_W-1:0]  m_axis_tdata,
    output reg               m_axis_tlast
);
    wire rst = ~rst_n;

    spec_param_check #(
        .C_W(C_W), .ANG_W(ANG_W), .ANG_FRAC(ANG_FRAC), .N_W(N_W), .L_W(L_W), .OUT_W(OUT_W), .SCALE_W(SCALE_W),
        .SCALE_FRAC(SCALE_FRAC), .TBL_AW(TBL_AW), .TBL_FRAC(TBL_FRAC), .INTERP(INTERP), .INTERP_FRAC(INTERP_FRAC),
        .DELTA_W(DELTA_W), .DECODER_ROM(DECODER_ROM), .TSEL_W(TSEL_W)
    ) u_check ();
    // the descriptor's fields lie inside DESC_W and do not overlap
    localparam C_END = DESC_C_LSB + C_W, N_END = DESC_N_LSB + N_W, L_END = DESC_L_LSB + L_W;
    localparam Z_END = DESC_ZETA0_LSB + ANG_W, D_END = DESC_DZETA_LSB + ANG_W;
    generate
        if (DESC_C_LSB < 0 || DESC_N_LSB < 0 || DESC_L_LSB < 0 || DESC_ZETA0_LSB < 0 || DESC_DZETA_LSB < 0 ||
            C_END > DESC_W || N_END > DESC_W || L_END > DESC_W || Z_END > DESC_W || D_END > DESC_W)
        begin : g_desc_inside
            spec_parameter_error_a_descriptor_field_lies_outside_DESC_W check_the_DESC_LSB_parameters ();
        end
        if (!(C_END <= DESC_N_LSB || N_END <= DESC_C_LSB) || !(C_END <= DESC_L_LSB || L_END <= DESC_C_LSB) ||
            !(C_END <= DESC_ZETA0_LSB || Z_END <= DESC_C_LSB) || !(C_END <= DESC_DZETA_LSB || D_END <= DESC_C_LSB) ||
            !(N_END <= DESC_L_LSB || L_END <= DESC_N_LSB) || !(N_END <= DESC_ZETA0_LSB || Z_END <= DESC_N_LSB) ||
            !(N_END <= DESC_DZETA_LSB || D_END <= DESC_N_LSB) || !(L_END <= DESC_ZETA0_LSB || Z_END <= DESC_L_LSB) ||
            !(L_END <= DESC_DZETA_LSB || D_END <= DESC_L_LSB) ||
            !(Z_END <= DESC_DZETA_LSB || D_END <= DESC_ZETA0_LSB))
        begin : g_desc_overlap
            spec_parameter_error_descriptor_fields_overlap check_the_DESC_LSB_parameters ();
        end
    endgenerate

    // descriptor fields
    wire [C_W-1:0] d_c = s_axis_tdata[DESC_C_LSB +: C_W];
    wire [N_W-1:0] d_n = s_axis_tdata[DESC_N_LSB +: N_W];
    wire [L_W-1:0] d_l = s_axis_tdata[DESC_L_LSB +: L_W];
    wire [ANG_W-1:0] d_zeta0 = s_axis_tdata[DESC_ZETA0_LSB +: ANG_W];
    wire [ANG_W-1:0] d_dzeta = s_axis_tdata[DESC_DZETA_LSB +: ANG_W];
    wire unused_desc;   // the reserved bits between the fields
    assign unused_desc = &{1'b0, s_axis_tdata};

    wire ce;             // the pipeline advances
    wire out_valid;

    // ---- descriptor buffer ("registers 1-4 and counter 5" of the next span) -------------------------------
    // Two entries (head, tail) so that s_axis_tready is a register: tready = "the tail is free".
    localparam DW = C_W + N_W + L_W + 1 + 2 * ANG_W;
    wire [DW-1:0] d_in = {d_c, d_n, d_l, (d_l == {L_W{1'b0}}), d_zeta0, d_dzeta};
    reg head_v, tail_v, ready_q;
    reg [DW-1:0] head, tail;
    wire take;           // the span generator takes the head in this cycle
    assign s_axis_tready = ready_q;
    wire accept = s_axis_tvalid & ready_q;
    // The data registers load without conditions on the input: the head whenever it is free or being
    // taken, the tail whenever it is free; the valid flags say what they hold. This keeps the enables of
    // the wide registers one gate away from flip-flops.
    wire head_load = ~head_v | take;
    always @(posedge clk) begin
        if (head_load) head <= tail_v ? tail : d_in;
        if (~tail_v) tail <= d_in;
    end
    wire tail_v_d = tail_v ? ~take : (accept & head_v & ~take);
    always @(posedge clk) begin
        if (rst) begin
            head_v <= 1'b0;
            tail_v <= 1'b0;
            ready_q <= 1'b0;
        end else begin
            if (head_load) head_v <= tail_v | accept;
            tail_v <= tail_v_d;
            ready_q <= ~tail_v_d;
        end
    end
    wire [C_W-1:0] head_c;
    wire [N_W-1:0] head_n;
    wire [L_W-1:0] head_l;
    wire head_single;    // l = 0: the span is one pixel
    wire [ANG_W-1:0] head_zeta0, head_dzeta;
    assign {head_c, head_n, head_l, head_single, head_zeta0, head_dzeta} = head;

    // ROM 9, read as the span starts: its word is the current span's scale (and, with DECODER_ROM = 1, its
    // table) from the span's first pixel on
    wire [SCALE_W-1:0] cur_scale;
    wire [TSEL_W-1:0] rom_tsel;
    spec_rom9 #(
        .N_W(N_W), .SCALE_W(SCALE_W), .SCALE_FRAC(SCALE_FRAC), .DECODER_ROM(DECODER_ROM), .TSEL_W(TSEL_W),
        .INIT_FILE(ROM9_FILE)
    ) u_rom9 (
        .clk(clk), .en(take), .n(head_n), .scale(cur_scale), .table_sel(rom_tsel)
    );
    // decoder 10 on the head's n (DECODER_ROM = 0)
    wire [1:0] head_tsel;
    wire d30_unused, d31_unused, d32_unused, d33_unused;
    spec_decoder #(.N_W(N_W)) u_dec10 (
        .n(head_n), .d30(d30_unused), .d31(d31_unused), .d32(d32_unused), .d33(d33_unused),
        .table_sel(head_tsel)
    );

    // ---- span generator: the counter, the span's C, scale and table; register 8 below ----------------------
    reg cur_v;
    reg [L_W-1:0] cur_cnt;        // intervals left after the current pixel
    reg cur_last;                 // the current pixel is its span's last (cur_cnt == 0), kept as a flag
    reg cur_first;                // the current pixel is its span's first
    reg [ANG_W-1:0] cur_zeta0, cur_dzeta;
    reg [C_W-1:0] cur_c;
    reg [1:0] cur_gate_tsel;      // decoder 10's gates (DECODER_ROM = 0)
    wire cur_done = ~cur_v | cur_last;     // the current pixel is the span's last (or there is none)
    assign take = ce & cur_done & head_v;
    wire step = ce & cur_v & ~cur_last;

    always @(posedge clk) begin
        if (rst) cur_v <= 1'b0;
        else if (ce & cur_done) cur_v <= head_v;
        if (take) begin
            cur_cnt <= head_l;
            cur_last <= head_single;
            cur_first <= 1'b1;
            cur_zeta0 <= head_zeta0;
            cur_dzeta <= head_dzeta;
            cur_c <= head_c;
            cur_gate_tsel <= head_tsel;
        end else if (step) begin
            cur_cnt <= cur_cnt - {{(L_W - 1) {1'b0}}, 1'b1};
            cur_last <= (cur_cnt == {{(L_W - 1) {1'b0}}, 1'b1});
            cur_first <= 1'b0;
        end
    end

    wire [TSEL_W-1:0] cur_tsel;
    generate
        if (DECODER_ROM != 0) begin : g_dec_rom
            assign cur_tsel = rom_tsel;
            wire unused_gates;
            assign unused_gates = &{1'b0, cur_gate_tsel};
        end else begin : g_dec_gates
            assign cur_tsel = cur_gate_tsel;
            wire unused_rom;
            assign unused_rom = &{1'b0, rom_tsel};
        end
    endgenerate

    // register 8: the pipelined accumulator (ACC clocks of ce from the current pixel to its angle)
    localparam ACC = (ANG_W + L_W + 15) / 16 + 2;
    wire [ANG_W-1:0] angle8;
    spec_saccum #(.ANG_W(ANG_W), .L_W(L_W), .SEG(16)) u_acc68 (
        .clk(clk), .ce(ce), .first(cur_first), .zeta0(cur_zeta0), .dzeta(cur_dzeta), .angle(angle8)
    );
    // the current pixel's flags, C, scale and table, delayed to meet its angle
    reg [ACC:1] v8;
    always @(posedge clk) begin
        if (rst) v8 <= {ACC{1'b0}};
        else if (ce) v8 <= {v8[ACC-1:1], cur_v};
    end
    wire last8;
    wire [C_W-1:0] c8;
    wire [SCALE_W-1:0] scale8;
    wire [TSEL_W-1:0] tsel8;
    spec_delay #(.W(1 + C_W + SCALE_W + TSEL_W), .N(ACC)) u_side8 (
        .clk(clk), .ce(ce), .d({cur_last, cur_c, cur_scale, cur_tsel}), .q({last8, c8, scale8, tsel8})
    );

    // ---- datapath: multiplier 11, ROM 12, [interpolator], multiplier 13 -------------------------------------
    wire dp_busy_unused;
    wire [OUT_W-1:0] dp_out;
    wire dp_last;
    spec_datapath #(
        .C_W(C_W), .ANG_W(ANG_W), .ANG_FRAC(ANG_FRAC), .OUT_W(OUT_W), .SCALE_W(SCALE_W),
        .SCALE_FRAC(SCALE_FRAC), .TBL_AW(TBL_AW), .TBL_FRAC(TBL_FRAC), .INTERP(INTERP),
        .INTERP_FRAC(INTERP_FRAC), .DELTA_W(DELTA_W), .TSEL_W(TSEL_W), .ROM12_FILE(ROM12_FILE)
    ) u_dp (
        .clk(clk), .rst(rst), .ce(ce), .in_valid(v8[ACC]), .in_last(last8), .angle(angle8),
        .scale(scale8), .table_sel(tsel8), .c(c8), .out(dp_out), .out_valid(out_valid),
        .out_last(dp_last), .busy(dp_busy_unused)
    );

    // ---- output register with a skid buffer ---------------------------------------------------------------
    // The pipeline's enable is a register (the skid buffer is empty), not m_axis_tready itself: no
    // combinational path from m_axis_tready into the core's hundreds of enables. When the sink stalls, the
    // one pixel already on its way is caught in the skid buffer and the pipeline stops a clock later.
    reg skid_v, skid_last;
    reg [OUT_W-1:0] skid_data;
    assign ce = ~skid_v;
    // each next-state function below has at most four inputs: one LUT level from the flip-flops
    wire o_load = skid_v ? m_axis_tready : (out_valid & (~m_axis_tvalid | m_axis_tready));
    always @(posedge clk) begin
        if (rst) begin
            m_axis_tvalid <= 1'b0;
            skid_v <= 1'b0;
        end else begin
            m_axis_tvalid <= skid_v | out_valid | (m_axis_tvalid & ~m_axis_tready);
            skid_v <= skid_v ? ~m_axis_tready : (out_valid & m_axis_tvalid & ~m_axis_tready);
        end
        if (~skid_v) begin                  // an empty skid buffer copies the pipeline's output
            skid_data <= dp_out;
            skid_last <= dp_last;
        end
        if (rst) begin                      // defined from the first reset on (4-state simulators)
            m_axis_tdata <= {OUT_W{1'b0}};
            m_axis_tlast <= 1'b0;
        end else if (o_load) begin
            m_axis_tdata <= skid_v ? skid_data : dp_out;
            m_axis_tlast <= skid_v ? skid_last : dp_last;
        end
    end
endmodule
`default_nettype wire
