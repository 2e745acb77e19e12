// report_parallax.cpp - specsim parallax's tables, plots and pictures (cmd_parallax.h).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "cmd_parallax.h"
#include "image.h"
#include "methods_util.h"
#include "parallax_quad.h"

namespace spec {

using methods_cli::pct;
using methods_cli::strf;

namespace {
std::string mp(const methods::ErrSummary& e) { return strf("%.2f / %.2f", e.mean, e.p99); }

std::string el_name(double el) { return strf("%g", el); }

render::Image error_ramp(const std::vector<double>& err, int w, int h) {
    render::Image img(w, h, 12, 14, 20);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const double e = err[size_t(y) * size_t(w) + size_t(x)];
            if (e < 0) continue;
            // 0 black, 1 texel red, 4 yellow, 16 and more white (log2 scale)
            const double t = std::min(1.0, std::max(0.0, std::log2(1.0 + e) / std::log2(17.0)));
            uint8_t* p = img.at(x, y);
            p[0] = uint8_t(std::lround(255 * std::min(1.0, 3 * t)));
            p[1] = uint8_t(std::lround(255 * std::min(1.0, std::max(0.0, 3 * t - 1))));
            p[2] = uint8_t(std::lround(255 * std::min(1.0, std::max(0.0, 3 * t - 2))));
        }
    }
    return img;
}
}  // namespace

void report_parallax_iterations(const std::vector<methods::IterRow>& rows, int cap, methods_cli::DocTables* doc) {
    std::string t = strf(
        "| map | elevation | Kaneko | Welsh | paper | fetches | other / cap | paper from the top | fetches | "
        "other / cap | f' outside (0, 2) |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const auto& r : rows) {
        t += strf("| %s | %g° | %s | %s | %s | %.1f | %.1f / %.1f %% | %s | %.1f | %.1f / %.1f %% | %.1f %% |\n",
                  r.map.c_str(), r.elevation, mp(r.kaneko).c_str(), mp(r.welsh).c_str(), mp(r.paper).c_str(),
                  r.paper.fetches, 100 * r.paper_other, 100 * (1 - r.paper.converged), mp(r.top).c_str(), r.top.fetches,
                  100 * r.top_other, 100 * (1 - r.top.converged), 100 * r.bad_slope);
    }
    std::printf("1. The paper's iteration (cap %d) from the polygon (t0 = 0, as printed) and from the slab's top\n"
                "   (t0 = s / Vh), beside Kaneko and Welsh; mean / 99th percentile error in texels. Fetches: mean\n"
                "   height fetches. Other: converged more than a texel from the nearest intersection; cap: not\n"
                "   converged. f' outside (0, 2): at the nearest intersection f'(t*) = Vh - s grad(h).V(u, v), where\n"
                "   the iteration cannot converge:\n\n%s\n",
                cap, t.c_str());
    doc->add("parallax-iteration", t);
    std::string fx = "| map | elevation | paper: double | fixed point | from the top: double | fixed point |\n"
                     "|---|---|---|---|---|---|\n";
    for (const auto& r : rows) {
        fx += strf("| %s | %g° | %s | %s | %s | %s |\n", r.map.c_str(), r.elevation, mp(r.paper).c_str(),
                   mp(r.paper_fixed).c_str(), mp(r.top).c_str(), mp(r.top_fixed).c_str());
    }
    std::printf("2. The same in rtl/parallax_iter.v's arithmetic (bit-exact model: 8-bit heights, nearest texel,\n"
                "   the host's start point for the top), mean / 99th percentile error in texels:\n\n%s\n",
                fx.c_str());
    doc->add("parallax-fixed", fx);
}

void report_parallax_sweep(const methods::Sweep& sw, methods_cli::DocTables* doc) {
    std::printf("3. Error against the height fetches spent, at equal budgets F (the iterations stop earlier at the\n"
                "   threshold: their mean fetches are below F). Divisions: per fragment, besides the fetches.\n\n");
    for (double el : sw.elevations) {
        for (const auto& map : sw.maps) {
            std::string t = "| method | divisions |";
            for (int b : sw.budgets) t += strf(" F = %d |", b);
            t += "\n|---|---|";
            for (size_t k = 0; k < sw.budgets.size(); ++k) t += "---|";
            t += "\n";
            for (methods::Pm m : sw.methods) {
                t += strf("| %s | %d |", methods::pm_info(m).key, methods::pm_info(m).divisions);
                for (int b : sw.budgets) t += strf(" %.2f |", sw.at(map, el, m, b).e.mean);
                t += "\n";
            }
            for (methods::Pm m : sw.methods) {
                if (!methods::pm_info(m).iterative) continue;
                t += strf("| %s: mean fetches | |", methods::pm_info(m).key);
                for (int b : sw.budgets) t += strf(" %.2f |", sw.at(map, el, m, b).e.fetches);
                t += "\n";
            }
            std::printf("Mean error (texels), %s, camera at %g deg:\n\n%s\n",
                        map == "all" ? "all maps pooled" : ("map " + map).c_str(), el, t.c_str());
            if (map == "all") doc->add("parallax-mean-" + el_name(el), t);
        }
        // the tails at a few budgets, pooled
        std::string t = "| method | F | mean fetches | mean | p95 | p99 | max | > 1 texel | >= 10 texels |\n"
                        "|---|---|---|---|---|---|---|---|---|\n";
        for (int b : {4, 8, 16}) {
            if (std::find(sw.budgets.begin(), sw.budgets.end(), b) == sw.budgets.end()) continue;
            for (methods::Pm m : sw.methods) {
                const methods::ErrSummary& e = sw.at("all", el, m, b).e;
                t += strf("| %s | %d | %.2f | %.2f | %.2f | %.2f | %.1f | %.2f %% | %.2f %% |\n", methods::pm_info(m).key,
                          b, e.fetches, e.mean, e.p95, e.p99, e.max, 100 * e.miss1, 100 * e.miss10);
            }
        }
        std::printf("The error tails, all maps pooled, camera at %g deg (texels; shares of fragments):\n\n%s\n", el,
                    t.c_str());
        doc->add("parallax-tails-" + el_name(el), t);
    }
    // README's summary: mean error at 4, 8 and 16 fetches, pooled, both elevations
    {
        std::string t = "| method (all maps, mean error in texels) |";
        std::string sep = "|---|";
        std::vector<std::pair<double, int>> cols;
        for (double el : sw.elevations) {
            for (int b : {4, 8, 16}) {
                if (std::find(sw.budgets.begin(), sw.budgets.end(), b) == sw.budgets.end()) continue;
                cols.emplace_back(el, b);
                t += strf(" %g°, F = %d |", el, b);
                sep += "---|";
            }
        }
        t += "\n" + sep + "\n";
        for (methods::Pm m : sw.methods) {
            if (m == methods::Pm::welsh || m == methods::Pm::steep) continue;
            t += strf("| %s |", methods::pm_info(m).key);
            for (const auto& c : cols) t += strf(" %.2f |", sw.at("all", c.first, m, c.second).e.mean);
            t += "\n";
        }
        doc->add("parallax-summary", t);
    }
    // per map at F = 8: mean / p99
    if (std::find(sw.budgets.begin(), sw.budgets.end(), 8) != sw.budgets.end()) {
        std::string t = "| method |";
        std::string sep = "|---|";
        for (double el : sw.elevations) {
            for (const auto& map : sw.maps) {
                if (map == "all") continue;
                t += strf(" %s %g° |", map.c_str(), el);
                sep += "---|";
            }
        }
        t += "\n" + sep + "\n";
        for (methods::Pm m : sw.methods) {
            t += strf("| %s |", methods::pm_info(m).key);
            for (double el : sw.elevations) {
                for (const auto& map : sw.maps) {
                    if (map != "all") t += " " + mp(sw.at(map, el, m, 8).e) + " |";
                }
            }
            t += "\n";
        }
        std::printf("Per map at F = 8 fetches, mean / 99th percentile error (texels):\n\n%s\n", t.c_str());
        doc->add("parallax-maps-8", t);
    }
}

void report_parallax_rtl(const std::vector<methods::ThroughputCell>& cells, uint64_t fragments, methods_cli::DocTables* doc) {
    std::string t = "| memory latency (clocks) | SLOTS = 1 | SLOTS = 4 | SLOTS = 16 |\n|---|---|---|---|\n";
    uint64_t bad = 0;
    for (size_t k = 0; k < cells.size(); k += 3) {
        t += strf("| %d |", cells[k].latency);
        for (size_t j = k; j < k + 3 && j < cells.size(); ++j) {
            t += strf(" %.3f |", double(cells[j].steps) / double(cells[j].cycles));
            bad += cells[j].mismatches;
        }
        t += "\n";
    }
    std::printf("4. rtl/parallax_iter.v (Verilated), %llu fragments of the first map at 30 deg from the slab's top:\n"
                "   steps per clock against the memory's latency and the number of fragments in flight (SLOTS);\n"
                "   results differing from the model iterate_fixed: %llu\n\n%s\n",
                (unsigned long long)fragments, (unsigned long long)bad, t.c_str());
    doc->add("parallax-rtl", t + strf("\nResults differing from the bit-exact model: %llu of %llu per run.\n",
                                      (unsigned long long)bad, (unsigned long long)fragments));
}

void plot_parallax_sweep(const methods::Sweep& sw, const std::string& out_dir) {
    std::string names;
    for (methods::Pm m : sw.methods) names += std::string(names.empty() ? "" : " ") + methods::pm_info(m).key;
    for (double el : sw.elevations) {
        for (const auto& map : sw.maps) {
            const std::string base = strf("fetches_%s_%g", map.c_str(), el);
            std::string dat = "# per method (one gnuplot index each): F, mean fetches, mean, p95, p99, max, "
                              "% > 1 texel, % >= 10 texels\n";
            for (methods::Pm m : sw.methods) {
                dat += strf("# %s\n", methods::pm_info(m).key);
                for (int b : sw.budgets) {
                    const methods::ErrSummary& e = sw.at(map, el, m, b).e;
                    dat += strf("%d %.4f %.5f %.5f %.5f %.5f %.4f %.4f\n", b, e.fetches, e.mean, e.p95, e.p99, e.max,
                                100 * e.miss1, 100 * e.miss10);
                }
                dat += "\n\n";
            }
            methods_cli::write_text(out_dir + "/" + base + ".dat", dat);
            const std::string d = out_dir + "/" + base + ".dat";
            const std::string gp = strf(
                "set terminal pngcairo size 1500,460 font ',10'\nset output '%s/%s.png'\n"
                "names = '%s'\ncolors = '#1f77b4 #ff7f0e #2ca02c #d62728 #9467bd #8c564b #e377c2 #7f7f7f #bcbd22 #17becf #000000'\n"
                "set multiplot layout 1,3 title 'parallax, map %s, camera at %g deg: error against "
                "mean height fetches'\nset grid\nset logscale x 2\nset xrange [0.9:40]\nset xlabel 'mean height "
                "fetches'\nset key outside bottom center maxrows 3 font ',8'\n"
                "set logscale y\nset ylabel 'texels'\nset title 'mean error'\n"
                "plot for [i=1:words(names)] '%s' index (i-1) u 2:(max($3,0.001)) w lp pt 7 ps 0.5 lc rgb word(colors, i) t word(names, i)\n"
                "set title '99th percentile'\n"
                "plot for [i=1:words(names)] '%s' index (i-1) u 2:(max($5,0.001)) w lp pt 7 ps 0.5 lc rgb word(colors, i) t word(names, i)\n"
                "unset logscale y\nset ylabel '%%'\nset title 'fragments more than 1 texel off'\n"
                "plot for [i=1:words(names)] '%s' index (i-1) u 2:7 w lp pt 7 ps 0.5 lc rgb word(colors, i) t word(names, i)\n"
                "unset multiplot\n",
                out_dir.c_str(), base.c_str(), names.c_str(), map.c_str(), el, d.c_str(), d.c_str(), d.c_str());
            if (!methods_cli::run_gnuplot(out_dir, base, "max(a,b) = a > b ? a : b\n" + gp)) {
                throw std::runtime_error("gnuplot failed (is gnuplot installed?)");
            }
        }
    }
    std::printf("plots: %s/fetches_MAP_ELEVATION.png (and .dat)\n", out_dir.c_str());
}

void render_parallax_pictures(const std::vector<methods::HeightMap>& maps, const ParallaxOptions& opt) {
    using methods::Pm;
    for (const auto& m : maps) {
        methods::QuadView q;
        q.s = opt.setup.depth;
        q.threshold = opt.setup.thr();
        q.budget = opt.cap;
        std::vector<double> err_p, err_t;
        const render::Image none = methods::render_quad(m, q, Pm::none);
        const render::Image k = methods::render_quad(m, q, Pm::kaneko);
        const render::Image p = methods::render_quad(m, q, Pm::paper, &err_p);
        const render::Image t = methods::render_quad(m, q, Pm::paper_top, &err_t);
        const render::Image ex = methods::render_quad(m, q, Pm::exact);
        const render::Image ep = error_ramp(err_p, q.width, q.height), et = error_ramp(err_t, q.width, q.height);
        const std::string cap = "cap " + std::to_string(opt.cap);
        const render::Image panel = render::make_panel(
            {{&none, "normal mapping", "no offset"},
             {&k, "Kaneko", "h (Vu, Vv) / Vh"},
             {&p, "paper", "start t = 0, " + cap},
             {&t, "paper", "start at top, " + cap},
             {&ex, "exact", "nearest intersection"},
             {&ep, "error: paper", "1 / 4 / 16 texels"},
             {&et, "error: from the top", "1 / 4 / 16 texels"}},
            "Companion paper C: parallax mapping, height map " + m.name + ", camera at " +
                std::to_string(int(q.elevation_deg)) + " deg");
        render::write_png(opt.out_dir + "/parallax_" + m.name + ".png", panel);
    }
    std::printf("images: %s/parallax_MAP.png\n", opt.out_dir.c_str());
}

}  // namespace spec
