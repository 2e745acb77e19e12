// spec_stream - the UA 71489 datapath as a streaming core: LANES pixels per clock (1, 2 or 4), span
// descriptors in through an AXI4-Stream sink, pixels out through an AXI4-Stream source. Same datapath modules
// as spec_unit (ROM 9, decoder 10, adder 6 / register 8, multiplier 11, ROM 12, multiplier 13), the same
// pixels bit for bit and in the same order for every LANES. POW = 1 (pow mode, docs/pow.md): each lane's
// datapath is spec_powpath (ROM 9 the log table, read per pixel; multiplier 11 by n; ROM 12 exp2), and n travels
// beside the pixels where ROM 9's scale does otherwise; the same ports, descriptor and rules.
//
// Descriptor (s_axis_tdata, DESC_W bits; the layout is the generator's, rom/spec_params.vh; bits outside the
// fields are ignored). Default widths: C [15:0], n [25:16], l [47:32], zeta0 [95:64], dzeta [127:96], 128 bits.
//   [DESC_C_LSB +: C_W]          C       UQ0.C_W                     (register 1)
//   [DESC_N_LSB +: N_W]          n       0 .. 2^N_W - 1              (register 4)
//   [DESC_L_LSB +: L_W]          l       intervals, l + 1 pixels     (counter 5)
//   [DESC_ZETA0_LSB +: ANG_W]    zeta0   start angle, two's complement, ANG_FRAC fraction bits (register 3)
//   [DESC_DZETA_LSB +: ANG_W]    dzeta   angle step, same format     (register 2)
// Fields outside DESC_W or overlapping stop elaboration (spec_parameter_error_... modules, as spec_param_check).
// Pixels: a beat carries LANES slots of OUT_W bits, slot j in m_axis_tdata[j*OUT_W +: OUT_W] (intensity
// UQ0.OUT_W); m_axis_tkeep[j] = 1 when slot j holds a pixel (the kept slots are always slots 0 .. k-1).
//   PACK = 0 (default): a beat holds pixels of one span, in order from slot 0; m_axis_tlast = 1 on a span's
//            last beat, whose slots after the span's last pixel are empty (tkeep 0). LANES = 1: one pixel
//            per beat, tkeep always 1, tlast on a span's last pixel.
//   PACK = 1 (LANES > 1): the slots are one sequence of pixels, span after span; a beat that ends a span goes
//            on with the next span's first pixels when its descriptor is there in time (at most one span
//            starts per beat). m_axis_tlast = 1 on a beat that holds a span's last pixel; where in the beat
//            it is follows from the spans' lengths (l + 1 pixels each), which the sink knows (it needs them
//            to place the pixels). Empty slots only at the end of a beat.
//
// Throughput: one beat per clock while m_axis_tready = 1 and descriptors arrive in time, also across span
// boundaries: the next descriptors wait in a three-entry buffer while the current span runs.
// Latency: a descriptor accepted in cycle a (core idle) gives its first beat in cycle
// a + 4 + ACC + LAT = a + `SPEC_STREAM_LATENCY: buffer and span generator (spec_spangen, 3), accumulator
// (spec_saccum, ACC = 8), datapath (spec_datapath with PIPE = 1, LAT = 14; 18 with INTERP = 1; POW = 1:
// spec_powpath with PIPE = 1, LAT = 27, 30 with INTERP = 1), output register. Backpressure: every pipeline
// stage advances only when the output register's skid buffer is empty (a register: no combinational path from
// m_axis_tready); m_axis_tvalid, m_axis_tdata, m_axis_tkeep and m_axis_tlast are registers and hold until
// accepted. s_axis_tready is a register too: 1 while the descriptor
// buffer's last entry is free.
// Reset: rst_n is synchronous, active low. At an edge where it is 0 the buffer, the span generator, the
// pipeline's valid flags and the output registers are cleared: m_axis_tvalid = 0 (and tdata, tlast = 0) from
// the next cycle and no pixel of a span in progress appears later; s_axis_tready is 0 in the cycle after a
// reset edge and 1 from the one after.
// A descriptor handed over in a cycle with rst_n = 0 is dropped.
// DELAY_RAM = 1: C, ROM 9's scale and the table wait beside the accumulator, and C beside the datapath, in
// memories (block RAM) instead of flip-flops (spec_delay RAM): the same pixels in the same cycles, about
// (C_W + SCALE_W + TSEL_W) * ACC + C_W * 13 flip-flops fewer per lane for 4 iCE40 block RAMs (1 on the ECP5).
// For the UP5K when the setup shares it (spec_shader's small configuration).
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
    parameter POW = `SPEC_POW,                  // 1: pow mode (ROM 9 the log table, spec_powpath; docs/pow.md)
    parameter POW_SEG_W = `SPEC_POW_SEG_W,
    parameter POW_IDX_W = `SPEC_POW_IDX_W,
    parameter POW_FRAC = `SPEC_POW_FRAC,
    parameter POW_VAL_W = `SPEC_POW_VAL_W,
    parameter POW_DLT_W = `SPEC_POW_DLT_W,
    parameter POW_SH_W = `SPEC_POW_SH_W,
    parameter POW_XB = `SPEC_POW_XB,
    parameter POW_YF = `SPEC_POW_YF,
    parameter POW_YI = `SPEC_POW_YI,
    parameter POW_K = `SPEC_POW_K,
    parameter ROM9_FILE = `SPEC_ROM9_FILE,
    parameter ROM12_FILE = `SPEC_ROM12_FILE,
    parameter DESC_W = `SPEC_DESC_W,
    parameter DESC_C_LSB = `SPEC_DESC_C_LSB,
    parameter DESC_N_LSB = `SPEC_DESC_N_LSB,
    parameter DESC_L_LSB = `SPEC_DESC_L_LSB,
    parameter DESC_ZETA0_LSB = `SPEC_DESC_ZETA0_LSB,
    parameter DESC_DZETA_LSB = `SPEC_DESC_DZETA_LSB,
    parameter LANES = 1,                        // pixels per beat: 1, 2 or 4
    parameter PACK = 0,                         // 1: a beat may end one span and start the next (LANES > 1)
    parameter DELAY_RAM = 0                     // 1: the long side-band delays in block RAM (fewer flip-flops)
) (
    input  wire              clk,
    input  wire              rst_n,
    input  wire              s_axis_tvalid,
    output wire              s_axis_tready,
    input  wire [DESC_W-1:0] s_axis_tdata,
    output wire                    m_axis_tvalid,
    input  wire                    m_axis_tready,
    output wire [LANES*OUT_W-1:0]  m_axis_tdata,
    output wire [LANES-1:0]        m_axis_tkeep,
    output wire                    m_axis_tlast
);
    wire rst = ~rst_n;

    spec_param_check #(
        .C_W(C_W), .ANG_W(ANG_W), .ANG_FRAC(ANG_FRAC), .N_W(N_W), .L_W(L_W), .OUT_W(OUT_W), .SCALE_W(SCALE_W),
        .SCALE_FRAC(SCALE_FRAC), .TBL_AW(TBL_AW), .TBL_FRAC(TBL_FRAC), .INTERP(INTERP), .INTERP_FRAC(INTERP_FRAC),
        .DELTA_W(DELTA_W), .DECODER_ROM(DECODER_ROM), .TSEL_W(TSEL_W), .POW(POW), .POW_SEG_W(POW_SEG_W),
        .POW_IDX_W(POW_IDX_W), .POW_FRAC(POW_FRAC), .POW_VAL_W(POW_VAL_W), .POW_DLT_W(POW_DLT_W), .POW_SH_W(POW_SH_W),
        .POW_XB(POW_XB), .POW_YF(POW_YF), .POW_YI(POW_YI), .POW_K(POW_K)
    ) u_check ();
    // the descriptor's fields lie inside DESC_W and do not overlap
    spec_desc_check #(
        .C_W(C_W), .N_W(N_W), .L_W(L_W), .ANG_W(ANG_W), .DESC_W(DESC_W), .DESC_C_LSB(DESC_C_LSB),
        .DESC_N_LSB(DESC_N_LSB), .DESC_L_LSB(DESC_L_LSB), .DESC_ZETA0_LSB(DESC_ZETA0_LSB),
        .DESC_DZETA_LSB(DESC_DZETA_LSB)
    ) u_desc_check ();
    generate
        if (LANES != 1 && LANES != 2 && LANES != 4) begin : g_lanes
            spec_parameter_error_LANES_must_be_1_2_or_4 check_the_LANES_parameter ();
        end
        if (PACK != 0 && PACK != 1) begin : g_pack
            spec_parameter_error_PACK_must_be_0_or_1 check_the_PACK_parameter ();
        end
    endgenerate

    wire ce;             // the pipeline advances
    wire ce_next;        // ce in the next cycle

    // ---- descriptor buffer and span generator: beats of LANES slots ---------------------------------------
    localparam OW = ANG_W + 2;
    // the span's ROM 9 word beside its pixels: the scale, or in pow mode n (ROM 9 is read per pixel there)
    localparam SW = (POW != 0) ? N_W : SCALE_W;
    wire [LANES-1:0] b_valid, b_first, b_last;
    wire [LANES*C_W-1:0] b_c;
    wire [LANES*SW-1:0] b_scale;
    wire [LANES*TSEL_W-1:0] b_tsel;
    wire [LANES*ANG_W-1:0] b_zeta0;
    wire [LANES*OW-1:0] b_offs, b_step;
    spec_spangen #(
        .LANES(LANES), .PACK(PACK), .C_W(C_W), .N_W(N_W), .L_W(L_W), .ANG_W(ANG_W), .SCALE_W(SW),
        .SCALE_FRAC(SCALE_FRAC), .DECODER_ROM(DECODER_ROM), .TSEL_W(TSEL_W), .POW(POW), .ROM9_FILE(ROM9_FILE),
        .DESC_W(DESC_W), .DESC_C_LSB(DESC_C_LSB), .DESC_N_LSB(DESC_N_LSB), .DESC_L_LSB(DESC_L_LSB),
        .DESC_ZETA0_LSB(DESC_ZETA0_LSB), .DESC_DZETA_LSB(DESC_DZETA_LSB), .OW(OW)
    ) u_gen (
        .clk(clk), .rst(rst), .ce(ce), .ce_next(ce_next), .s_axis_tvalid(s_axis_tvalid),
        .s_axis_tready(s_axis_tready),
        .s_axis_tdata(s_axis_tdata), .b_valid(b_valid), .b_first(b_first), .b_last(b_last), .b_c(b_c),
        .b_scale(b_scale), .b_tsel(b_tsel), .b_zeta0(b_zeta0), .b_offs(b_offs), .b_step(b_step)
    );

    // ---- the slots' flags (valid, last), from the beat to the output: NC stages of ce ------------------------
    localparam SEG = 12;
    localparam ACC = (ANG_W + L_W + SEG - 1) / SEG + 4;            // spec_saccum's stages
    // spec_datapath's stages (PIPE = 1), or spec_powpath's (Format::pow_latency)
    localparam LAT_COSK = 14 + ((INTERP != 0) ? 4 : 0);
    localparam LAT_POW = 3 + POW_SEG_W + 3 + 3 + 3 + (POW_SH_W + 1) / 2 + ((INTERP != 0) ? 0 : 1) +
                         ((INTERP != 0) ? 3 : 2) + ((INTERP != 0) ? 3 : 0) + POW_YI / 2 + 4;
    localparam LAT = (POW != 0) ? LAT_POW : LAT_COSK;
    localparam NC = ACC + LAT;
    reg [NC*LANES-1:0] ctl_v, ctl_l;    // stage k (1 .. NC) of slot j at [(k-1)*LANES + j]
    always @(posedge clk) begin
        if (rst) ctl_v <= {NC*LANES{1'b0}};
        else if (ce) ctl_v <= {ctl_v[(NC-1)*LANES-1:0], b_valid};
        if (ce) ctl_l <= {ctl_l[(NC-1)*LANES-1:0], b_last};
    end
    wire [LANES-1:0] out_v = ctl_v[(NC-1)*LANES +: LANES];
    wire [LANES-1:0] out_l = ctl_l[(NC-1)*LANES +: LANES];
    wire out_valid = out_v[0];           // slot 0 is kept whenever any slot is
    wire out_last = |(out_l & out_v);

    // ---- per slot: register 8 (the pipelined accumulator), then multiplier 11, ROM 12, [interpolator],
    // multiplier 13 -------------------------------------------------------------------------------------------
    wire [LANES*OUT_W-1:0] dp_out;
    genvar j;
    generate
        for (j = 0; j < LANES; j = j + 1) begin : g_lane
            wire [ANG_W-1:0] angle8;
            spec_saccum #(.ANG_W(ANG_W), .L_W(L_W), .SEG(SEG), .OW(OW), .OFFS((LANES > 1) ? 1 : 0)) u_acc68 (
                .clk(clk), .ce(ce), .first(b_first[j]), .zeta0(b_zeta0[j*ANG_W +: ANG_W]),
                .offs(b_offs[j*OW +: OW]), .step(b_step[j*OW +: OW]), .angle(angle8)
            );
            // the slot's C, scale (pow mode: n) and table, delayed to meet its angle
            wire [C_W-1:0] c8;
            wire [SW-1:0] scale8;
            wire [TSEL_W-1:0] tsel8;
            spec_delay #(.W(C_W + SW + TSEL_W), .N(ACC), .RAM(DELAY_RAM)) u_side8 (
                .clk(clk), .ce(ce),
                .d({b_c[j*C_W +: C_W], b_scale[j*SW +: SW], b_tsel[j*TSEL_W +: TSEL_W]}),
                .q({c8, scale8, tsel8})
            );
            // the datapath's scale (patent and tuned mode) or n (pow mode)
            wire [SCALE_W-1:0] scale_dp;
            wire [N_W-1:0] n_dp;
            if (POW != 0) begin : g_pow
                assign scale_dp = {SCALE_W{1'b0}};
                assign n_dp = scale8;
                wire unused_tsel;
                assign unused_tsel = &{1'b0, tsel8};
            end else begin : g_cosk
                assign scale_dp = scale8;
                assign n_dp = {N_W{1'b0}};
            end
            wire dp_valid_unused, dp_next_unused, dp_last_unused, dp_busy_unused;
            spec_datapath #(
                .C_W(C_W), .ANG_W(ANG_W), .ANG_FRAC(ANG_FRAC), .OUT_W(OUT_W), .SCALE_W(SCALE_W),
                .SCALE_FRAC(SCALE_FRAC), .TBL_AW(TBL_AW), .TBL_FRAC(TBL_FRAC), .INTERP(INTERP),
                .INTERP_FRAC(INTERP_FRAC), .DELTA_W(DELTA_W), .TSEL_W(TSEL_W), .PIPE(1), .CTRL(0),
                .DELAY_RAM(DELAY_RAM), .N_W(N_W), .POW(POW), .POW_SEG_W(POW_SEG_W), .POW_IDX_W(POW_IDX_W), .POW_FRAC(POW_FRAC),
                .POW_VAL_W(POW_VAL_W), .POW_DLT_W(POW_DLT_W), .POW_SH_W(POW_SH_W), .POW_XB(POW_XB), .POW_YF(POW_YF),
                .POW_YI(POW_YI), .POW_K(POW_K), .ROM9_FILE(ROM9_FILE), .ROM12_FILE(ROM12_FILE)
            ) u_dp (
                .clk(clk), .rst(rst), .ce(ce), .in_valid(1'b0), .in_last(1'b0), .angle(angle8),
                .scale(scale_dp), .table_sel(tsel8), .n(n_dp), .c(c8), .out(dp_out[j*OUT_W +: OUT_W]),
                .out_valid(dp_valid_unused), .out_valid_next(dp_next_unused), .out_last(dp_last_unused),
                .busy(dp_busy_unused)
            );
        end
    endgenerate

    // ---- output register with a skid buffer (spec_stream_out) ------------------------------------------------
    // out_valid in the next cycle: the stage before it moves up when ce
    wire out_valid_d = ce ? ctl_v[(NC-2)*LANES] : out_valid;
    spec_stream_out #(.LANES(LANES), .OUT_W(OUT_W)) u_out (
        .clk(clk), .rst(rst), .in_valid(out_valid), .in_valid_next(out_valid_d), .in_data(dp_out),
        .in_keep(out_v), .in_last(out_last), .ce(ce), .ce_next(ce_next), .m_axis_tvalid(m_axis_tvalid),
        .m_axis_tready(m_axis_tready), .m_axis_tdata(m_axis_tdata), .m_axis_tkeep(m_axis_tkeep),
        .m_axis_tlast(m_axis_tlast)
    );
endmodule
`default_nettype wire
