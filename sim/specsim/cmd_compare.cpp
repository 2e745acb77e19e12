// cmd_compare.cpp - specsim compare (make compare, docs/tuned.md), and what compare and tables share.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "cli.h"
#include "cmd_tuned.h"
#include "commands.h"
#include "fit.h"
#include "romgen.h"

namespace spec {

const char* const kTunedUsage =
    "  compare  patent mode, tuned mode, pow mode and the prototype (one table cos^2, scale sqrt(n/2)) on the\n"
    "           same datapath, and a per-material table of 256 entries indexed by N.H (the PICA200's way),\n"
    "           worst errors per BRDF range on the same spans: double precision and fixed point (the cores\n"
    "           bit-exact), ROM bits, the cost of a material change\n"
    "           --points P (100..100000, default 4000: pixels over [0, pi/2] per n, as accuracy)\n"
    "           --epi-points E (0..100000, default 0: also a span over the epicentre alone)\n"
    "  tables   other table sets and table sizes: worst epicentre error (double, fixed point) against ROM bits,\n"
    "           both modes; prints a Markdown table, writes tables.md, tables.csv, tables.dat, tables.gp and\n"
    "           tables.png (gnuplot) into --out-dir DIR (required). --quick: fewer sets and sizes\n";

const BrdfRange kBrdfRanges[7] = {{"n = 1 (cos)", 1, 1},
                                  {"n = 2 (cos^2)", 2, 2},
                                  {"n = 3..6 (cos^4)", 3, 6},
                                  {"n = 7..1000 (cos^16)", 7, 1000},
                                  {"n = 1001..1023 (cos^16)", 1001, 1023},
                                  {"all n = 1..1000", 1, 1000},
                                  {"all n = 0..1023", 0, 1023}};

Worst worst_of(const std::vector<double>& v, unsigned lo, unsigned hi) {
    Worst w{v.at(lo), lo};
    for (unsigned n = lo; n <= hi; ++n) {
        if (v.at(n) > w.v) w = {v[n], n};
    }
    return w;
}

Format sized_format(Mode mode, const std::vector<int>& tables, int tbl_aw, bool interp) {
    constexpr double kPi = 3.14159265358979323846;
    Format f;
    f.mode = mode;
    f.tables = tables;
    f.tbl_aw = tbl_aw;
    f.interp = interp;
    double smax = std::sqrt(((1 << f.n_w) - 1) / double(tables.back())) * 2 / kPi;
    for (const TableFit& t : table_fits(f)) smax = std::max(smax, t.scale * 2 / kPi);
    int ib = 1;
    while (std::nearbyint(std::ldexp(smax, f.scale_frac)) >= std::ldexp(1.0, f.scale_frac + ib)) ++ib;
    f.scale_w = f.scale_frac + ib;
    if (interp) {
        for (f.delta_w = 4;; ++f.delta_w) {
            try {
                make_rom12(f);
                break;
            } catch (const std::out_of_range&) {
                if (f.delta_w >= 20) throw;
            }
        }
    }
    f.validate();
    return f;
}

std::vector<CompareColumn> compare_modes(uint32_t points, uint32_t epi) {
    Format tuned, pow;
    tuned.mode = Mode::tuned;
    pow.mode = Mode::pow;
    std::vector<CompareColumn> cols{{"prototype", sized_format(Mode::patent, {2}, Format().tbl_aw, false), {}, {}},
                                    {"patent", Format(), {}, {}},
                                    {"tuned", tuned, {}, {}},
                                    {"pow", pow, {}, {}}};
    for (CompareColumn& c : cols) {
        c.dbl = mode_errors(c.f);
        c.core = core_errors(Model(c.f), points, epi);
    }
    return cols;
}

CompareLut compare_lut(uint32_t points, uint32_t epi) {
    const Model m;
    return {lut_errors(m, points, epi, false), lut_errors(m, points, epi, true)};
}

double rom_bits(const Format& f) {
    return std::ldexp(double(f.rom9_dw()), f.rom9_aw()) + std::ldexp(double(f.rom12_dw()), f.rom12_aw());
}

namespace {
std::string pct(const Worst& w) {
    char b[64];
    std::snprintf(b, sizeof b, "%.3f %% (n = %u)", 100 * w.v, w.n);
    return b;
}

void report_compare(const std::vector<CompareColumn>& cols, const CompareLut& lut, long long points, long long epi) {
    std::printf("Patent mode, tuned mode, pow mode and the prototype on the same datapath (ROM 12 of 2^%d positions per "
                "table, 17-bit words; the prototype: one table cos^2, ROM 9 = sqrt(n/2) * 2/pi in UQ%d.%d; pow mode:\n"
                "ROM 9 the log table, ROM 12 exp2, docs/pow.md).\n"
                "double: the approximation alone; core: the bit-exact model (= the RTL), %lld pixels over "
                "[0, pi/2]%s per n, C = 1 - 2^-16, against C cos^n in double precision.\n\n",
                Format().tbl_aw, cols[0].f.scale_w - cols[0].f.scale_frac, cols[0].f.scale_frac, points,
                epi ? (" and " + std::to_string(epi) + " over the epicentre").c_str() : "");
    for (int table = 0; table < 2; ++table) {
        std::printf(table == 0 ? "Worst relative error in the epicentre:\n\n" : "\nWorst absolute error / C on [0, pi/2]:\n\n");
        std::printf("| BRDF range | prototype, double | prototype, core | patent, double | patent, core | "
                    "tuned, double | tuned, core | pow, double | pow, core |\n|---|---|---|---|---|---|---|---|---|\n");
        for (const BrdfRange& r : kBrdfRanges) {
            std::printf("| %s |", r.name);
            for (const CompareColumn& c : cols) {
                const std::vector<double>& d = table == 0 ? c.dbl.q : c.dbl.a;
                const std::vector<double>& k = table == 0 ? c.core.rel_in : c.core.abs_all;
                std::printf(" %s | %s |", pct(worst_of(d, r.lo, r.hi)).c_str(), pct(worst_of(k, r.lo, r.hi)).c_str());
            }
            std::printf("\n");
        }
    }
    // the choices side by side: each core in fixed point (what the hardware gives), the per-material table in
    // double and in its fixed point; ROM bits; what changing the material (n) costs
    std::printf("\nThe choices on the same spans, fixed point (the cores bit-exact; the per-material table: 256 entries "
                "of 12-bit value and 12-bit difference indexed by N.H, interpolated, as the PICA200's lighting tables; "
                "also in double). Each cell: worst relative error in the epicentre / worst absolute error / C on "
                "[0, pi/2].\n\n");
    std::printf("| BRDF range | prototype (cos^2) | patent | tuned | pow | per-material table, double | "
                "per-material table, fixed point |\n|---|---|---|---|---|---|---|\n");
    auto pair = [&](const CoreErrors& e, const BrdfRange& r) {
        return pct(worst_of(e.rel_in, r.lo, r.hi)) + " / " + pct(worst_of(e.abs_all, r.lo, r.hi));
    };
    for (const BrdfRange& r : kBrdfRanges) {
        std::printf("| %s |", r.name);
        for (const CompareColumn& c : cols) std::printf(" %s |", pair(c.core, r).c_str());
        std::printf(" %s | %s |\n", pair(lut.dbl, r).c_str(), pair(lut.fixed, r).c_str());
    }
    std::printf("| ROM bits |");
    for (const CompareColumn& c : cols) std::printf(" %.0f |", rom_bits(c.f));
    std::printf(" %d per material | %d per material |\n", MaterialLut::bits(), MaterialLut::bits());
    std::printf("| a material change (n) |");
    for (size_t i = 0; i < cols.size(); ++i) std::printf(" n in the span's descriptor (none) |");
    std::printf(" the table reloaded: %d entries | the table reloaded: %d entries (%d bits) |\n", MaterialLut::kEntries,
                MaterialLut::kEntries, MaterialLut::bits());
}}  // namespace

int cmd_compare(int argc, char** argv) {
    long long points = 4000, epi = 0;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string fl = a.flag();
        if (fl == "--points") points = parse_int(fl, a.value(fl), 100, 100000);
        else if (fl == "--epi-points") epi = parse_int(fl, a.value(fl), 0, 100000);
        else throw UsageError("compare: unknown option " + fl);
    }
    report_compare(compare_modes(uint32_t(points), uint32_t(epi)), compare_lut(uint32_t(points), uint32_t(epi)), points,
                   epi);
    return 0;
}

}  // namespace spec
