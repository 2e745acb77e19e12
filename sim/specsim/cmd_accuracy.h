// cmd_accuracy.h - specsim accuracy: the core's worst error per BRDF range against double precision, every
// n, beside the approximation's own error (parse -> compute -> report).
#pragma once

#include <string>
#include <vector>

#include "analysis.h"
#include "span_core.h"

namespace spec {

struct AccuracyOptions {
    std::string model = "golden";   // golden | rtl
    uint32_t points = 4000;         // intervals over [0, pi/2] per n
    Format fmt;                     // --tbl-aw, --config, --mode, --tables
};
// Throws UsageError (also for a format the generator rejects).
AccuracyOptions parse_accuracy(int argc, char** argv);

// One BRDF range's row: the worst value and its n of each column.
struct AccuracyRow {
    std::string name, claim;
    unsigned lo, hi;
    double q, core_rel, a, core_abs;   // approximation q (double), core max rel. in epicentre, a, core max abs./C
    unsigned q_n, core_rel_n, a_n, core_abs_n;
};
struct AccuracyResult {
    std::vector<AccuracyRow> rows;   // n = 1, 2, 3..6, 7..1000, 1001..1023, 0
    double worst_extra = 0;          // largest (core rel. error - q) over n: what fixed point adds in the epicentre
    unsigned worst_extra_n = 0;
    // pow mode: every angle and every n (pow_exhaustive, the bit-exact model), and the worst over n
    bool pow = false;
    PowExhaustive every;
    double every_worst = 0, every_rel = 0;
    unsigned every_worst_n = 0, every_rel_n = 0;
};
// pow mode's goal (issue 30): every pixel within 0.1 % of C + 2^-14; the stretch goal 0.025 % of C + 2^-14.
constexpr double kPowGoal = 0.001, kPowStretch = 0.00025;
// core: the spans' runner for the rtl model (the Verilated spec_unit of the options' mode); null: the bit-exact
// model of the options' format.
AccuracyResult accuracy(const AccuracyOptions& o, SpanCore* core = nullptr);
std::string accuracy_report(const AccuracyOptions& o, const AccuracyResult& r);

}  // namespace spec
