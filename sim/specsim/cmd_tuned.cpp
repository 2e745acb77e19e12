// cmd_tuned.cpp - specsim compare and specsim tables (issue 7, docs/tuned.md): patent mode against tuned mode
// and the prototype, and the worst error of other table sets and table sizes against ROM bits.
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis.h"
#include "cli.h"
#include "commands.h"
#include "fit.h"
#include "romgen.h"
#include "spec_model.h"

namespace spec {

const char* const kTunedUsage =
    "  compare  patent mode, tuned mode and the prototype (one table cos^2, scale sqrt(n/2)) on the same\n"
    "           datapath, worst errors per BRDF range: double precision and the fixed-point core (bit-exact)\n"
    "           --points P (100..100000, default 4000: pixels over [0, pi/2] per n, as accuracy)\n"
    "           --epi-points E (0..100000, default 0: also a span over the epicentre alone)\n"
    "  tables   other table sets and table sizes: worst epicentre error (double, fixed point) against ROM bits,\n"
    "           both modes; prints a Markdown table, writes tables.md, tables.csv, tables.dat, tables.gp and\n"
    "           tables.png (gnuplot) into --out-dir DIR (required). --quick: fewer sets and sizes\n";

namespace {
constexpr double kPi = 3.14159265358979323846;

struct Range {
    const char* name;
    unsigned lo, hi;
};
const Range kRanges[] = {{"n = 1 (cos)", 1, 1},
                         {"n = 2 (cos^2)", 2, 2},
                         {"n = 3..6 (cos^4)", 3, 6},
                         {"n = 7..1000 (cos^16)", 7, 1000},
                         {"n = 1001..1023 (cos^16)", 1001, 1023},
                         {"all n = 1..1000", 1, 1000},
                         {"all n = 0..1023", 0, 1023}};

struct Worst {
    double v = 0;
    unsigned n = 0;
};
Worst worst_of(const std::vector<double>& v, unsigned lo, unsigned hi) {
    Worst w{v.at(lo), lo};
    for (unsigned n = lo; n <= hi; ++n) {
        if (v.at(n) > w.v) w = {v[n], n};
    }
    return w;
}

std::string pct(const Worst& w) {
    char b[64];
    std::snprintf(b, sizeof b, "%.3f %% (n = %u)", 100 * w.v, w.n);
    return b;
}

std::string tables_name(const std::vector<int>& t) {
    std::string s;
    for (int k : t) s += (s.empty() ? "" : ",") + std::to_string(k);
    return s;
}

// A format for the table set with ROM 9's integer bits and (with interpolation) ROM 12's step field as narrow
// as the contents allow, so that ROM bits compare fairly. The patent's set keeps its 18-bit UQ3.15 word.
Format sized_format(Mode mode, const std::vector<int>& tables, int tbl_aw, bool interp) {
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

void write_text(const std::string& path, const std::string& text) {
    const std::string tmp = path + ".tmp";
    {
        std::ofstream o(tmp);
        o << text;
        o.close();
        if (!o) {
            std::remove(tmp.c_str());
            throw std::runtime_error("cannot write " + path);
        }
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) throw std::runtime_error("cannot write " + path);
}
}  // namespace

int cmd_compare(int argc, char** argv) {
    long long points = 4000, epi = 0;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string fl = a.flag();
        if (fl == "--points") points = parse_int(fl, a.value(fl), 100, 100000);
        else if (fl == "--epi-points") epi = parse_int(fl, a.value(fl), 0, 100000);
        else throw UsageError("compare: unknown option " + fl);
    }
    struct Col {
        const char* name;
        Format f;
    };
    Format tuned;
    tuned.mode = Mode::tuned;
    const Col cols[] = {{"prototype", sized_format(Mode::patent, {2}, Format().tbl_aw, false)},
                        {"patent", Format()},
                        {"tuned", tuned}};
    std::vector<const ErrorTable*> dbl;
    std::vector<CoreErrors> core;
    for (const Col& c : cols) {
        dbl.push_back(&mode_errors(c.f));
        core.push_back(core_errors(Model(c.f), uint32_t(points), uint32_t(epi)));
    }
    std::printf("Patent mode, tuned mode and the prototype on the same datapath (ROM 12 of 2^%d positions per "
                "table, 17-bit words; the prototype: one table cos^2, ROM 9 = sqrt(n/2) * 2/pi in UQ%d.%d).\n"
                "double: the approximation alone; core: the bit-exact model (= the RTL), %lld pixels over "
                "[0, pi/2]%s per n, C = 1 - 2^-16, against C cos^n in double precision.\n\n",
                Format().tbl_aw, cols[0].f.scale_w - cols[0].f.scale_frac, cols[0].f.scale_frac, points,
                epi ? (" and " + std::to_string(epi) + " over the epicentre").c_str() : "");
    std::printf("Worst relative error in the epicentre:\n\n"
                "| BRDF range | prototype, double | prototype, core | patent, double | patent, core | "
                "tuned, double | tuned, core |\n|---|---|---|---|---|---|---|\n");
    for (const Range& r : kRanges) {
        std::printf("| %s |", r.name);
        for (size_t c = 0; c < 3; ++c) {
            std::printf(" %s | %s |", pct(worst_of(dbl[c]->q, r.lo, r.hi)).c_str(),
                        pct(worst_of(core[c].rel_in, r.lo, r.hi)).c_str());
        }
        std::printf("\n");
    }
    std::printf("\nWorst absolute error / C on [0, pi/2]:\n\n"
                "| BRDF range | prototype, double | prototype, core | patent, double | patent, core | "
                "tuned, double | tuned, core |\n|---|---|---|---|---|---|---|\n");
    for (const Range& r : kRanges) {
        std::printf("| %s |", r.name);
        for (size_t c = 0; c < 3; ++c) {
            std::printf(" %s | %s |", pct(worst_of(dbl[c]->a, r.lo, r.hi)).c_str(),
                        pct(worst_of(core[c].abs_all, r.lo, r.hi)).c_str());
        }
        std::printf("\n");
    }
    return 0;
}

int cmd_tables(int argc, char** argv) {
    std::string dir;
    bool quick = false;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string fl = a.flag();
        if (fl == "--out-dir") dir = a.value(fl);
        else if (fl == "--quick") quick = true;
        else throw UsageError("tables: unknown option " + fl);
    }
    if (dir.empty()) throw UsageError("tables: --out-dir DIR is required");
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw std::runtime_error("cannot create " + dir + ": " + ec.message());

    std::vector<std::vector<int>> sets = {{2},
                                          {1, 4},
                                          {1, 2, 16},
                                          {1, 2, 4, 16},
                                          {1, 2, 4, 8, 16},
                                          {1, 2, 3, 4, 8, 16},
                                          {1, 2, 4, 16, 64},
                                          {1, 2, 4, 8, 16, 32, 64},
                                          {1, 2, 3, 4, 8, 16, 32, 64}};
    std::vector<int> plain = {8, 9, 10, 11, 12, 13}, interp = {6, 7, 8};
    if (quick) {
        sets = {{1, 2, 4, 16}, {1, 2, 3, 4, 8, 16, 32, 64}};
        plain = {10, 12};
        interp = {8};
    }
    const uint32_t points = 2000, epi = 500;   // --quick: the same rows as the full run, fewer of them

    struct Row {
        std::vector<int> tables;
        Mode mode;
        int aw;
        bool interp;
        Format f;
        double rom9_bits, rom12_bits;
        Worst q, core_rel, core_abs;
    };
    std::vector<Row> rows;
    for (const auto& t : sets) {
        for (Mode mode : {Mode::patent, Mode::tuned}) {
            const ErrorTable& e = mode_errors(sized_format(mode, t, 12, false));
            for (int pass = 0; pass < 2; ++pass) {
                for (int aw : pass == 0 ? plain : interp) {
                    Row r{t, mode, aw, pass == 1, sized_format(mode, t, aw, pass == 1), 0, 0, {}, {}, {}};
                    r.rom9_bits = double(1 << r.f.n_w) * r.f.rom9_dw();
                    r.rom12_bits = double(t.size()) * double(1 << aw) * r.f.rom12_dw();
                    r.q = worst_of(e.q, 0, 1023);
                    const CoreErrors ce = core_errors(Model(r.f), points, epi);
                    r.core_rel = worst_of(ce.rel_in, 0, 1023);
                    r.core_abs = worst_of(ce.abs_all, 0, 1023);
                    rows.push_back(r);
                }
            }
        }
    }

    std::ostringstream md, csv, dat;
    md << "Worst errors over n = 0..1023 against ROM bits (`specsim tables" << (quick ? " --quick" : "")
       << "`, `make tables`); "
       << "core: the bit-exact model (= the RTL), " << points << " pixels over [0, pi/2] and " << epi
       << " over the epicentre per n, C = 1 - 2^-16, against C cos^n in double precision. patent: ROM 9 = "
          "sqrt(n/k) (with the patent's tables the Fig. 10 rule, otherwise the better of the two tables next "
          "to n); tuned: minimax scale and table. ROM 9 word = table index (outside the patent's default) + "
          "scale with as many integer bits as the set needs; ROM 12 = tables x positions x word bits "
          "(interp.: + step field).\n\n"
       << "| tables k | mode | ROM 12 | ROM 9 | ROM kbit | double: worst rel. in epicentre | core: worst rel. "
          "in epicentre | core: worst abs. / C | core <= 0.25 % |\n"
       << "|---|---|---|---|---|---|---|---|---|\n";
    csv << "tables,mode,tbl_aw,interp,rom9_bits,rom12_bits,total_kbit,q_double,q_double_n,core_rel,core_rel_n,"
           "core_abs,core_abs_n\n";
    char b[512];
    for (const Row& r : rows) {
        const double kbit = (r.rom9_bits + r.rom12_bits) / 1024;
        std::snprintf(b, sizeof b, "| %s | %s | %zu x 2^%d x %d%s | 1024 x %d | %.1f | %s | %s | %s | %s |\n",
                      tables_name(r.tables).c_str(), mode_name(r.mode), r.tables.size(), r.aw, r.f.rom12_dw(),
                      r.interp ? " (interp.)" : "", r.f.rom9_dw(), kbit, pct(r.q).c_str(), pct(r.core_rel).c_str(),
                      pct(r.core_abs).c_str(), r.core_rel.v <= 0.0025 ? "yes" : "no");
        md << b;
        std::snprintf(b, sizeof b, "\"%s\",%s,%d,%d,%.0f,%.0f,%.3f,%.6g,%u,%.6g,%u,%.6g,%u\n",
                      tables_name(r.tables).c_str(), mode_name(r.mode), r.aw, int(r.interp), r.rom9_bits,
                      r.rom12_bits, kbit, r.q.v, r.q.n, r.core_rel.v, r.core_rel.n, r.core_abs.v, r.core_abs.n);
        csv << b;
    }
    // gnuplot data: one block per (mode, set, plain/interp), in the order the script plots them
    std::ostringstream plot_patent, plot_tuned;
    const char* colors[] = {"#7f7f7f", "#bcbd22", "#17becf", "#1f77b4", "#ff7f0e",
                            "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2"};
    int block = 0;
    for (Mode mode : {Mode::patent, Mode::tuned}) {
        std::ostringstream& pl = mode == Mode::patent ? plot_patent : plot_tuned;
        for (size_t s = 0; s < sets.size(); ++s) {
            for (int pass = 0; pass < 2; ++pass) {
                dat << "# " << mode_name(mode) << " k = " << tables_name(sets[s]) << (pass ? " interpolated" : "")
                    << ": total_kbit core_rel_% q_double_%\n";
                for (const Row& r : rows) {
                    if (r.mode != mode || r.tables != sets[s] || r.interp != (pass == 1)) continue;
                    std::snprintf(b, sizeof b, "%.3f %.6f %.6f\n", (r.rom9_bits + r.rom12_bits) / 1024,
                                  100 * r.core_rel.v, 100 * r.q.v);
                    dat << b;
                }
                dat << "\n\n";
                pl << (pl.tellp() > 0 ? ", \\\n     " : "plot ") << "'tables.dat' index " << block
                   << " u 1:2 w lp lw 2 pt " << (pass ? 6 : 7) << " dt " << (pass ? 2 : 1) << " lc rgb '"
                   << colors[s % 10] << "' t '"
                   << (pass ? "  interpolated" : "k = " + tables_name(sets[s]) + (sets[s].size() == 1 ? " (prototype)" : ""))
                   << "'";
                ++block;
            }
        }
        pl << ", \\\n     0.25 w l dt 3 lw 1.5 lc rgb 'black' t '0.25 %', 1 w l dt 2 lw 1.5 lc rgb 'black' t '1 %'\n";
    }
    const std::string gp =
        "# written by specsim tables; gnuplot tables.gp (in this directory) redraws tables.png\n"
        "set terminal pngcairo size 1400,640 font 'sans,10'\n"
        "set output 'tables.png.tmp'\n"
        "set multiplot layout 1,2 title 'Worst relative error of the fixed-point core in the epicentre "
        "(n = 0..1023) against ROM 9 + ROM 12 bits'\n"
        "set logscale xy\n"
        "set xlabel 'ROM 9 + ROM 12, kbit'\n"
        "set ylabel 'worst relative error in the epicentre, %'\n"
        "set yrange [0.02:50]\n"
        "set format y '%g'\n"
        "set grid\n"
        "set xrange [15:1500]\n"
        "set lmargin at screen 0.05\nset rmargin at screen 0.39\n"
        "unset key\n"
        "set title 'patent mode: ROM 9 = sqrt(n/k)'\n" +
        plot_patent.str() +
        "set lmargin at screen 0.46\nset rmargin at screen 0.80\n"
        "set key at screen 0.995, screen 0.88 right top box opaque font ',9'\n"
        "set title 'tuned mode: minimax scale and table in ROM 9'\n" + plot_tuned.str() +
        "unset multiplot\nunset output\n";
    write_text(dir + "/tables.md", md.str());
    write_text(dir + "/tables.csv", csv.str());
    write_text(dir + "/tables.dat", dat.str());
    write_text(dir + "/tables.gp", gp);
    const std::string cmd = "cd '" + dir + "' && gnuplot tables.gp 2>gnuplot.log";
    const int st = std::system(cmd.c_str());
    const int code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    if (code != 0) {
        std::remove((dir + "/tables.png.tmp").c_str());
        if (code == 127) throw std::runtime_error("gnuplot not found (make deps installs gnuplot-nox)");
        throw std::runtime_error("gnuplot failed, see " + dir + "/gnuplot.log");
    }
    const std::string png = dir + "/tables.png";
    if (std::rename((png + ".tmp").c_str(), png.c_str()) != 0) throw std::runtime_error("cannot write " + png);
    std::remove((dir + "/gnuplot.log").c_str());
    std::cout << md.str() << "\ntables: " << dir << "/tables.md, tables.csv, tables.png (data tables.dat, script "
              << "tables.gp)\n";
    return 0;
}

}  // namespace spec
