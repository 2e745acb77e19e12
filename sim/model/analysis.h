// analysis.h - double-precision analysis of the patent's approximation cos^n(d) ~ cos^k(sqrt(n/k) d).
#pragma once

#include <string>
#include <vector>

namespace spec {

// End of the highlight epicentre: the inflection point atan(1/sqrt(n-1)) of cos^n (n >= 2);
// n = 1: pi/3 (cos has no inflection before pi/2); n = 0: pi/2 (cos^0 = 1, the whole quarter).
double epicentre_end(unsigned n);

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

// The recomputed Fig. 8: for each k = 1..16, the n in 1..1000 whose q(n, k) <= limit.
struct Fig8Row {
    int k;
    int n_lo, n_hi;     // smallest and largest such n (0, 0 when none)
    bool contiguous;    // every n between n_lo and n_hi qualifies
    int count;
};
std::vector<Fig8Row> fig8(double limit = 0.01);

// The report `specsim fig8` prints.
std::string fig8_report(bool all_n);

}  // namespace spec
