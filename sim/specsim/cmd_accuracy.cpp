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
    "           --mode M     patent (default) | tuned (docs/tuned.md)\n"
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
    if (o.model == "rtl" && (fmt.tbl_aw != Format().tbl_aw || fmt.interp || fmt.tables != patent_tables())) {
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
        r.rows.push_back({rg.name, rg.claim, rg.lo, rg.hi, e.q[qn], ce.rel_in[cn], e.a[an], ce.abs_all[bn], qn, cn,
                          an, bn});
    }
    for (unsigned n = 0; n < ce.rel_in.size(); ++n) {
        if (ce.rel_in[n] - e.q[n] > r.worst_extra) {
            r.worst_extra = ce.rel_in[n] - e.q[n];
            r.worst_extra_n = n;
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
    char b[512];
    std::snprintf(b, sizeof b,
                  "Core (%s model, %s mode, tables k = %s, ROM 12 with 2^%d positions per table%s, %u points per n "
                  "on [0, pi/2], C = 1 - 2^-16)\nagainst double precision\n\n",
                  o.model.c_str(), mode_name(f.mode), tables.c_str(), f.tbl_aw, f.interp ? " and interpolation" : "",
                  o.points);
    s << b << "| BRDF range | patent's claim | approximation q (double) | core, max rel. error in epicentre |"
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
