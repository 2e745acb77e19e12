// cmd_accuracy.cpp - specsim accuracy (make accuracy).
#include "cmd_accuracy.h"

#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "cli.h"
#include "cmd_span.h"
#include "commands.h"
#include "unit_driver.h"

namespace spec {

const char* const kAccuracyUsage =
    "  accuracy the core's worst error per BRDF range against double precision, every n, beside the\n"
    "           approximation's own error (q, a) and the patent's claims\n"
    "           --model golden|rtl (default golden; equal bit for bit)  --points P (100..100000, default 4000)\n"
    "           --tbl-aw N   (golden only) model a ROM 12 of 2^N positions per table instead of the default\n"
    "           --config C   (golden only) default | up5k (interpolated 4 x 256 tables, docs/stream.md)\n"
    "           --mode M     patent (default) | tuned (docs/tuned.md) | pow (docs/pow.md: also every angle and\n"
    "                        every n through the bit-exact model, against the goal 0.1 % of C + 2^-14)\n"
    "           --tables K,K,...  (golden only) ROM 12's powers k instead of 1,2,4,16 (table in ROM 9)\n";

AccuracyOptions parse_accuracy(int argc, char** argv) {
    AccuracyOptions o;
    Format& fmt = o.fmt;
    Args a(argc, argv, 2);
    while (!a.done()) {
        std::string fl = a.flag();
        if (fl == "--model") {
            o.model = a.value(fl);
            if (o.model != "golden" && o.model != "rtl") throw UsageError("--model: '" + o.model + "' is not golden or rtl");
        } else if (fl == "--points") {
            o.points = static_cast<uint32_t>(parse_int(fl, a.value(fl), 100, 100000));
        } else if (fl == "--tbl-aw") {
            fmt.tbl_aw = static_cast<int>(parse_int(fl, a.value(fl), 4, 16));
        } else if (fl == "--config") {
            try {
                const Mode mode = fmt.mode;
                const std::vector<int> tables = fmt.tables;
                fmt = config_format(a.value(fl));
                fmt.mode = mode;
                fmt.tables = tables;
            } catch (const std::invalid_argument& e) {
                throw UsageError(std::string("--config: ") + e.what());
            }
        } else if (fl == "--mode") {
            fmt.mode = parse_mode_flag(fl, a.value(fl));
        } else if (fl == "--tables") {
            fmt.tables = parse_tables(fl, a.value(fl));
        } else {
            throw UsageError("accuracy: unknown option " + fl);
        }
    }
    if (o.model == "rtl" && (fmt.tbl_aw != Format().tbl_aw || fmt.interp || fmt.tables != patent_tables() ||
                             fmt.pow_idx_w != Format().pow_idx_w)) {
        throw UsageError("--tbl-aw, --config, --tables: only with --model golden");
    }
    try {
        fmt.validate();
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("accuracy: ") + e.what());
    }
    return o;
}

AccuracyResult accuracy(const AccuracyOptions& o, SpanCore* core) {
    const Model m(o.fmt);
    const ErrorTable& e = mode_errors(m.format());
    const CoreErrors ce = core_errors(m, o.points, 0,
                                      core ? SpanRunner([&](const SpanRegs& r) { return core->span(r); }) : SpanRunner());
    struct Range {
        const char* name;
        unsigned lo, hi;
        const char* claim;
    } ranges[] = {{"n = 1 (cos)", 1, 1, "<= 1 %"},          {"n = 2 (cos^2)", 2, 2, "<= 1 %"},
                  {"n = 3..6 (cos^4)", 3, 6, "<= 1 %"},      {"n = 7..1000 (cos^16)", 7, 1000, "<= 1 %, <= 0.6 % (n >= 6)"},
                  {"n = 1001..1023 (cos^16)", 1001, 1023, "-"}, {"n = 0 (C)", 0, 0, "-"}};
    AccuracyResult r;
    for (const auto& rg : ranges) {
        unsigned qn = rg.lo, cn = rg.lo, an = rg.lo, bn = rg.lo;
        for (unsigned n = rg.lo; n <= rg.hi; ++n) {
            if (e.q[n] > e.q[qn]) qn = n;
            if (ce.rel_in[n] > ce.rel_in[cn]) cn = n;
            if (e.a[n] > e.a[an]) an = n;
            if (ce.abs_all[n] > ce.abs_all[bn]) bn = n;
        }
        const char* claim = m.format().pow() ? (rg.lo == 0 ? "C exactly" : "<= 0.1 % of C + 2^-14") : rg.claim;
        r.rows.push_back({rg.name, claim, rg.lo, rg.hi, e.q[qn], ce.rel_in[cn], e.a[an], ce.abs_all[bn], qn, cn,
                          an, bn});
    }
    for (unsigned n = 0; n < ce.rel_in.size(); ++n) {
        if (ce.rel_in[n] - e.q[n] > r.worst_extra) {
            r.worst_extra = ce.rel_in[n] - e.q[n];
            r.worst_extra_n = n;
        }
    }
    if (m.format().pow()) {
        r.pow = true;
        r.every = pow_exhaustive(m);
        for (unsigned n = 0; n < r.every.abs_err.size(); ++n) {
            if (r.every.abs_err[n] > r.every_worst) {
                r.every_worst = r.every.abs_err[n];
                r.every_worst_n = n;
            }
            if (r.every.rel_in[n] > r.every_rel) {
                r.every_rel = r.every.rel_in[n];
                r.every_rel_n = n;
            }
        }
    }
    return r;
}

std::string accuracy_report(const AccuracyOptions& o, const AccuracyResult& r) {
    const Model m(o.fmt);
    const Format& f = m.format();
    std::string tables;
    for (int k : f.tables) tables += (tables.empty() ? "" : ", ") + std::to_string(k);
    std::ostringstream s;
    char b[2048];
    if (f.pow()) {
        std::snprintf(b, sizeof b,
                      "Core (%s model, pow mode: log table of 2 x %d x %d entries, exp2 table of 2^%d positions%s, %u "
                      "points per n on [0, pi/2], C = 1 - 2^-16)\nagainst double precision\n\n",
                      o.model.c_str(), 1 << f.pow_seg_w, 1 << f.pow_idx_w, f.tbl_aw, f.interp ? " interpolated" : "",
                      o.points);
    } else {
        std::snprintf(b, sizeof b,
                      "Core (%s model, %s mode, tables k = %s, ROM 12 with 2^%d positions per table%s, %u points per n "
                      "on [0, pi/2], C = 1 - 2^-16)\nagainst double precision\n\n",
                      o.model.c_str(), mode_name(f.mode), tables.c_str(), f.tbl_aw, f.interp ? " and interpolation" : "",
                      o.points);
    }
    s << b << "| BRDF range | " << (f.pow() ? "goal (issue 30)" : "patent's claim") << " | approximation q (double) | core, max rel. error in epicentre |"
              " approximation a (double) | core, max abs. error / C on [0, pi/2] |\n"
              "|---|---|---|---|---|---|\n";
    for (const AccuracyRow& w : r.rows) {
        std::snprintf(b, sizeof b, "| %s | %s | %.3f %% (n = %u) | %.3f %% (n = %u) | %.3f %% (n = %u) | %.3f %% (n = %u) |\n",
                      w.name.c_str(), w.claim.c_str(), 100 * w.q, w.q_n, 100 * w.core_rel, w.core_rel_n, 100 * w.a,
                      w.a_n, 100 * w.core_abs, w.core_abs_n);
        s << b;
    }
    std::snprintf(b, sizeof b,
                  "\nFixed point adds at most %.4f %% to the approximation's relative error in the epicentre (n = %u).\n",
                  100 * r.worst_extra, r.worst_extra_n);
    s << b;
    if (r.pow) {
        // a pixel is round(C v) in UQ0.out_w: |pixel - C cos^n| <= 2^-(out_w+1) + C |v - cos^n|, so |v - cos^n| <= E
        // keeps every pixel within E C + 2^-(out_w+1), inside the goal's g C + 2^-14 when E <= g (C < 1)
        const double half = std::ldexp(1.0, -(f.out_w + 1));
        std::snprintf(b, sizeof b,
                      "\nEvery angle and every n (bit-exact model = RTL): the output depends on the angle only through its\n"
                      "position in the log table, constant over each position's interval of angles while cos^n is\n"
                      "monotone there; %llu positions (every angle |a| <= pi/2; 0 past it, for n >= 1) x %u values of n,\n"
                      "each checked at both ends of its interval:\n"
                      "  worst |2^-y - cos^n| = %.4f %% (n = %u, angle %.6f rad): every pixel within %.4f %% of C + 2^-%d\n"
                      "  worst relative error in the epicentre %.4f %% (n = %u)\n"
                      "Goal 0.1 %% of C + 2^-14: %s (stretch goal 0.025 %% of C + 2^-14: %s).\n",
                      (unsigned long long)r.every.positions, unsigned(r.every.abs_err.size()), 100 * r.every_worst,
                      r.every_worst_n, r.every.abs_at[r.every_worst_n], 100 * r.every_worst, f.out_w + 1,
                      100 * r.every_rel, r.every_rel_n,
                      r.every_worst <= kPowGoal && half <= std::ldexp(1.0, -14) ? "met for every n and every angle"
                                                                                  : "NOT met",
                      r.every_worst <= kPowStretch ? "met" : "not met");
        s << b;
    }
    return s.str();
}

int cmd_accuracy(int argc, char** argv) {
    const AccuracyOptions o = parse_accuracy(argc, argv);
    std::unique_ptr<SpanCore> core;
    if (o.model == "rtl") core = make_unit_driver(o.fmt.mode);
    std::cout << accuracy_report(o, accuracy(o, core.get()));
    return 0;
}

}  // namespace spec
