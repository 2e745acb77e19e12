// analysis.h - double-precision analysis of the patent's approximation cos^n(d) ~ cos^k(sqrt(n/k) d).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "fit.h"   // epicentre_end, maximize, the table fits of patent and tuned mode
#include "spec_format.h"
#include "spec_model.h"

namespace spec {

// cos^k(sqrt(n/k) d) with the table clamped to 0 once sqrt(n/k) d >= pi/2 (as ROM 12 is); n = 0 gives 1.
double approx(unsigned n, int k, double d);

// q(n, k): worst relative error |approx - cos^n| / cos^n over the epicentre [0, epicentre_end(n)].
double q_error(unsigned n, int k);
// a(n, k): worst absolute error |approx - cos^n| over [0, pi/2].
double a_error(unsigned n, int k);

// Both for the Fig. 10 rule (k = k_of_n(n)), cached for n = 0 .. 2^n_w - 1.
struct ErrorTable {
    std::vector<double> q, a;
};
const ErrorTable& fig10_errors();  // n = 0 .. 1023
// The same for any format's mode and table set (ROM 9's scale and table per n, fit.h), in double precision:
// q(n) worst relative error in the epicentre, a(n) worst absolute error on [0, pi/2]. Cached; for the patent's
// default it is fig10_errors(). Pow mode: pow_approx's errors, on a grid four times finer than the log table's
// in every segment.
const ErrorTable& mode_errors(const Format& f);

// The fixed-point core against double precision, every n = 0 .. 2^n_w - 1, C = 1 - 2^-c_w:
// one span from angle 0 to pi/2 (`points` intervals) and, when epi_points > 0, one from 0 to the end of the
// epicentre (epi_points intervals, so that large n get as many samples there as small n); ref = C cos^n(x)
// at the angle x register 8 holds. run: the core (e.g. a Verilated one); empty: m's bit-exact model.
struct CoreErrors {
    std::vector<double> rel_in;   // worst |out - ref| / ref over the epicentre
    std::vector<double> abs_all;  // worst |out - ref| / C over [0, pi/2]
};
using SpanRunner = std::function<std::vector<uint32_t>(const SpanRegs&)>;
CoreErrors core_errors(const Model& m, uint32_t points, uint32_t epi_points = 0, const SpanRunner& run = {});

// Pow mode (docs/pow.md), every angle: the core's output depends on the angle only through its position in the
// log table (side, segment, entry, pow_frac bits of fraction; rtl/spec_powpath.v), so over each position's
// interval of angles it is constant while cos^n is monotone, and the worst error over the interval is at one of
// its ends. pow_exhaustive runs every position of both sides (every angle |a| <= K = pi/2 in the angle format)
// for every n = 0 .. 2^n_w - 1 and measures the value before multiplier 13 (2^-y, what multiplies C) against
// cos^n at the interval's ends: worst |value - cos^n| (per n), and within the epicentre the worst relative error.
// A pixel is round(C value) (UQ0.out_w), so |pixel - C cos^n| <= 2^-(out_w+1) + C |value - cos^n|.
struct PowExhaustive {
    std::vector<double> abs_err;   // per n: worst |value - cos^n| over every angle
    std::vector<double> abs_at;    // ... at this angle (radians)
    std::vector<double> rel_in;    // per n: worst |value - cos^n| / cos^n over the epicentre
    uint64_t positions = 0;        // positions of the log table that some angle reaches
};
PowExhaustive pow_exhaustive(const Model& m, unsigned threads = 2);
// The double-precision approximation of pow mode: exp2(-n L~(d)), L~ the log table's linear interpolation between
// the exact -log2 cos at its grid points (no rounding anywhere): what the table design alone costs. d >= 0.
double pow_approx(const Format& f, unsigned n, double d);

// The alternative a GPU with per-material tables takes (the PICA200's lighting lookup tables): a table of 256
// entries indexed by N.H = cos(d) in [0, 1], reloaded for each material (each n), linear interpolation between
// entries. Entry i holds (i/256)^n and the difference to entry i + 1 ((256/256)^n = 1 after the last).
//   double: exact entries, x = cos d exact, exact interpolation;
//   fixed:  the PICA200's entry format as emulators document it: the value in 12 bits (UQ0.12, 1.0 saturating to
//           4095/4096), the difference in 12 bits two's complement with 11 fraction bits (saturating), x in 16
//           bits (an 8-bit index and an 8-bit fraction), the interpolated value rounded to 12 bits; times C
//           (UQ0.c_w) rounded to out_w bits as the core's output.
// Returns the output as a fraction of 1 (C c_w-bit quantized as the core's register 1).
struct MaterialLut {
    explicit MaterialLut(unsigned n);
    double value_double(double x) const;             // the interpolated table at x in [0, 1]
    uint32_t pixel_fixed(uint32_t c, double x, int c_w, int out_w) const;   // the output word, UQ0.out_w
    static constexpr int kEntries = 256, kValueBits = 12, kDiffFrac = 11, kFracBits = 8;
    static constexpr int bits() { return kEntries * (kValueBits + kDiffFrac + 1); }   // per material
    unsigned n;
    std::vector<double> t;           // t[i] = (i/256)^n, i = 0 .. 256
    std::vector<uint32_t> value;     // 12-bit values
    std::vector<int32_t> diff;       // 12-bit differences
};
// core_errors' spans and measures (C = 1 - 2^-c_w, angles as register 8 holds them) for the per-material table,
// in double (fixed = false) or its fixed point.
CoreErrors lut_errors(const Model& m, uint32_t points, uint32_t epi_points, bool fixed);

// The recomputed Fig. 8: for each k = 1..16, the n in 1..1000 whose q(n, k) <= limit.
struct Fig8Row {
    int k;
    int n_lo, n_hi;     // smallest and largest such n (0, 0 when none)
    bool contiguous;    // every n between n_lo and n_hi qualifies
    int count;
};
// mode = tuned: each table with the minimax scale for each n (fit.h) instead of sqrt(n/k).
std::vector<Fig8Row> fig8(double limit = 0.01, Mode mode = Mode::patent);

// The report `specsim fig8` prints.
std::string fig8_report(bool all_n, Mode mode = Mode::patent);

}  // namespace spec
