// setup_format.h - the arithmetic and the machine of spec_setup (the patent's "external device" in hardware):
// number format, table sizes, thresholds, and the functional units the schedule runs on. One set of
// definitions for the generator (setuprom: tables, microcode, rom/setup_params.{vh,h}), the bit-exact model
// (sim/setup/setup_model) and, through the generated header, the RTL (rtl/spec_setup*.v). docs/setup.md explains
// every choice and what it was measured against.
//
// The setup is a dataflow program of floating-point operations (rom/gen/setup_program.h) on the products of the
// 16-bit span ends, which an exact integer front end forms first; a modulo schedule (rom/gen/setup_sched.h) maps
// it onto a machine of pipelined units, several spans in flight.
#pragma once

#include <stdexcept>
#include <string>

#include "setup_fp.h"

namespace spec {

// The functional units of the machine (rtl/spec_setup_machine.v). A configuration sets how many of each.
struct SetupMachine {   // the defaults are the ecp5 configuration's
    int idot = 1;    // exact integer dot / cross products of the span ends, and their conversion to floating point
    int mul = 4;     // floating-point multipliers
    int add = 3;     // floating-point adders
    int efu = 1;     // tables: 1/sqrt, 1/x, atan(x)/x, log2
    int misc = 2;    // compare, select, min, max
    int max_ii = 0;  // 0: the least II the schedule reaches; else the schedule must reach this II or less
};

struct SetupFormat {
    // ---- interface (the span-ends beat) ----
    int vec_w = 16;      // end vectors N1, N2, H1, H2: three two's complement components each
    int vec_frac = 14;   //   value = code / 2^vec_frac: Q1.14, [-2, 2); any length, not zero
    int str_w = 16;      // strength Is*ks: unsigned, value = code / 2^str_frac
    int str_frac = 15;   //   UQ1.15, [0, 2)

    // ---- floating point ----
    FpFmt fp;            // mantissa 22 bits (the defaults in setup_fp.h are the ecp5 configuration's)

    // ---- the EFU's tables: 1/sqrt(x) on [1, 2) and [2, 4), 1/x on [1, 2), atan(x)/x on [0, 1], log2(x) on [1, 2);
    // 2^tab_t intervals each, words with tab_f fraction bits, read with linear interpolation on tab_r bits ----
    int tab_t = 10;
    int tab_r = 12;
    int tab_f = 26;

    // ---- the finish stage: angles and C in fixed point ----
    int zf = 30;         // fraction bits of the angles before rounding to the descriptor's
    int lf = 24;         // fraction bits of p = -log2 C
    int exp_t = 9;       // exp2 table: 2^-x on [0, 1), 2^exp_t intervals
    int exp_r = 12;
    int exp_f = 24;

    // ---- degenerate spans ----
    int flat_log2 = -20;     // gamma below 2^flat_log2 rad (the patent's gamma): the span is flat
    double opp_eps = 1e-6;   // 1 + N1.N2 below it: "opposite normals" (the host's threshold)
    int a_tol_log2 = -20;    // midpoint rule: an amplitude up to 1 + 2^a_tol_log2 is a sinusoid (rounding)

    SetupMachine mach;
    std::string name = "ecp5";

    int word_w() const { return fp.w(); }

    // Throws std::invalid_argument with a one-line reason when the combination is not supported.
    void validate() const {
        auto need = [](bool ok, const char* what) {
            if (!ok) throw std::invalid_argument(std::string("setup format: ") + what);
        };
        need(vec_w >= 8 && vec_w <= 16, "vec_w must be 8..16 (a 16-bit slot of the span-ends beat each)");
        need(vec_frac >= 1 && vec_frac <= vec_w - 1, "vec_frac must be 1..vec_w-1");
        need(str_w >= 4 && str_w <= 16 && str_frac >= 0 && str_frac <= str_w, "bad strength format (at most 16 bits)");
        need(fp.m >= 12 && fp.m <= 24, "the mantissa must be 12..24 bits (the multiplier: 18 x 18 and shift-and-add)");
        need(fp.e >= 7 && fp.e <= 10, "the exponent must be 7..10 bits");
        need(fp.g >= 1 && fp.g <= 4, "the adder's guard bits must be 1..4");
        need(tab_t >= 4 && tab_t <= 12, "the tables must have 2^4..2^12 intervals");
        need(tab_r >= 4 && tab_r <= 16, "tab_r must be 4..16");
        need(tab_t + tab_r <= fp.m, "tab_t + tab_r must be at most the mantissa's bits (a position from the mantissa)");
        need(tab_f >= fp.m + 1 && tab_f <= 40, "tab_f must be m+1..40");
        need(zf >= 29 && zf <= 34, "zf must be 29..34");
        need(lf >= 16 && lf <= 28, "lf must be 16..28");
        need(exp_t >= 4 && exp_t <= 12 && exp_r >= 4 && exp_r <= 16 && exp_t + exp_r <= lf, "bad exp2 table");
        need(exp_f >= 17 && exp_f <= 28, "exp_f must be 17..28 (above the C code's 16 bits)");
        need(flat_log2 <= -4 && flat_log2 >= -40, "flat_log2 must be -40..-4");
        need(a_tol_log2 <= -8 && a_tol_log2 >= -40, "a_tol_log2 must be -40..-8");
        need(opp_eps > 0 && opp_eps < 1e-2, "opp_eps must be in (0, 0.01)");
        need(mach.idot >= 1 && mach.mul >= 1 && mach.add >= 1 && mach.efu >= 1 && mach.misc >= 1, "every unit at least once");
        need(mach.idot <= 8 && mach.mul <= 16 && mach.add <= 16 && mach.efu <= 4 && mach.misc <= 8, "too many units");
    }
};

// Named formats (docs/setup.md). "ecp5" is the ecp5 configuration's, committed in rom/ (the shader's accuracy goal,
// issue 13's bound; units chosen so that spec_shader fits the ECP5-25F); "race" is the same format and arithmetic
// on more units (II 28 instead of 41, bit for bit the same results), which the ULX3S's racing-the-beam design
// builds so that a line's clocks hold K = 8's sub-spans (committed in rom/race/, make roms); "narrow" is the multiplier setup at its smallest for the iCE40 UP5K (a 16-bit mantissa for its
// 16 x 16 DSP blocks, one unit of each kind): `make synth`'s row that shows it does not fit there, which is why
// the up5k configuration keeps the small CORDIC setup (rom/gen/setup_small_format.h).
inline SetupFormat setup_format_config(const std::string& name) {
    SetupFormat sf;
    if (name == "ecp5") return sf;
    if (name == "race") {
        sf.name = "race";
        sf.mach.idot = 2;
        sf.mach.mul = 6;
        sf.mach.add = 4;
        sf.mach.efu = 2;
        sf.mach.misc = 4;
        return sf;
    }
    if (name == "narrow") {
        sf.name = "narrow";
        sf.fp.m = 16;
        sf.fp.e = 8;
        sf.tab_t = 8;
        sf.tab_r = 7;
        sf.tab_f = 20;
        sf.exp_t = 7;
        sf.exp_r = 9;
        sf.exp_f = 18;
        sf.lf = 16;
        sf.a_tol_log2 = -14;
        sf.mach.idot = 1;
        sf.mach.mul = 1;
        sf.mach.add = 1;
        sf.mach.efu = 1;
        sf.mach.misc = 1;
        return sf;
    }
    throw std::invalid_argument("unknown multiplier setup format '" + name + "' (ecp5, race, narrow)");
}

}  // namespace spec
