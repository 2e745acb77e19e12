// cmd_tables.cpp - specsim tables (make tables, docs/tables.md): other table sets and table sizes, worst
// errors against ROM bits, both modes.
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "cli.h"
#include "cmd_tuned.h"
#include "commands.h"
#include "fileutil.h"

namespace spec {

TablesPlan tables_plan(bool quick) {
    TablesPlan p;
    p.sets = {{2},
              {1, 4},
              {1, 2, 16},
              {1, 2, 4, 16},
              {1, 2, 4, 8, 16},
              {1, 2, 3, 4, 8, 16},
              {1, 2, 4, 16, 64},
              {1, 2, 4, 8, 16, 32, 64},
              {1, 2, 3, 4, 8, 16, 32, 64}};
    p.plain = {8, 9, 10, 11, 12, 13};
    p.interp = {6, 7, 8};
    if (quick) {   // the same rows as the full run, fewer of them
        p.sets = {{1, 2, 4, 16}, {1, 2, 3, 4, 8, 16, 32, 64}};
        p.plain = {10, 12};
        p.interp = {8};
    }
    return p;
}

std::vector<TablesRow> tables_rows(const TablesPlan& p) {
    std::vector<TablesRow> rows;
    for (const auto& t : p.sets) {
        for (Mode mode : {Mode::patent, Mode::tuned}) {
            const ErrorTable& e = mode_errors(sized_format(mode, t, 12, false));
            for (int pass = 0; pass < 2; ++pass) {
                for (int aw : pass == 0 ? p.plain : p.interp) {
                    TablesRow r{t, mode, aw, pass == 1, sized_format(mode, t, aw, pass == 1), 0, 0, {}, {}, {}};
                    r.rom9_bits = double(1 << r.f.n_w) * r.f.rom9_dw();
                    r.rom12_bits = double(t.size()) * double(1 << aw) * r.f.rom12_dw();
                    r.q = worst_of(e.q, 0, 1023);
                    const CoreErrors ce = core_errors(Model(r.f), p.points, p.epi);
                    r.core_rel = worst_of(ce.rel_in, 0, 1023);
                    r.core_abs = worst_of(ce.abs_all, 0, 1023);
                    rows.push_back(r);
                }
            }
        }
    }
    return rows;
}

namespace {
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

void write_text(const std::string& path, const std::string& text) {
    render::write_atomic(path, [&](const std::string& tmp) {
        std::ofstream o(tmp);
        o << text;
        o.close();
        if (!o) throw InputError("cannot write " + path);
    });
}

// Writes tables.md, .csv, .dat, .gp and .png into dir; returns the Markdown table.
std::string report_tables(const std::string& dir, bool quick, const TablesPlan& plan, const std::vector<TablesRow>& rows) {
    const auto& sets = plan.sets;
    const uint32_t points = plan.points, epi = plan.epi;
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
    for (const TablesRow& r : rows) {
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
                for (const TablesRow& r : rows) {
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
    if (std::rename((png + ".tmp").c_str(), png.c_str()) != 0) throw InputError("cannot write " + png);
    std::remove((dir + "/gnuplot.log").c_str());
    return md.str();
}
}  // namespace

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
    if (ec) throw InputError("cannot create " + dir + ": " + ec.message());
    const TablesPlan plan = tables_plan(quick);
    const std::string md = report_tables(dir, quick, plan, tables_rows(plan));
    std::cout << md << "\ntables: " << dir << "/tables.md, tables.csv, tables.png (data tables.dat, script "
              << "tables.gp)\n";
    return 0;
}

}  // namespace spec
