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
// default it is fig10_errors().
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
