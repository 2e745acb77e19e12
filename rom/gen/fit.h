// fit.h - what ROM 9 holds for each n: which table cos^k of ROM 12, and the scale s that multiplies the angle,
// so that cos^k(s * d) stands for cos^n(d).
//
//   patent mode: s = sqrt(n/k) (the patent's match of the second Maclaurin terms, eq. 11); with the patent's
//                tables {1, 2, 4, 16} k follows the Fig. 10 rule (decoder 10's gates), with any other table
//                set the table whose Taylor scale gives the smaller worst relative error.
//   tuned mode:  for each candidate table, the minimax scale: the s that minimises the worst relative error
//                |cos^k(s d) / cos^n(d) - 1| over the epicentre [0, epicentre_end(n)]; then the table with the
//                smaller error. Candidates are the tables next to n (largest k <= n, smallest k >= n): the
//                error grows with |1/k - 1/n| (docs/tuned.md; checked against all tables by a test).
//
// Everything here is double precision; the generator rounds s * 2/pi into ROM 9's word.
#pragma once

#include <functional>
#include <vector>

#include "spec_format.h"

namespace spec {

// End of the highlight epicentre: the inflection point atan(1/sqrt(n-1)) of cos^n (n >= 2);
// n = 1: pi/3 (cos has no inflection before pi/2); n = 0: pi/2 (cos^0 = 1, the whole quarter).
double epicentre_end(unsigned n);

// Maximum of a continuous function on [lo, hi]: `samples` + 1 equidistant samples, then golden-section search
// in the bracket around the best sample.
double maximize(const std::function<double(double)>& f, double lo, double hi, int samples = 1024);

// cos^k(s |d|), 0 once s |d| >= pi/2 (as ROM 12 is); n = 0 (s = 0) gives 1.
double approx_scaled(int k, double s, double d);
// Worst relative error of approx_scaled(k, s, d) against cos^n(d) over the epicentre; n = 0: 0.
double rel_error(unsigned n, int k, double s);
// Worst absolute error against cos^n(d) over [0, pi/2]; n = 0: 0.
double abs_error(unsigned n, int k, double s);
// The minimax scale for n and table k (sqrt(n/k) exactly when n = k), and its worst relative error in *q.
double minimax_scale(unsigned n, int k, double* q = nullptr);

struct TableFit {
    int table = 0;     // index into Format::tables
    int k = 1;         // Format::tables[table]
    double scale = 0;  // s (radians to radians; ROM 9 holds s * 2/pi)
};

// One entry per n = 0 .. 2^n_w - 1, for f.mode and f.tables. Cached per (mode, tables, n_w): the tuned fit
// takes about a second. Throws std::invalid_argument for an empty or unsorted table set.
const std::vector<TableFit>& table_fits(const Format& f);

}  // namespace spec
