// report_normalize.cpp - specsim normalize's tables and plots (cmd_normalize.h).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>

#include "cmd_normalize.h"
#include "methods_util.h"
#include "raster.h"
#include "scenes.h"

namespace spec {

using methods_cli::pct;
using methods_cli::strf;

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;
using ull = unsigned long long;

std::string ops_str(const methods::OpClass& c, double per) {
    return strf("%.2f / %.2f / %.2f / %.2f / %.2f / %.2f", double(c.add) / per, double(c.mul) / per, double(c.div) / per,
                double(c.sqrt) / per, double(c.rsqrt) / per, double(c.trig) / per);
}

// Per pixel of the frame: everything the vectors cost (the per-span setup spread over the pixels).
double cost_per_pixel(const methods::NormRow& r) {
    methods::OpClass all = r.ops.span;
    all += r.ops.pixel;
    return all.weighted() / double(std::max<uint64_t>(1, r.pixels()));
}
}  // namespace

void report_normalize_figures(const methods::NormBounds& b, const std::string& out_dir, methods_cli::DocTables* doc) {
    std::string t = "| psi | d_1/2 | d_1/4 | d_1/8 | d_1/2 / d_1/4 | d_1/4 / d_1/8 | the paper's series for d_1/2 / d_1/4 | "
                    "z recursion error (4 levels) |\n|---|---|---|---|---|---|---|---|\n";
    for (double p : {5.0, 10.0, 16.0, 16.2, 20.0, 30.0, 32.0, 32.5, 45.0, 60.0, 90.0, 120.0, 150.0, 180.0}) {
        const double psi = p * kDeg;
        const double d1 = methods::deviation(psi, 1), d2 = methods::deviation(psi, 2), d3 = methods::deviation(psi, 3);
        const double series = 4 - psi * psi / 16 + std::pow(psi, 4) / 3072 - std::pow(psi, 6) / 1474560;
        double zerr = 0;
        for (int i = 1; i <= 4; ++i) {
            zerr = std::max(zerr, std::fabs(methods::z_level(psi, i) - 2 * std::cos(psi / std::ldexp(1.0, i))));
        }
        t += strf("| %g° | %.4f %% | %.4f %% | %.5f %% | %.4f | %.4f | %.4f | %.0e |\n", p, 100 * d1, 100 * d2, 100 * d3,
                  d1 / d2, d2 / d3, series, zerr < 1e-15 ? 1e-15 : zerr);
    }
    std::printf("1. The paper's figures recomputed. d_(1/2^i) = 1 - cos(psi / 2^i) (eq. 2): the length deficit of the\n"
                "   unnormalized average at halving level i, psi the angle between the span's end normals; z by the\n"
                "   recursion z_(1/2^(i+1)) = sqrt(2 + z_(1/2^i)) (eq. 1) against 2 cos(psi / 2^(i+1)) (errors below\n"
                "   1e-15 printed as 1e-15):\n\n%s\n", t.c_str());
    doc->add("normalize-figures", t);
    std::string dat2, dat3;
    double rmin = 10, rmin90 = 10, rmax = 0;
    for (int k = 1; k <= 18000; ++k) {
        const double psi = k * 0.01 * kDeg;
        const double r = methods::deviation(psi, 1) / methods::deviation(psi, 2);
        rmin = std::min(rmin, r);
        rmax = std::max(rmax, r);
        if (k <= 9000) rmin90 = std::min(rmin90, r);
        if (k % 50 == 0) {
            dat2 += strf("%g %.6f %.6f\n", k * 0.01, r, methods::deviation(psi, 2) / methods::deviation(psi, 3));
            dat3 += strf("%g %.6f\n", k * 0.01, 100 * methods::deviation(psi, 1));
        }
    }
    std::string c = "| the paper's claim | recomputed |\n|---|---|\n";
    c += strf("| d is 1 %% at ψ = 16° and 4 %% at 32° | %.3f %% at 16°, %.3f %% at 32°; d reaches 1 %% at %.2f° and 4 %% at "
              "%.2f° |\n",
              100 * methods::deviation(16 * kDeg, 1), 100 * methods::deviation(32 * kDeg, 1),
              methods::angle_for_deviation(0.01) / kDeg, methods::angle_for_deviation(0.04) / kDeg);
    c += strf("| largest d is 0.293, \"at cos ψ → 0\" | %.4f at ψ = 90°; for ψ > 90° d grows to %.3f at 180° |\n",
              methods::deviation(90 * kDeg, 1), methods::deviation(180 * kDeg, 1));
    c += strf("| d shrinks 3.4 to 4 times a level | d_1/2 / d_1/4 = 4 cos²(ψ/8): %.3f (at 180°) to %.4f; %.3f to 4 for "
              "ψ ≤ 90° |\n",
              rmin, rmax, rmin90);
    std::string stop;
    for (unsigned n : {1u, 10u, 100u, 1000u}) {
        stop += strf("%s%.2g° (n = %u)", stop.empty() ? "" : ", ", std::acos(methods::specular_cos_bound(b.specular, n)) / kDeg, n);
    }
    c += strf("| specular stop: cos χ ≥ 2(1 − δs)^(2/n) − 1 | at δs = %.2g: χ ≤ %s |\n", b.specular, stop.c_str());
    std::printf("%s\n", c.c_str());
    doc->add("normalize-claims", c);
    if (!out_dir.empty()) {
        methods_cli::write_text(out_dir + "/fig2.dat", dat2);
        methods_cli::write_text(out_dir + "/fig3.dat", dat3);
        const std::string gp =
            "set terminal pngcairo size 640,420 font ',10'\n"
            "set grid\nset key top right\n"
            "set output '" + out_dir + "/fig2.png'\n"
            "set title 'Fig. 2 recomputed: d_{1/2^i} / d_{1/2^{i+1}} against psi'\n"
            "set xlabel 'psi, degrees'\nset ylabel 'ratio'\nset xrange [0:180]\n"
            "plot '" + out_dir + "/fig2.dat' u 1:2 w l lw 2 t 'd_{1/2} / d_{1/4}', '' u 1:3 w l lw 2 t 'd_{1/4} / d_{1/8}'\n"
            "set output '" + out_dir + "/fig3.png'\n"
            "set title 'Fig. 3 recomputed: largest relative diffuse error d_{1/2} against psi'\n"
            "set ylabel 'd_{1/2}, %'\nset key top left\n"
            "set arrow from 16.2,0 to 16.2,1 nohead dt 2\nset arrow from 0,1 to 16.2,1 nohead dt 2\n"
            "set arrow from 32.5,0 to 32.5,4 nohead dt 2\nset arrow from 0,4 to 32.5,4 nohead dt 2\n"
            "plot '" + out_dir + "/fig3.dat' u 1:2 w l lw 2 t '1 - cos(psi/2)'\n";
        if (!methods_cli::run_gnuplot(out_dir, "figs", gp)) throw std::runtime_error("gnuplot failed (is gnuplot installed?)");
    }
}

void report_normalize_rows(const std::vector<methods::NormRow>& rows, methods_cli::DocTables* doc) {
    std::string w = "| scene (triangles) | method | per pixel: add / mul / div / sqrt / rsqrt / trig | per span: add / mul / "
                    "div / sqrt / rsqrt / trig | cost per pixel | sqrt + div + rsqrt per frame |\n"
                    "|---|---|---|---|---|---|\n";
    std::string e = "| scene | method | max 1 − \\|N\\| | max rel. error vs full: diffuse / specular | image vs full: "
                    "max levels / pixels changed |\n|---|---|---|---|---|\n";
    for (const auto& r : rows) {
        const double px = double(std::max<uint64_t>(1, r.pixels())), sp = double(std::max<uint64_t>(1, r.spans()));
        methods::OpClass all = r.ops.span;
        all += r.ops.pixel;
        w += strf("| %s (%llu) | %s | %s | %s | %.1f | %llu |\n", r.scene.c_str(), ull(r.triangles),
                  methods::norm_mode_name(r.mode), ops_str(r.ops.pixel, px).c_str(), ops_str(r.ops.span, sp).c_str(),
                  cost_per_pixel(r), ull(all.div + all.sqrt + all.rsqrt));
        e += strf("| %s | %s | %.2e | %.3f %% / %.3f %% | %d / %llu |\n", r.scene.c_str(), methods::norm_mode_name(r.mode),
                  r.max_deficit, 100 * r.rel_diffuse, 100 * r.rel_specular, r.image_max, ull(r.image_differing));
    }
    std::printf("Operations for the vectors (N and H), counted as each method runs: per pixel of the spans, per span\n"
                "(setup and the two ends), and their weighted sum per pixel (add, mul 1; div, sqrt, rsqrt 4; trig: acos,\n"
                "sin, cos 8):\n\n%s\n", w.c_str());
    doc->add("normalize-cost", w);
    std::printf("Errors against classic Phong (full: normalize(lerp) at every pixel; the relative errors where its\n"
                "diffuse term is >= 0.05 and its specular term >= 1 level of 255):\n\n%s\n", e.c_str());
    doc->add("normalize-error", e);
    // the bounds: adaptive against halving (the same directions normalized)
    std::string bd = "| scene | max 1 − \\|N\\| | max rel. error vs halving: diffuse / specular | image vs halving "
                     "(levels) |\n|---|---|---|---|\n";
    for (const auto& r : rows) {
        if (r.mode != methods::NormMode::adaptive) continue;
        bd += strf("| %s | %.3f %% | %.3f %% / %.3f %% | %d |\n", r.scene.c_str(), 100 * r.max_deficit, 100 * r.rel_diffuse_h,
                   100 * r.rel_specular_h, r.image_max_h);
    }
    std::printf("Adaptive against halving (what its bounds speak of):\n\n%s\n", bd.c_str());
    doc->add("normalize-bounds", bd);
    // the operation-count model of the paper's speed-up claim
    const double phong = methods::phong_pixel_ops().weighted();
    std::string m = strf("| scene | full: vectors + shading per pixel | adaptive | adaptive saves | recurrence saves | "
                         "sqrt + div per pixel: full → adaptive |\n|---|---|---|---|---|---|\n");
    std::map<std::string, std::map<methods::NormMode, const methods::NormRow*>> by;
    std::vector<std::string> order;
    for (const auto& r : rows) {
        if (by[r.scene].empty()) order.push_back(r.scene);
        by[r.scene][r.mode] = &r;
    }
    for (const auto& s : order) {
        const auto& f = *by[s][methods::NormMode::full];
        const auto& a = *by[s][methods::NormMode::adaptive];
        const auto& rc = *by[s][methods::NormMode::recurrence];
        const double cf = cost_per_pixel(f) + phong, ca = cost_per_pixel(a) + phong, cr = cost_per_pixel(rc) + phong;
        methods::OpClass af = f.ops.span, aa = a.ops.span;
        af += f.ops.pixel;
        aa += a.ops.pixel;
        m += strf("| %s | %.1f | %.1f | %.1f %% | %.1f %% | %.2f → %.2f |\n", s.c_str(), cf, ca, 100 * (1 - ca / cf),
                  100 * (1 - cr / cf), double(af.sqrt + af.div) / double(f.pixels()), double(aa.sqrt + aa.div) / double(a.pixels()));
    }
    std::printf("The paper's \"20-30 %% faster\" as an operation count: vectors plus the rest of a Phong pixel (%.0f:\n"
                "N.L, N.H, pow as exp2(n log2 x), three colour channels), same weights:\n\n%s\n", phong, m.c_str());
    doc->add("normalize-model", m);
}

void plot_normalize_cost(const std::vector<methods::NormRow>& rows, const std::string& out_dir) {
    std::string dat = "# per method (gnuplot index): scene number, cost per pixel, image vs full (levels), rel. specular error %\n";
    std::vector<std::string> scenes;
    for (const auto& r : rows) {
        if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
    }
    std::string names;
    for (methods::NormMode mode : methods::norm_modes()) {
        names += std::string(names.empty() ? "" : " ") + methods::norm_mode_name(mode);
        dat += strf("# %s\n", methods::norm_mode_name(mode));
        for (const auto& r : rows) {
            if (r.mode != mode) continue;
            const size_t si = size_t(std::find(scenes.begin(), scenes.end(), r.scene) - scenes.begin());
            dat += strf("%zu %.4f %d %.6f\n", si, cost_per_pixel(r), r.image_max, 100 * r.rel_specular);
        }
        dat += "\n\n";
    }
    methods_cli::write_text(out_dir + "/cost.dat", dat);
    const std::string gp = strf(
        "set terminal pngcairo size 900,520 font ',10'\nset output '%s/cost.png'\nnames = '%s'\n"
        "set title 'Companion paper B: error against the cost of the unit vectors, every scene (one point per scene)'\n"
        "set grid\nset xlabel 'operations per pixel for N and H (div, sqrt, rsqrt 4; acos, sin, cos 8)'\n"
        "set ylabel 'largest difference from classic Phong (full), levels of 255'\nset key outside right\n"
        "plot for [i=1:words(names)] '%s/cost.dat' index (i-1) u 2:3 w p pt (i+5) ps 1.5 t word(names, i)\n",
        out_dir.c_str(), names.c_str(), out_dir.c_str());
    if (!methods_cli::run_gnuplot(out_dir, "cost", gp)) throw std::runtime_error("gnuplot failed (is gnuplot installed?)");
    std::printf("plots: %s/fig2.png, fig3.png, cost.png; images: panel_SCENE.png\n", out_dir.c_str());
}

void report_normalize_timing(const NormalizeOptions& opt) {
    std::printf("CPU time of the shading loop per frame, ms (this machine, %d runs each, medians; these vary from run\n"
                "to run and are not figures of docs/methods.md):\n\n| scene |", opt.runs);
    for (methods::NormMode m : methods::norm_modes()) std::printf(" %s |", methods::norm_mode_name(m));
    std::printf("\n|---|");
    for (size_t k = 0; k < methods::norm_modes().size(); ++k) std::printf("---|");
    std::printf("\n");
    for (const auto& name : opt.scenes) {
        const render::Scene sc = methods::methods_scene(name);
        const render::Frame fr = render::rasterize(sc, opt.size, opt.size);
        std::printf("| %s |", name.c_str());
        for (methods::NormMode m : methods::norm_modes()) {
            std::vector<double> t;
            for (int k = 0; k < opt.runs; ++k) t.push_back(methods::shade_phong(sc, fr, m, opt.bounds).seconds);
            std::sort(t.begin(), t.end());
            std::printf(" %.2f |", 1e3 * t[t.size() / 2]);
        }
        std::printf("\n");
    }
}

}  // namespace spec
