// spec_setup_efu - spec_setup's table unit (rom/gen/setup_program.cpp, setup_efu): 1/sqrt(a), 1/a, atan(|a|)/|a|
// and log2(a), each from a table of 2^TAB_T intervals read at two neighbouring words and interpolated linearly on
// TAB_R bits of the position, the result times 2^scale, rounded once. Defined for every word: 1/sqrt of zero or a
// negative value is 0, 1/0 is 0, atan(x)/x reads |x| >= 1 as 1, log2 of zero or a negative value is -1024.
// The five tables share one ROM (EFU_FILE, setuprom: table * 2^TAB_T + index; the words at the intervals' end
// are the parameter END). Pipelined, a new operation every clock:
//   1  the table, the position (from the mantissa; atan: from |a| in fixed point), the result's scale
//   2  the ROM's two reads (index, index + 1)
//   3  the end word where an index passes the table
//   4  (next - this) * fraction
//   5  the interpolated word; log2: the exponent added
//   6-8  spec_setup_fpround
`timescale 1ns / 1ps
`default_nettype none
module spec_setup_efu #(
    parameter FM = 22,
    parameter FE = 8,
    parameter TAB_T = 10,
    parameter TAB_R = 12,
    parameter TAB_F = 27,
    parameter SCALE_W = 4,
    parameter [5*(TAB_F+1)-1:0] END = 0,
    parameter EFU_FILE = ""
) (
    input  wire               clk,
    input  wire [FE+FM:0]     a,
    input  wire [1:0]         op,      // 0 1/sqrt, 1 1/x, 2 atan(x)/x, 3 log2
    input  wire [SCALE_W-1:0] scale,
    output wire [FE+FM:0]     r
);
    localparam TW = TAB_F + 1;
    localparam KW = FE + 6;
    localparam PW = TAB_T + TAB_R;                 // position bits
    localparam XW = TAB_F + FE + 2;                // |e * 2^TAB_F + v|
    localparam [PW:0] ONE = {1'b1, {PW{1'b0}}};

    // ---- 1: table and position
    wire sa = a[FE+FM];
    wire signed [FE-1:0] ea = a[FE+FM-1:FM];
    wire [FM-1:0] ma = a[FM-1:0];
    wire az = ~|ma;
    wire odd = ea[0];
    wire [PW-1:0] mpos = {ma[FM-2:0], 1'b0} >> (FM - PW);      // the mantissa below its leading one
    // atan: |a| * 2^PW = m >> ((FM - 1) - PW - e), e < 0 (e >= 0: 1)
    wire signed [FE+1:0] ash = (FM - PW) - $signed({ea[FE-1], ea});   // right shift of {m, 0}
    wire [FM:0] am = {ma, 1'b0};
    wire [FM:0] aq = (ash >= FM + 1) ? {(FM + 1) {1'b0}} : am >> ash[FE:0];
    wire [PW:0] apos = ea >= 0 ? ONE : aq[PW:0];
    wire signed [KW-1:0] sc = $signed({{(KW - SCALE_W) {scale[SCALE_W-1]}}, scale});
    wire signed [KW-1:0] eax = $signed({{(KW - FE) {ea[FE-1]}}, ea});
    wire signed [KW-1:0] ehalf = (eax - $signed({{(KW - 1) {1'b0}}, odd})) >>> 1;   // (e - odd) / 2, exact
    reg [2:0] s1_t;
    reg [PW:0] s1_pos;
    reg signed [KW-1:0] s1_k;
    reg s1_s, s1_zero, s1_log2, s1_lz;
    reg signed [FE-1:0] s1_e;
    always @(posedge clk) begin
        s1_zero <= 1'b0;
        s1_lz <= 1'b0;
        s1_s <= 1'b0;
        s1_pos <= {1'b0, mpos};
        s1_e <= ea;
        s1_log2 <= op == 2'd3;
        case (op)
            2'd0: begin   // 1/sqrt: [1, 2) or [2, 4) by the exponent's parity
                s1_t <= {2'b00, odd};
                s1_k <= sc - TAB_F - ehalf;
                s1_zero <= az | sa;
            end
            2'd1: begin
                s1_t <= 3'd2;
                s1_k <= sc - TAB_F - eax;
                s1_s <= sa;
                s1_zero <= az;
            end
            2'd2: begin
                s1_t <= 3'd3;
                s1_pos <= az ? {(PW + 1) {1'b0}} : apos;
                s1_k <= sc - TAB_F;
            end
            default: begin
                s1_t <= 3'd4;
                s1_k <= sc - TAB_F;
                s1_lz <= az | sa;
            end
        endcase
    end

    // ---- 2: the ROM, two reads
    reg [TW-1:0] rom[0:5*(1<<TAB_T)-1];
    initial $readmemh(EFU_FILE, rom);
    spec_setup_imgcheck #(.FILE(EFU_FILE), .WORDS(5 << TAB_T), .DIGITS((TW + 3) / 4)) u_check ();
    wire [TAB_T-1:0] ia = s1_pos[PW-1:TAB_R];
    wire [TAB_T-1:0] ib = ia + 1'b1;

    reg [TW-1:0] s2_a, s2_b;
    reg s2_enda, s2_endb;
    reg [2:0] s2_t;
    reg [TAB_R-1:0] s2_f;
    reg signed [KW-1:0] s2_k;
    reg s2_s, s2_zero, s2_log2, s2_lz;
    reg signed [FE-1:0] s2_e;
    always @(posedge clk) begin
        s2_a <= rom[{s1_t, ia}];
        s2_b <= rom[{s1_t, ib}];
        s2_enda <= s1_pos[PW];                       // atan at 1: the end word
        s2_endb <= s1_pos[PW] | (&ia);               // the last interval: its end word
        s2_t <= s1_t;
        s2_f <= s1_pos[TAB_R-1:0];
        s2_k <= s1_k;
        s2_s <= s1_s;
        s2_zero <= s1_zero;
        s2_log2 <= s1_log2;
        s2_lz <= s1_lz;
        s2_e <= s1_e;
    end

    // ---- 3: the end word
    wire [TW-1:0] endw = END[s2_t * TW +: TW];
    reg [TW-1:0] s3_t0, s3_t1;
    reg [TAB_R-1:0] s3_f;
    reg signed [KW-1:0] s3_k;
    reg s3_s, s3_zero, s3_log2, s3_lz;
    reg signed [FE-1:0] s3_e;
    always @(posedge clk) begin
        s3_t0 <= s2_enda ? endw : s2_a;
        s3_t1 <= s2_endb ? endw : s2_b;
        s3_f <= s2_f;
        s3_k <= s2_k;
        s3_s <= s2_s;
        s3_zero <= s2_zero;
        s3_log2 <= s2_log2;
        s3_lz <= s2_lz;
        s3_e <= s2_e;
    end

    // ---- 4: (next - this) * fraction; |next - this| < 1.5 * 2^(TAB_F - TAB_T) (the tables' slopes are below 1.5)
    localparam DLW = TAB_F - TAB_T + 2;
    wire signed [TW:0] dlt_full = $signed({1'b0, s3_t1}) - $signed({1'b0, s3_t0});
    wire signed [DLW-1:0] dlt = dlt_full[DLW-1:0];
    reg signed [TW+TAB_R+1:0] s4_p;
    reg [TW-1:0] s4_t0;
    reg signed [KW-1:0] s4_k;
    reg s4_s, s4_zero, s4_log2, s4_lz;
    reg signed [FE-1:0] s4_e;
    always @(posedge clk) begin
        s4_p <= $signed({{(TW + 2 - DLW) {dlt[DLW-1]}}, dlt}) * $signed({1'b0, s3_f});
        s4_t0 <= s3_t0;
        s4_k <= s3_k;
        s4_s <= s3_s;
        s4_zero <= s3_zero;
        s4_log2 <= s3_log2;
        s4_lz <= s3_lz;
        s4_e <= s3_e;
    end

    // ---- 5: the interpolated word (rounded half up: the floor of p / 2^R + 1/2); log2: e * 2^TAB_F + it
    wire signed [TW+TAB_R+1:0] pr = s4_p + (1 <<< (TAB_R - 1));
    wire signed [TW+TAB_R+1:0] prs = pr >>> TAB_R;
    wire signed [TW+1:0] step = prs[TW+1:0];
    wire signed [TW+1:0] v = $signed({2'b00, s4_t0}) + step;
    wire signed [XW:0] lsum = ($signed({{(XW - FE + 1) {s4_e[FE-1]}}, s4_e}) <<< TAB_F) + $signed({{(XW - TW - 1) {1'b0}}, v});
    reg s5_s;
    reg [XW-1:0] s5_x;
    reg signed [KW-1:0] s5_k;
    always @(posedge clk) begin
        if (s4_zero) begin
            s5_x <= {XW{1'b0}};
            s5_s <= 1'b0;
            s5_k <= s4_k;
        end else if (s4_lz) begin   // log2 of zero or a negative value: -1024
            s5_x <= 1024;
            s5_s <= 1'b1;
            s5_k <= s4_k + TAB_F;
        end else if (s4_log2) begin
            s5_x <= lsum[XW] ? -lsum[XW-1:0] : lsum[XW-1:0];
            s5_s <= lsum[XW];
            s5_k <= s4_k;
        end else begin
            s5_x <= {{(XW - TW) {1'b0}}, v[TW-1:0]};
            s5_s <= s4_s;
            s5_k <= s4_k;
        end
    end
    spec_setup_fpround #(.FM(FM), .FE(FE), .XW(XW), .KW(KW)) u_round (
        .clk(clk), .s(s5_s), .x(s5_x), .k(s5_k), .r(r)
    );
    wire unused;
    assign unused = &{1'b0, aq, prs, step[TW+1], v[TW+1:TW], pr[TAB_R-1:0], dlt_full[TW:DLW]};
endmodule
`default_nettype wire
