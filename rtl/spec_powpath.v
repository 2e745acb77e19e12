// spec_powpath - pow mode's value for multiplier 13 (spec_datapath with POW = 1, in spec_unit, spec_stream and
// spec_stream_seq; docs/pow.md): cos^n(angle) = exp2(-n L), L = -log2 cos(angle), on the patent's budget of two
// ROMs and two multipliers besides multiplier 13:
//   ROM 9 (the log table) read every pixel at register 8's angle, interpolated;
//   multiplier 11 multiplies L by n;
//   ROM 12 holds exp2 of minus y's fraction, shifted right by y's integer part (y = n L);
//   multiplier 13 multiplies by C.
// Not in the patent: ROM 9 is read per pixel instead of per span (addressed by the angle, not by n), and the
// angle does not go into multiplier 11 (docs/decisions.md).
//
// The log table. a = |angle|. Side 0 (a < 1 rad): t = a, L(t) = -log2 cos t. Side 1 (1 rad <= a <= K, K = pi/2 in
// the angle format, POW_K): t = K - a, L = -log2 sin t, which grows without bound as a nears pi/2. Each side has
// 2^POW_SEG_W segments: the octaves of t ([2^-(j+1), 2^-j) rad, j = 0 .. 2^POW_SEG_W - 2) and the interval below
// the last one; 2^POW_IDX_W equidistant entries each, so the relative spacing is that of a floating-point number
// and L's relative error stays small where L is tiny (near a = 0) and its growth is followed near pi/2. The entry
// comes from t normalized (a leading-one search and shift capped at the last octave), the interpolation fraction
// from the POW_FRAC bits after it. A word {shift, sign, |step|, value} holds L = value * 2^-(POW_XB + shift) and
// the step to the next entry in the same scale; the interpolated value is value +- round(|step| frac / 2^POW_FRAC).
// y = n value 2^(POW_YF - POW_XB - shift), floor, POW_YF fraction bits (a right shift by `shift`); y >= 2^POW_YI
// gives 0. ROM 12 at y's fraction: the nearest of 2^TBL_AW positions (INTERP = 0; the rounding may carry into the
// integer part) or the position below, interpolated (INTERP = 1, spec_interp); the value is shifted right by the
// integer part: the value (UQ1.TBL_FRAC) that spec_datapath's multiplier 13 multiplies by C. `zero` (the pixel is
// 0): a > K for n >= 1, or y >= 2^POW_YI; n = 0 gives 1.0 for every angle (y = 0).
//
// Every stage is registered and advances when `ce` is 1. Stages (P = PIPE: a register after each DSP block, and a
// second one on each interpolated table's word, as spec_datapath):
//   1-3    |angle| and d = K - |angle| (the inversion; the halves, d's high half for both carries in; the
//          choice), side and past from them, t = side ? d : |angle|
//   4..    normalization, one level a stage (shift by 2^(POW_SEG_W-1) .. 1; the last capped): ROM 9's address
//   +1     ROM 9 (its output register), then 1 + P registers on its word
//   +2+P   interpolation: |step| * frac (a DSP block), value +- its rounding (one carry chain)
//   +2+P   multiplier 11: its operands in registers of their own, the product (a DSP block)
//   +..    the shift by `shift`, two levels a stage; y and its high bits (overflow) registered
//   [+1    INTERP = 0: ROM 12's position rounded, with y's integer part, one carry chain]
//   +1     ROM 12, then 1 (+ P with INTERP = 1) registers on its word [+ 2 + P: spec_interp]
//   +..    the shift by y's integer part, two levels a stage (the last level after the last register, in front of
//          multiplier 13's input registers): `value` and `zero` at stage VS
// VS is spec_datapath's (with multiplier 13's 3 + P stages: Format::pow_latency, 23 clocks with the default
// parameters, 24 with INTERP = 1, 27 / 30 with PIPE); a VS that these stages do not add up to stops elaboration.
`timescale 1ns / 1ps
`default_nettype none
module spec_powpath #(
    parameter ANG_W = 32,
    parameter ANG_FRAC = 28,
    parameter N_W = 10,
    parameter TBL_AW = 12,
    parameter TBL_FRAC = 16,
    parameter INTERP = 0,
    parameter INTERP_FRAC = 10,
    parameter DELTA_W = 10,
    parameter POW_SEG_W = 3,
    parameter POW_IDX_W = 6,
    parameter POW_FRAC = 10,
    parameter POW_VAL_W = 16,
    parameter POW_DLT_W = 14,
    parameter POW_SH_W = 5,
    parameter POW_XB = 12,
    parameter POW_YF = 18,
    parameter POW_YI = 5,
    parameter POW_K = 421657428,
    parameter PIPE = 0,
    parameter SIDE = 1,       // 1: n travels beside each pixel; 0: the caller holds it for a span (spec_datapath)
    parameter VS = 20,        // the stage of `value` and `zero` (spec_datapath's; checked)
    parameter ROM9_FILE = "",
    parameter ROM12_FILE = ""
) (
    input  wire                  clk,
    input  wire                  ce,
    input  wire [ANG_W-1:0]      angle,   // register 8
    input  wire [N_W-1:0]        n,       // register 4
    output wire [TBL_FRAC:0]     value,   // 2^-y, UQ1.TBL_FRAC, at stage VS
    output wire                  zero     // the pixel is 0, at stage VS
);
    localparam P = (PIPE != 0) ? 1 : 0;
    localparam H = ANG_W / 2;
    localparam NS = 1 << POW_SEG_W;                  // segments per side
    localparam ALOW = ANG_FRAC - 1 - POW_IDX_W - POW_FRAC;   // the fraction's LSB in normalized t (>= 0)
    localparam TLOW = (ALOW > NS - 2) ? ALOW - (NS - 2) : 0;  // the lowest bit of t that can reach it
    localparam TW = ANG_FRAC - TLOW;                  // bits of t kept
    localparam A9 = 1 + POW_SEG_W + POW_IDX_W;        // ROM 9's address
    localparam D9 = POW_SH_W + 1 + POW_DLT_W + POW_VAL_W;   // ROM 9's word
    localparam PW = N_W + POW_VAL_W + POW_YF - POW_XB;      // n * value, aligned to y's fraction
    localparam YW = POW_YI + POW_YF;                  // y
    localparam SHS = (POW_SH_W + 1) / 2;              // the alignment's stages
    localparam TBL_DW = TBL_FRAC + 1;
    localparam WORD12 = TBL_DW + ((INTERP != 0) ? DELTA_W : 0);
    localparam FR12 = (INTERP != 0) ? INTERP_FRAC : 1;
    localparam IW = POW_YI + 1;                       // y's integer part after the rounding's carry
    localparam BSS = POW_YI / 2;                      // the shift by it: stages before multiplier 13
    // stage numbers: where each value is registered (Format::pow_latency)
    localparam S_T = 3;
    localparam S_N = S_T + POW_SEG_W;
    localparam S_W9 = S_N + 2 + P;
    localparam S_I2 = S_W9 + 2 + P;
    localparam S_M1 = S_I2 + 2 + P;
    localparam S_A = S_M1 + SHS;
    localparam S_R = S_A + ((INTERP != 0) ? 0 : 1);
    localparam S_W12 = S_R + 2 + ((INTERP != 0) ? P : 0);
    localparam S_IB = S_W12 + ((INTERP != 0) ? 2 + P : 0);
    generate
        if (S_IB + BSS != VS) begin : g_vs
            spec_parameter_error_powpath_VS_is_not_its_stages check_spec_datapath_VS_POW ();
        end
    endgenerate

    // ---- stages 1-3: |angle|, d = K - |angle|, side, past, t --------------------------------------------------
    // |angle| = (angle ^ sign) + sign, and d = K - |angle| = ~((angle ^ sign) + ~K + sign): both sums have the
    // stage-1 registers and constants as operands and the sign as carry in, so no inverter stands in front of a
    // carry chain (d's inversion is the sum's own LUT). Stage 1 inverts; stage 2 adds the low halves, |angle|'s
    // high half (its carry in known from stage 1) and d's high half for both carries in (carry select); stage 3
    // picks d's high half by the low half's carry and t = side ? d : |angle| (two LUT levels, no carry chain).
    localparam [ANG_W-1:0] NK = ~POW_K;
    reg [ANG_W-1:0] ang_inv;
    reg ang_neg, hi_cin;
    always @(posedge clk) begin
        if (ce) begin
            ang_inv <= angle ^ {ANG_W{angle[ANG_W-1]}};
            ang_neg <= angle[ANG_W-1];
            hi_cin <= angle[ANG_W-1] & (angle[H-1:0] == {H{1'b0}});
        end
    end
    wire [H-1:0] mag_lo_s;
    wire mag_lo_co_unused;
    spec_add #(.W(H), .CO(0)) u_mag_lo (
        .a(ang_inv[H-1:0]), .b({H{1'b0}}), .cin(ang_neg), .p(ang_inv[H-1]), .sum(mag_lo_s), .cout(mag_lo_co_unused)
    );
    // the high half below its top bit (ang_inv's top bit is always 0), whose carry out is |angle|'s top bit
    wire [ANG_W-H-2:0] mag_hi_s;
    wire mag_hi_co;
    spec_add #(.W(ANG_W - H - 1)) u_mag_hi (
        .a(ang_inv[ANG_W-2:H]), .b({(ANG_W - H - 1) {1'b0}}), .cin(hi_cin), .p(ang_inv[H]), .sum(mag_hi_s),
        .cout(mag_hi_co)
    );
    wire [H-1:0] s_lo_s;
    wire s_lo_co;
    spec_add #(.W(H)) u_s_lo (
        .a(ang_inv[H-1:0]), .b(NK[H-1:0]), .cin(ang_neg), .p(ang_inv[H-1]), .sum(s_lo_s), .cout(s_lo_co)
    );
    wire [ANG_W-H-1:0] s_hi0_s, s_hi1_s;
    wire s_hi0_co_unused, s_hi1_co_unused;
    spec_add #(.W(ANG_W - H), .CO(0)) u_s_hi0 (
        .a(ang_inv[ANG_W-1:H]), .b(NK[ANG_W-1:H]), .cin(1'b0), .p(ang_inv[H]), .sum(s_hi0_s), .cout(s_hi0_co_unused)
    );
    spec_add #(.W(ANG_W - H), .CO(0)) u_s_hi1 (
        .a(ang_inv[ANG_W-1:H]), .b(NK[ANG_W-1:H]), .cin(1'b1), .p(ang_inv[H]), .sum(s_hi1_s), .cout(s_hi1_co_unused)
    );
    reg [ANG_W-1:0] mag;
    reg [H-1:0] s_lo;
    reg s_c;
    reg [ANG_W-H-1:0] s_hi0, s_hi1;
    always @(posedge clk) begin
        if (ce) begin
            mag <= {mag_hi_co, mag_hi_s, mag_lo_s};
            s_lo <= s_lo_s;
            s_c <= s_lo_co;
            s_hi0 <= s_hi0_s;
            s_hi1 <= s_hi1_s;
        end
    end
    wire [ANG_W-1:0] d = ~{s_c ? s_hi1 : s_hi0, s_lo};
    wire side_w = |mag[ANG_W-1:ANG_FRAC];          // |angle| >= 1 rad
    reg side3, past3;
    reg [TW-1:0] t3;
    always @(posedge clk) begin
        if (ce) begin
            side3 <= side_w;
            past3 <= d[ANG_W-1];                    // K - |angle| < 0
            t3 <= side_w ? d[ANG_FRAC-1:TLOW] : mag[ANG_FRAC-1:TLOW];
        end
    end
    wire unused_front;
    generate
        if (TLOW > 0) begin : g_tlow
            assign unused_front = &{1'b0, mag[TLOW-1:0], d[TLOW-1:0], mag_lo_co_unused, s_hi0_co_unused,
                                     s_hi1_co_unused, ang_inv[ANG_W-1]};
        end else begin : g_notlow
            assign unused_front = &{1'b0, mag_lo_co_unused, s_hi0_co_unused, s_hi1_co_unused, ang_inv[ANG_W-1]};
        end
    endgenerate

    // n (and whether it is 0) beside the pixel: SIDE = 0 reads the caller's register as it is
    localparam NZ_D = S_T - 1;
    wire [N_W-1:0] n_t;
    spec_delay #(.W(N_W), .N((SIDE != 0) ? NZ_D : 0)) u_n_t (.clk(clk), .ce(ce), .d(n), .q(n_t));
    reg nz3;
    always @(posedge clk) if (ce) nz3 <= |n_t;
    // the pixel is 0 past K, for n >= 1 (a register of its own: stage 4)
    reg zero_a;
    always @(posedge clk) if (ce) zero_a <= past3 & nz3;

    // ---- stages 4 .. 3 + POW_SEG_W: normalization -----------------------------------------------------------
    // Level k shifts t left by 2^k when its top 2^k bits are 0; the last level (1) not when the shift is already
    // NS - 2 (t below the last octave: the interval under it keeps the last octave's scale). The segment is the
    // shift, NS - 1 when the top bit is still 0 after the cap.
    // level k's input at [k*TW +: TW] (shift accumulated so far at [k*POW_SEG_W +: POW_SEG_W]); level POW_SEG_W: out
    wire [(POW_SEG_W+1)*TW-1:0] nx;
    wire [(POW_SEG_W+1)*POW_SEG_W-1:0] nacc;
    wire [POW_SEG_W:0] nside;
    assign nx[TW-1:0] = t3;
    assign nacc[POW_SEG_W-1:0] = {POW_SEG_W{1'b0}};
    assign nside[0] = side3;
    genvar k;
    generate
        for (k = 0; k < POW_SEG_W; k = k + 1) begin : g_norm
            localparam integer AMT = 1 << (POW_SEG_W - 1 - k);
            localparam [POW_SEG_W-1:0] CAP = NS - 2;
            localparam [POW_SEG_W-1:0] AMTV = AMT[POW_SEG_W-1:0];
            wire [TW-1:0] x = nx[k*TW +: TW];
            wire [POW_SEG_W-1:0] acc = nacc[k*POW_SEG_W +: POW_SEG_W];
            wire top0 = ~|x[TW-1:TW-AMT];
            wire go = top0 & ((k != POW_SEG_W - 1) || (acc != CAP));
            wire [TW-1:0] x_d = go ? {x[TW-AMT-1:0], {AMT{1'b0}}} : x;
            wire [POW_SEG_W-1:0] acc_d = acc | (go ? AMTV : {POW_SEG_W{1'b0}});
            reg [TW-1:0] x_q;
            reg [POW_SEG_W-1:0] acc_q;
            reg side_q;
            always @(posedge clk) begin
                if (ce) begin
                    x_q <= x_d;
                    // after the last level: t below the last octave (top bit still 0) is segment NS - 1
                    acc_q <= (k == POW_SEG_W - 1) ? (acc_d | {{(POW_SEG_W - 1) {1'b0}}, ~x_d[TW-1]}) : acc_d;
                    side_q <= nside[k];
                end
            end
            assign nx[(k+1)*TW +: TW] = x_q;
            assign nacc[(k+1)*POW_SEG_W +: POW_SEG_W] = acc_q;
            assign nside[k+1] = side_q;
        end
    endgenerate
    wire [TW-1:0] tn = nx[POW_SEG_W*TW +: TW];
    wire [A9-1:0] addr9 = {nside[POW_SEG_W], nacc[POW_SEG_W*POW_SEG_W +: POW_SEG_W], tn[TW-2:TW-1-POW_IDX_W]};
    wire [POW_FRAC-1:0] frac9;
    generate
        if (TW - 1 - POW_IDX_W - POW_FRAC >= 0) begin : g_frac_in
            assign frac9 = tn[TW-2-POW_IDX_W:TW-1-POW_IDX_W-POW_FRAC];
            if (TW - 1 - POW_IDX_W - POW_FRAC > 0) begin : g_low
                wire unused_tlow;
                assign unused_tlow = &{1'b0, tn[TW-2-POW_IDX_W-POW_FRAC:0]};
            end
        end else begin : g_frac_pad
            assign frac9 = {tn[TW-2-POW_IDX_W:0], {(POW_FRAC - (TW - 1 - POW_IDX_W)) {1'b0}}};
        end
    endgenerate
    wire unused_top = tn[TW-1];

    // ---- ROM 9 (the log table) and its word register(s) -------------------------------------------------------
    wire [D9-1:0] word9_r;
    spec_rom #(
        .AW(A9), .DW(D9), .INIT_FILE(ROM9_FILE), .HEADER(9), .POW(1), .H0(ANG_FRAC), .H1(POW_K), .H2(POW_SEG_W),
        .H3(POW_IDX_W), .H4(POW_VAL_W), .H5(POW_DLT_W), .H6(POW_SH_W), .H7(POW_XB)
    ) u_rom9 (
        .clk(clk), .en(ce), .addr(addr9), .data(word9_r)
    );
    // the block RAM's output register, then a plain register (two with PIPE: one for the DSP block's input)
    wire [D9-1:0] word9;
    spec_delay #(.W(D9), .N(1 + P)) u_word9 (.clk(clk), .ce(ce), .d(word9_r), .q(word9));
    wire [POW_FRAC-1:0] frac_w;
    spec_delay #(.W(POW_FRAC), .N(2 + P)) u_frac9 (.clk(clk), .ce(ce), .d(frac9), .q(frac_w));
    wire [POW_VAL_W-1:0] w_val = word9[POW_VAL_W-1:0];
    wire [POW_DLT_W-1:0] w_dlt = word9[POW_VAL_W+POW_DLT_W-1:POW_VAL_W];
    wire w_neg = word9[POW_VAL_W+POW_DLT_W];
    wire [POW_SH_W-1:0] w_sh = word9[D9-1:D9-POW_SH_W];

    // ---- interpolation: value +- round(|step| frac / 2^POW_FRAC) -----------------------------------------------
    localparam IPW = POW_DLT_W + POW_FRAC;
    reg [IPW-1:0] ip_prod;
    reg [POW_VAL_W-1:0] ip_val;
    reg ip_neg;
    reg [POW_SH_W-1:0] ip_sh;
    always @(posedge clk) begin
        if (ce) begin
            ip_prod <= {{POW_FRAC{1'b0}}, w_dlt} * {{POW_DLT_W{1'b0}}, frac_w};
            ip_val <= w_val;
            ip_neg <= w_neg;
            ip_sh <= w_sh;
        end
    end
    // the rounded step's bits, inverted for a negative step (v - r = v + ~r_hi + ~r[F-1], as spec_interp), chosen
    // before the DSP_FF register, so that the next stage is one carry chain
    wire [POW_DLT_W:0] ip_x_d = ip_prod[IPW-1:POW_FRAC-1] ^ {(POW_DLT_W + 1) {ip_neg}};
    wire [POW_DLT_W:0] ip_x;
    wire [POW_VAL_W-1:0] ip_val_q;
    wire ip_neg_q;
    wire [POW_SH_W-1:0] ip_sh_q;
    spec_delay #(.W(POW_DLT_W + 1 + POW_VAL_W + 1 + POW_SH_W), .N(P)) u_ip_ff (
        .clk(clk), .ce(ce), .d({ip_x_d, ip_val, ip_neg, ip_sh}), .q({ip_x, ip_val_q, ip_neg_q, ip_sh_q})
    );
    localparam XV = (POW_VAL_W > POW_DLT_W) ? POW_VAL_W : POW_DLT_W;
    wire [XV-1:0] ip_b = {{(XV - POW_DLT_W) {ip_neg_q}}, ip_x[POW_DLT_W:1]};
    wire [XV-1:0] ip_a = {{(XV - POW_VAL_W) {1'b0}}, ip_val_q};
    wire [XV-1:0] ip_sum;
    wire ip_co_unused;
    spec_add #(.W(XV), .CO(0)) u_ip_add (.a(ip_a), .b(ip_b), .cin(ip_x[0]), .p(ip_a[0]), .sum(ip_sum), .cout(ip_co_unused));
    reg [POW_VAL_W-1:0] lval;
    reg [POW_SH_W-1:0] lsh;
    always @(posedge clk) begin
        if (ce) begin
            lval <= ip_sum[POW_VAL_W-1:0];
            lsh <= ip_sh_q;
        end
    end
    wire unused_ip;
    assign unused_ip = &{1'b0, ip_sum, ip_co_unused, ip_prod[POW_FRAC-2:0], ip_neg_q};

    // ---- multiplier 11: n * value (operands in registers of their own, then the DSP block's product) ----------
    wire [N_W-1:0] n_m;
    spec_delay #(.W(N_W), .N((SIDE != 0) ? S_I2 - NZ_D : 0)) u_n_m (.clk(clk), .ce(ce), .d(n_t), .q(n_m));
    reg [POW_VAL_W-1:0] op_v;
    reg [N_W-1:0] op_n;
    reg [POW_SH_W-1:0] op_sh, m_sh_d;
    reg [N_W+POW_VAL_W-1:0] m_prod_d;
    always @(posedge clk) begin
        if (ce) begin
            op_v <= lval;
            op_n <= n_m;
            op_sh <= lsh;
            m_prod_d <= {{N_W{1'b0}}, op_v} * {{POW_VAL_W{1'b0}}, op_n};
            m_sh_d <= op_sh;
        end
    end
    wire [N_W+POW_VAL_W-1:0] m_prod;
    wire [POW_SH_W-1:0] m_sh;
    spec_delay #(.W(N_W + POW_VAL_W + POW_SH_W), .N(P)) u_m_ff (
        .clk(clk), .ce(ce), .d({m_prod_d, m_sh_d}), .q({m_prod, m_sh})
    );

    // ---- the alignment: y = (n value 2^(POW_YF - POW_XB)) >> shift, two levels a stage ------------------------
    wire [PW-1:0] al_in;
    generate
        if (POW_YF > POW_XB) begin : g_pre
            assign al_in = {m_prod, {(POW_YF - POW_XB) {1'b0}}};
        end else begin : g_nopre
            assign al_in = m_prod;
        end
    endgenerate
    wire [PW-1:0] al_out;
    wire [POW_SH_W-1:0] al_sh_unused;
    spec_shr #(.W(PW), .S(POW_SH_W), .LAST_COMB(0)) u_align (
        .clk(clk), .ce(ce), .d(al_in), .amt(m_sh), .q(al_out), .q_amt(al_sh_unused)
    );
    wire [YW-1:0] y = al_out[YW-1:0];
    // y's bits above its format (overflow: the pixel is 0), OR-ed a stage later
    wire ovf_a;
    generate
        if (PW > YW) begin : g_ovf
            reg ovf_q;
            always @(posedge clk) if (ce) ovf_q <= |al_out[PW-1:YW];
            assign ovf_a = ovf_q;
        end else begin : g_noovf
            assign ovf_a = 1'b0;
        end
    endgenerate
    wire unused_alsh = &{1'b0, al_sh_unused};

    // ---- ROM 12's position and y's integer part ----------------------------------------------------------------
    wire [TBL_AW-1:0] pos12;
    wire [FR12-1:0] fr12;
    wire [IW-1:0] yint_r;   // at stage S_R
    generate
        if (INTERP != 0) begin : g_pos_interp
            assign pos12 = y[POW_YF-1:POW_YF-TBL_AW];
            assign fr12 = y[POW_YF-TBL_AW-1:POW_YF-TBL_AW-INTERP_FRAC];
            assign yint_r = {1'b0, y[YW-1:POW_YF]};
            if (POW_YF - TBL_AW - INTERP_FRAC > 0) begin : g_low
                wire unused_ylow;
                assign unused_ylow = &{1'b0, y[POW_YF-TBL_AW-INTERP_FRAC-1:0]};
            end
        end else begin : g_pos_round
            // the nearest position: {integer part, position} + the bit below, one carry chain whose carry out is
            // the integer part's top bit
            wire [POW_YI+TBL_AW-1:0] r_s;
            wire r_co;
            spec_add #(.W(POW_YI + TBL_AW)) u_round (
                .a(y[YW-1:POW_YF-TBL_AW]), .b({(POW_YI + TBL_AW) {1'b0}}), .cin(y[POW_YF-TBL_AW-1]),
                .p(y[POW_YF-TBL_AW]), .sum(r_s), .cout(r_co)
            );
            reg [TBL_AW-1:0] pos_q;
            reg [IW-1:0] yint_q;
            always @(posedge clk) begin
                if (ce) begin
                    pos_q <= r_s[TBL_AW-1:0];
                    yint_q <= {r_co, r_s[POW_YI+TBL_AW-1:TBL_AW]};
                end
            end
            assign pos12 = pos_q;
            assign fr12 = 1'b0;
            assign yint_r = yint_q;
            if (POW_YF - TBL_AW - 1 > 0) begin : g_low
                wire unused_ylow;
                assign unused_ylow = &{1'b0, y[POW_YF-TBL_AW-2:0]};
            end
        end
    endgenerate

    // ---- ROM 12 (exp2 of minus y's fraction), [interpolation] ---------------------------------------------------
    wire [WORD12-1:0] word12_r;
    spec_rom #(
        .AW(TBL_AW), .DW(WORD12), .INIT_FILE(ROM12_FILE), .HEADER(12), .POW(1), .H0(TBL_AW), .H1(TBL_FRAC),
        .H2((INTERP != 0) ? 1 : 0), .H3((INTERP != 0) ? DELTA_W : -1)
    ) u_rom12 (
        .clk(clk), .en(ce), .addr(pos12), .data(word12_r)
    );
    localparam WR12 = ((INTERP != 0) && (PIPE != 0)) ? 2 : 1;
    wire [TBL_DW-1:0] b_word;
    spec_delay #(.W(TBL_DW), .N(WR12)) u_word12 (.clk(clk), .ce(ce), .d(word12_r[TBL_DW-1:0]), .q(b_word));
    wire [TBL_DW-1:0] b_val;   // at stage S_IB
    generate
        if (INTERP != 0) begin : g_interp12
            wire [FR12-1:0] fr_w;
            spec_delay #(.W(FR12), .N(1 + WR12)) u_fr12 (.clk(clk), .ce(ce), .d(fr12), .q(fr_w));
            wire [DELTA_W-1:0] b_delta;
            spec_delay #(.W(DELTA_W), .N(WR12)) u_delta12 (
                .clk(clk), .ce(ce), .d(word12_r[WORD12-1:TBL_DW]), .q(b_delta)
            );
            spec_interp #(.TBL_DW(TBL_DW), .DELTA_W(DELTA_W), .INTERP_FRAC(INTERP_FRAC), .DSP_FF(P)) u_interp12 (
                .clk(clk), .ce(ce), .v(b_word), .delta(b_delta), .frac(fr_w), .value(b_val)
            );
        end else begin : g_plain12
            assign b_val = b_word;
            wire unused_fr12 = &{1'b0, fr12};
        end
    endgenerate

    // ---- the shift by y's integer part (two levels a stage; the last level in front of multiplier 13) -----------
    wire [IW-1:0] yint_b;
    spec_delay #(.W(IW), .N(S_IB - S_R)) u_yint (.clk(clk), .ce(ce), .d(yint_r), .q(yint_b));
    wire [TBL_DW-1:0] bs_q;
    wire [POW_YI-1:0] bs_amt_unused;
    spec_shr #(.W(TBL_DW), .S(POW_YI), .LAST_COMB(1)) u_bshift (
        .clk(clk), .ce(ce), .d(b_val), .amt(yint_b[POW_YI-1:0]), .q(bs_q), .q_amt(bs_amt_unused)
    );
    wire unused_bs = &{1'b0, bs_amt_unused};
    // the integer part's top bit (y's integer part, after the rounding's carry, reaching 2^POW_YI) beside it
    wire yint_big;
    spec_delay #(.W(1), .N(BSS)) u_big (.clk(clk), .ce(ce), .d(yint_b[IW-1]), .q(yint_big));

    // ---- zero: past K (n >= 1), y overflowing its format, or its integer part reaching 2^POW_YI ---------------
    wire zero_a_m, ovf_m;
    spec_delay #(.W(1), .N(VS - (S_T + 1))) u_zero_a (.clk(clk), .ce(ce), .d(zero_a), .q(zero_a_m));
    spec_delay #(.W(1), .N(VS - (S_A + 1))) u_ovf (.clk(clk), .ce(ce), .d(ovf_a), .q(ovf_m));
    assign zero = zero_a_m | ovf_m | yint_big;
    assign value = bs_q;
endmodule
`default_nettype wire
