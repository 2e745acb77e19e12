// spec_spangen - spec_stream's descriptor buffer and span generator: turns span descriptors (AXI4-Stream
// sink) into beats of LANES pixel slots, one beat per clock of `ce`. It holds registers 1-4 and counter 5 of
// the patent for the spans in flight, ROM 9 and decoder 10.
//
// Descriptor buffer: three registers, tail -> head -> prep. s_axis_tdata goes into tail or head without logic
// in between; s_axis_tready is a register (1 while the tail is free), so a descriptor can be taken every
// clock. Prep holds the next span with what the generator needs precomputed: ROM 9's word (read as the
// descriptor moves into prep), decoder 10's table, 3 * dzeta (LANES = 4) and the comparisons of l with the
// lane counts.
//
// Beats: slot j of a beat holds pixel k of a span; a beat holds the pixels of a span in order, from slot 0.
//   PACK = 0: a beat holds pixels of one span only; a span starts in slot 0 of a beat, and its last beat
//             has slots left empty when l + 1 is not a multiple of LANES.
//   PACK = 1: a beat that ends a span goes on with the next span's first pixels when a descriptor is waiting
//             (at most one span starts per beat): slots are empty only at the end of a beat, when no
//             descriptor was there in time, or when the new span also ends in that beat.
// Per slot: valid, first (the slot's first pixel of its span: the angle accumulator starts there), last (the
// span's last pixel) and the span's parameters: C, ROM 9's scale, the table, zeta0, and for the accumulator
// offs = o * dzeta (o = the pixel number k of the slot's first pixel, 0 .. LANES - 1) and step = LANES * dzeta.
// The beat registers are the outputs (b_*); the parameters are chosen from the span registers per slot.
//
// Latency: a descriptor accepted in cycle a (everything idle) is in prep in a + 2 and its first beat on the
// outputs in a + 3. Throughput: one span start per beat, also for l = 0 back to back.
// Reset (rst, synchronous): buffer, generator and beat valid flags cleared; the data registers are not.
`timescale 1ns / 1ps
`default_nettype none
module spec_spangen #(
    parameter LANES = 1,
    parameter PACK = 0,
    parameter C_W = 16,
    parameter N_W = 10,
    parameter L_W = 16,
    parameter ANG_W = 32,
    parameter SCALE_W = 18,
    parameter SCALE_FRAC = 15,
    parameter DECODER_ROM = 0,
    parameter TSEL_W = 2,
    parameter POW = 0,          // 1: pow mode: the span's "scale" is n itself (SCALE_W = N_W); ROM 9 is per pixel
    parameter ROM9_FILE = "",
    parameter DESC_W = 128,
    parameter DESC_C_LSB = 0,
    parameter DESC_N_LSB = 16,
    parameter DESC_L_LSB = 32,
    parameter DESC_ZETA0_LSB = 64,
    parameter DESC_DZETA_LSB = 96,
    parameter OW = ANG_W + 2    // width of offs and step
) (
    input  wire                     clk,
    input  wire                     rst,
    input  wire                     ce,
    input  wire                     ce_next,    // the value ce has in the next cycle (from its next-state logic)
    input  wire                     s_axis_tvalid,
    output wire                     s_axis_tready,
    input  wire [DESC_W-1:0]        s_axis_tdata,
    output wire [LANES-1:0]         b_valid,
    output wire [LANES-1:0]         b_first,
    output wire [LANES-1:0]         b_last,
    output wire [LANES*C_W-1:0]     b_c,
    output wire [LANES*SCALE_W-1:0] b_scale,
    output wire [LANES*TSEL_W-1:0]  b_tsel,
    output wire [LANES*ANG_W-1:0]   b_zeta0,
    output wire [LANES*OW-1:0]      b_offs,
    output wire [LANES*OW-1:0]      b_step
);
    localparam LI = (LANES > 2) ? 2 : 1;        // bits of a slot number
    localparam SH = (LANES == 4) ? 2 : (LANES == 2) ? 1 : 0;   // log2(LANES)
    localparam integer LM = LANES - 1;       // slot numbers modulo LANES

    // ---- descriptor buffer: tail, head ---------------------------------------------------------------------
    wire [C_W-1:0] d_c = s_axis_tdata[DESC_C_LSB +: C_W];
    wire [N_W-1:0] d_n = s_axis_tdata[DESC_N_LSB +: N_W];
    wire [L_W-1:0] d_l = s_axis_tdata[DESC_L_LSB +: L_W];
    wire [ANG_W-1:0] d_zeta0 = s_axis_tdata[DESC_ZETA0_LSB +: ANG_W];
    wire [ANG_W-1:0] d_dzeta = s_axis_tdata[DESC_DZETA_LSB +: ANG_W];
    wire unused_desc;   // the reserved bits between the fields
    assign unused_desc = &{1'b0, s_axis_tdata};
    // With the descriptor, flags saying which 4-bit groups of l above its low four bits are 0 (one LUT each
    // on the input): prep's comparisons of l need one more level only.
    localparam NG = (L_W > 4) ? (L_W - 4 + 3) / 4 : 1;
    wire [NG-1:0] d_zg;
    genvar g;
    generate
        for (g = 0; g < NG; g = g + 1) begin : g_zg
            if (L_W > 4) begin : g_z
                localparam LO = 4 + 4 * g;
                localparam HI = (LO + 3 < L_W) ? LO + 3 : L_W - 1;
                assign d_zg[g] = ~|d_l[HI:LO];
            end else begin : g_none
                assign d_zg[g] = 1'b1;
            end
        end
    endgenerate
    localparam DW = C_W + N_W + L_W + NG + 2 * ANG_W;
    wire [DW-1:0] d_in = {d_c, d_n, d_l, d_zg, d_zeta0, d_dzeta};
    reg head_v, tail_v, ready_q;
    wire [DW-1:0] head;
    reg [DW-1:0] tail;
    assign s_axis_tready = ready_q;
    wire accept = s_axis_tvalid & ready_q;
    // Enables. The widest registers, prep and the span parameters, load under enables that are flip-flops
    // themselves (tk, pl), computed a cycle ahead from the next-state values: on the iCE40 nextpnr gives the
    // widest enable nets global buffers, a long detour after any logic. tk = take and pl = prep_load in every
    // cycle (checked in simulation, proved by formal/fv_spec_stream.v). The head is a spec_ldreg: its load
    // stays logic in front of its flip-flops.
    reg tk, pl;
    // pl_n = ~pl, a copy for the buffer's valid flags only (inverted, so that synthesis does not merge it with
    // pl): pl and head_load fan out to the head's and prep's loads (over a hundred flip-flops), and the flags'
    // next-state logic would otherwise wait for those nets' long routing.
    reg pl_n;
    wire take = tk;                  // = ce & room & prep_v: the generator starts prep's span in the next beat
    wire prep_load = pl;             // = ~prep_v | take: prep takes the head
    wire head_load = ~head_v | pl;
    // The data registers load without conditions on the input: the head whenever it is free or moving on,
    // the tail whenever it is free (ready_q = ~tail_v after the first cycle out of reset); the valid flags
    // say what they hold.
    spec_ldreg #(.W(DW)) u_head (.clk(clk), .ld(head_load), .d(tail_v ? tail : d_in), .q(head));
    always @(posedge clk) begin
        if (ready_q) tail <= d_in;
    end
    wire head_out_v = ~pl_n & head_v;  // the head moves into prep in this cycle
    wire tail_v_d = tail_v ? ~head_out_v : (accept & head_v & ~head_out_v);
    // = head_load ? (tail_v | accept) : head_v, written without the choice, so that head_v's flip-flop gets
    // no enable (which would be head_load, the wide net)
    wire head_v_d = accept | tail_v | (head_v & pl_n);
    always @(posedge clk) begin
        if (rst) begin
            head_v <= 1'b0;
            tail_v <= 1'b0;
            ready_q <= 1'b0;
        end else begin
            head_v <= head_v_d;
            tail_v <= tail_v_d;
            ready_q <= ~tail_v_d;
        end
    end
    wire [C_W-1:0] head_c;
    wire [N_W-1:0] head_n;
    wire [L_W-1:0] head_l;
    wire [ANG_W-1:0] head_zeta0, head_dzeta;
    wire [NG-1:0] head_zg;
    assign {head_c, head_n, head_l, head_zg, head_zeta0, head_dzeta} = head;

    // decoder 10 on the head's n (DECODER_ROM = 0)
    wire [1:0] head_gate_tsel;
    wire d30_unused, d31_unused, d32_unused, d33_unused;
    spec_decoder #(.N_W(N_W)) u_dec10 (
        .n(head_n), .d30(d30_unused), .d31(d31_unused), .d32(d32_unused), .d33(d33_unused),
        .table_sel(head_gate_tsel)
    );

    // ---- prep: the next span, with ROM 9's word and what the generator needs of l -------------------------
    // With lq = l >> log2(LANES) and lr = l mod LANES: a span that starts in slot s has
    // c = (lr + s >= LANES) and lq + c beats after its first; its last pixel is in slot (lr + s) mod LANES.
    localparam QW = L_W - SH;        // bits of lq (and of the beat counter)
    localparam LB4 = (L_W < 4) ? L_W : 4;
    reg prep_v;
    wire [C_W-1:0] prep_c;
    wire [1:0] prep_gate_tsel;
    wire [ANG_W-1:0] prep_zeta0, prep_dzeta;
    wire [OW-1:0] prep_d3;           // 3 * dzeta (LANES = 4)
    wire [1:0] prep_lr;
    wire [QW-1:0] prep_nlqm1, prep_nlqm2; // ~(lq - 1), ~(lq - 2)
    wire prep_lq0, prep_lq1, prep_lq2p;   // lq = 0, lq = 1, lq >= 2
    wire [OW-1:0] head_dz = {{(OW - ANG_W) {head_dzeta[ANG_W-1]}}, head_dzeta};
    wire [OW-1:0] head_d3 = (LANES == 4) ? (head_dz + {head_dz[OW-2:0], 1'b0}) : {OW{1'b0}};
    wire [QW-1:0] head_lq = head_l[L_W-1:SH];
    wire [1:0] head_lr;
    generate
        if (LANES == 1) begin : g_lr1
            assign head_lr = 2'd0;
        end else if (LANES == 2) begin : g_lr2
            assign head_lr = {1'b0, head_l[0]};
        end else begin : g_lr4
            assign head_lr = head_l[1:0];
        end
    endgenerate
    wire [QW+1:0] head_lq_x = {2'b00, head_lq};
    wire [QW+1:0] head_lqm1_x = head_lq_x - {{QW{1'b0}}, 2'd1};
    wire [QW+1:0] head_lqm2_x = head_lq_x - {{QW{1'b0}}, 2'd2};
    // lq = 0, lq = 1: the high groups are 0 (head_zg) and the low four bits of l, shifted, are 0 or 1
    wire [3:0] head_l4;
    generate
        if (L_W >= 4) begin : g_l4
            assign head_l4 = head_l[3:0];
        end else begin : g_l4x
            assign head_l4 = {{(4 - LB4) {1'b0}}, head_l};
        end
    endgenerate
    wire [3:0] head_lq4 = head_l4 >> SH;
    wire head_lq0 = (&head_zg) & (head_lq4 == 4'd0);
    wire head_lq1 = (&head_zg) & (head_lq4 == 4'd1);
    wire head_lq2p = ~(&head_zg) | (head_lq4 >= 4'd2);
    wire prep_v_d = prep_load ? head_v : prep_v;
    always @(posedge clk) begin
        if (rst) prep_v <= 1'b0;
        else prep_v <= prep_v_d;
    end
    localparam PRW = C_W + 2 + 2 * ANG_W + OW + 2 + 2 * QW + 3;
    reg [PRW-1:0] prep_q;
    always @(posedge clk) begin
        if (prep_load) begin
            prep_q <= {head_c, head_gate_tsel, head_zeta0, head_dzeta, head_d3, head_lr, ~head_lqm1_x[QW-1:0],
                       ~head_lqm2_x[QW-1:0], head_lq0, head_lq1, head_lq2p};
        end
    end
    assign {prep_c, prep_gate_tsel, prep_zeta0, prep_dzeta, prep_d3, prep_lr, prep_nlqm1, prep_nlqm2, prep_lq0,
            prep_lq1, prep_lq2p} = prep_q;
    // ROM 9, read as the descriptor moves into prep: its word is prep's scale (and, with DECODER_ROM = 1, its
    // table) while prep holds it. POW = 1: n itself, in a register loaded at the same time (ROM 9 is the log
    // table, read per pixel in spec_powpath).
    wire [SCALE_W-1:0] prep_scale;
    wire [TSEL_W-1:0] prep_rom_tsel;
    wire [TSEL_W-1:0] prep_tsel;
    generate
        if (POW != 0) begin : g_pow_n
            reg [SCALE_W-1:0] n_q;
            always @(posedge clk) if (prep_load) n_q <= head_n;
            assign prep_scale = n_q;
            assign prep_rom_tsel = {TSEL_W{1'b0}};
            if (SCALE_W != N_W) begin : g_w
                spec_parameter_error_spangen_POW_needs_SCALE_W_equal_N_W check_spec_stream ();
            end
            wire unused_pow;
            assign unused_pow = &{1'b0, SCALE_FRAC[0]};
        end else begin : g_rom9
            spec_rom9 #(
                .N_W(N_W), .SCALE_W(SCALE_W), .SCALE_FRAC(SCALE_FRAC), .DECODER_ROM(DECODER_ROM), .TSEL_W(TSEL_W),
                .INIT_FILE(ROM9_FILE)
            ) u_rom9 (
                .clk(clk), .en(prep_load), .n(head_n), .scale(prep_scale), .table_sel(prep_rom_tsel)
            );
        end
        if (DECODER_ROM != 0) begin : g_dec_rom
            assign prep_tsel = prep_rom_tsel;
            wire unused_gates;
            assign unused_gates = &{1'b0, prep_gate_tsel};
        end else begin : g_dec_gates
            assign prep_tsel = prep_gate_tsel;
            wire unused_rom;
            assign unused_rom = &{1'b0, prep_rom_tsel};
        end
    endgenerate

    // ---- span generator ------------------------------------------------------------------------------------
    // The running span R: the newest span with pixels left after the presented beat. r_last1: the next beat
    // is its last; r_end: the slot of its last pixel; bc counts its beats since its first; when bc = r_t2 the
    // beat after the next is its last.
    reg r_v;
    reg [LI-1:0] r_end;
    reg [QW-1:0] bc, r_nt2;          // r_nt2 = ~r_t2
    // r_last1 from two flip-flops, so that neither has a choice in front: a take of a span with two beats
    // left (r_v & ~r_ntk), or the beat counter reaching r_t2 (r_last1_bc: the carry out of bc + ~r_t2 + 1, i.e.
    // bc >= r_t2, which is bc = r_t2 as bc never passes it while the span runs). r_ntk = r_v and not the
    // former, so that r_cont = r_ntk & ~r_last1_bc takes two inputs.
    reg r_ntk, r_last1_bc;
    wire r_last1 = (r_v & ~r_ntk) | r_last1_bc;
    wire [QW-1:0] bc_diff_unused;
    wire bc_reached;
    spec_add #(.W(QW)) u_bc_cmp (
        .a(bc), .b(r_nt2), .cin(1'b1), .p(r_nt2[0]), .sum(bc_diff_unused), .cout(bc_reached)
    );
    reg [LI-1:0] r_s;
    reg r_second;                    // the next beat is R's second (its slots below r_s start there)
    reg r_inb;                       // R's parameters are in set B (PACK)
    genvar j;
    integer i, s, rs, re, lr;
    localparam [1:0] LM2 = LM[1:0];
    // slots of R in the next beat: rl[j] = R has a pixel for slot j; its last one
    reg [LANES-1:0] rl, rlast;
    always @(*) begin
        rs = {{(32 - LI) {1'b0}}, r_s};
        re = {{(32 - LI) {1'b0}}, r_end};
        lr = {30'd0, prep_lr};
        for (i = 0; i < LANES; i = i + 1) begin
            rl[i] = r_v && (!r_last1 || i <= re);
            rlast[i] = r_v && r_last1 && i == re;
        end
        // the next beat's first free slot s (PACK; 0 otherwise)
        s = 0;
        if (PACK != 0 && r_v) s = r_last1 ? re + 1 : LANES;
    end
    wire r_cont = r_ntk & ~r_last1_bc;         // R has pixels left after the next beat (r_v & ~r_last1)
    wire room = (PACK != 0) ? ~rl[LANES-1] : ~r_v;   // a slot is free for a new span
    // the new span B in the next beat, from slot s
    reg nb_carry;                          // lr + s >= LANES
    reg b_cont;                       // B has pixels left after the next beat (lq + c >= 1)
    reg b_last1;                      // ... and the beat after the next is its last (lq + c = 1)
    reg b_cont2;                      // ... more than one (lq + c >= 2)
    reg [LI-1:0] b_end;               // the slot of its last pixel: (lr + s) mod LANES
    reg [1:0] t2;
    reg [LANES-1:0] bl_v, bl_last;
    // per slot of the next beat: first (the slot's first pixel of its span), o = (slot - the span's first
    // slot) mod LANES
    reg [LANES-1:0] f_next;
    reg [2*LANES-1:0] o_next;
    always @(*) begin
        nb_carry = (lr + s >= LANES);
        b_cont = nb_carry | ~prep_lq0;
        b_last1 = nb_carry ? prep_lq0 : prep_lq1;
        b_cont2 = nb_carry ? ~prep_lq0 : prep_lq2p;
        t2 = (prep_lr + s[1:0]) & LM2;
        b_end = t2[LI-1:0];
        for (i = 0; i < LANES; i = i + 1) begin
            bl_v[i] = (i >= s) && (b_cont || i <= lr + s);
            bl_last[i] = (i >= s) && !b_cont && i == lr + s;
            f_next[i] = rl[i] ? (r_second && (i < rs)) : 1'b1;
            o_next[2*i +: 2] = (rl[i] ? i[1:0] - rs[1:0] : i[1:0] - s[1:0]) & LM2;
        end
    end

    // the registers' next values (with ce), for the registered enables
    wire r_v_d;
    wire room_d;
    generate
        if (PACK == 0) begin : g_rv_nopack
            // = ce ? (r_cont | (take & b_cont)) : r_v, written with what PACK = 0 implies (a take needs ce and
            // ~r_v; r_ntk needs r_v; b_cont = ~prep_lq0 as nb_carry = 0), so that the registered enables'
            // next-state logic is two LUT levels: ce_next, prep_v_d, r_v & (~ce | r_cont), take & ~prep_lq0
            assign r_v_d = (r_v & (~ce | r_cont)) | (take & ~prep_lq0);
        end else begin : g_rv_pack
            assign r_v_d = ce ? (r_cont | (take & b_cont)) : r_v;
        end
        if (PACK != 0 && LANES > 1) begin : g_room_pack
            wire r_ntk_d = ce ? (take ? b_cont2 : r_cont) : r_ntk;
            wire r_last1_bc_d = ce ? (~take & bc_reached) : r_last1_bc;
            wire [LI-1:0] r_end_d = (ce & take) ? b_end : r_end;
            wire r_last1_d = (r_v_d & ~r_ntk_d) | r_last1_bc_d;
            assign room_d = ~r_v_d | (r_last1_d & (r_end_d != LM[LI-1:0]));
        end else begin : g_room
            assign room_d = ~r_v_d;
        end
    endgenerate
    wire tk_d = ce_next & room_d & prep_v_d;
    wire pl_d = ~prep_v_d | tk_d;
    always @(posedge clk) begin
        if (rst) begin
            tk <= 1'b0;
            pl <= 1'b1;
            pl_n <= 1'b0;
        end else begin
            tk <= tk_d;
            pl <= pl_d;
            pl_n <= ~pl_d;
        end
    end
`ifndef SYNTHESIS
    // the registered enables are their definitions (a simulation stops otherwise)
    reg past_rst = 1'b1;
    always @(posedge clk) past_rst <= rst;
    always @(posedge clk) begin
        if (!rst && !past_rst && (tk != (ce & room & prep_v) || pl != (~prep_v | tk) || pl_n == pl ||
                                  r_v_d != (ce ? (r_cont | (take & b_cont)) : r_v))) begin
            $display("spec_spangen: a registered enable differs from its definition (%m): an RTL bug");
            $fatal(1);
        end
    end
`endif

    wire [QW:0] bc_inc = {1'b0, bc} + {{QW{1'b0}}, 1'b1};
    wire unused_bc;
    assign unused_bc = &{1'b0, bc_inc[QW], head_lqm1_x[QW+1:QW], head_lqm2_x[QW+1:QW], t2, bc_diff_unused, b_last1};
    // presented beat
    reg [LANES-1:0] bv, bf, blst, bsel;
    reg [2*LANES-1:0] bo;
    always @(posedge clk) begin
        if (rst) begin
            r_v <= 1'b0;
            r_ntk <= 1'b0;
            bv <= {LANES{1'b0}};
        end else if (ce) begin
            r_v <= r_cont | (take & b_cont);
            r_ntk <= take ? b_cont2 : r_cont;
            bv <= rl | (take ? bl_v : {LANES{1'b0}});
        end
        if (ce) begin
            // the beat counter: 0 at a span's first beat (its flip-flops' synchronous reset), +1 per beat
            bc <= take ? {QW{1'b0}} : bc_inc[QW-1:0];
            r_last1_bc <= take ? 1'b0 : bc_reached;
            blst <= rl & rlast | (take ? ~rl & bl_last : {LANES{1'b0}});
            bsel <= ~rl;
            bf <= f_next;
            bo <= o_next;
            r_second <= take;
            r_inb <= take;
        end
        if (take) begin
            r_nt2 <= nb_carry ? prep_nlqm1 : prep_nlqm2;   // ~(lq + c - 2)
            r_end <= b_end;
            r_s <= s[LI-1:0];
        end
    end

    // ---- span parameters: set A (R's), set B (the span started in the presented beat; PACK) ------------------
    localparam PW = C_W + TSEL_W + SCALE_W + 2 * ANG_W + OW;
    wire [PW-1:0] prep_p = {prep_c, prep_tsel, prep_scale, prep_zeta0, prep_dzeta, prep_d3};
    reg [PW-1:0] pb_q;
    wire [PW-1:0] pa, pb;
    generate
        if (PACK != 0) begin : g_pab
            // set A takes R's parameters from set B when R started in the presented beat
            spec_ldreg #(.W(PW)) u_pa (.clk(clk), .ld(ce & r_v & r_inb), .d(pb), .q(pa));
            always @(posedge clk) if (take) pb_q <= prep_p;
            assign pb = pb_q;
        end else begin : g_pa
            always @(posedge clk) if (take) pb_q <= prep_p;
            assign pa = pb_q;
            assign pb = {PW{1'b0}};
        end
    endgenerate
    wire unused_pb;
    assign unused_pb = &{1'b0, pb, bsel, r_inb};

    // ---- per slot --------------------------------------------------------------------------------------------
    assign b_valid = bv;
    assign b_first = bf;
    assign b_last = blst;
    generate
        for (j = 0; j < LANES; j = j + 1) begin : g_slot
            wire [PW-1:0] p = (PACK != 0 && bsel[j]) ? pb : pa;
            wire [C_W-1:0] pc;
            wire [TSEL_W-1:0] ptsel;
            wire [SCALE_W-1:0] pscale;
            wire [ANG_W-1:0] pz, pd;
            wire [OW-1:0] pd3;
            assign {pc, ptsel, pscale, pz, pd, pd3} = p;
            wire [OW-1:0] d1 = {{(OW - ANG_W) {pd[ANG_W-1]}}, pd};
            wire [OW-1:0] d2 = {d1[OW-2:0], 1'b0};
            wire [1:0] o = (PACK != 0) ? bo[2*j +: 2] : j[1:0];
            assign b_c[j*C_W +: C_W] = pc;
            assign b_tsel[j*TSEL_W +: TSEL_W] = ptsel;
            assign b_scale[j*SCALE_W +: SCALE_W] = pscale;
            assign b_zeta0[j*ANG_W +: ANG_W] = pz;
            assign b_offs[j*OW +: OW] = (o == 2'd0) ? {OW{1'b0}} : (o == 2'd1) ? d1 : (o == 2'd2) ? d2 : pd3;
            assign b_step[j*OW +: OW] = d1 << SH;
        end
    endgenerate
endmodule
`default_nettype wire
