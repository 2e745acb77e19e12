#include "plots.h"

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "analysis.h"
#include "fileutil.h"
#include "spec_model.h"

namespace spec {
namespace render {

namespace {
constexpr double kPi = 3.14159265358979323846;

void write_text(const std::string& path, const std::string& text) {
    write_atomic(path, [&](const std::string& tmp) {
        std::ofstream o(tmp);
        o << text;
        o.close();
        if (!o) throw InputError("cannot write " + path);
    });
}

// Worst relative error of the fixed-point core (bit-exact model) in the epicentre of n: one span from
// angle 0 to the epicentre's end, `points` intervals, C = 1 - 2^-16; ref = C cos^n at register 8's angle.
double core_q(const Model& m, unsigned n, uint32_t points) {
    const Format& f = m.format();
    const uint32_t craw = (1u << f.c_w) - 1;
    const double c = std::ldexp(double(craw), -f.c_w);
    const double e = epicentre_end(n);
    SpanRegs r{craw, m.quantize_angle(e / points), 0, n, points};
    const std::vector<uint32_t> px = m.span(r);
    const std::vector<int64_t> ang = m.angles(r);
    double q = 0;
    for (size_t i = 0; i < px.size(); ++i) {
        const double x = m.angle_value(ang[i]);
        if (x > e) break;
        const double ref = c * std::pow(std::cos(x), double(n));
        q = std::max(q, std::fabs(m.out_value(px[i]) - ref) / ref);
    }
    return q;
}
}  // namespace

std::string make_plots(const std::string& dir) {
    const Model m;
    const ErrorTable& e = fig10_errors();
    std::ostringstream report;

    // Fig. 5 (the prototype) and the patent's answer to it, against n.
    std::ostringstream d5;
    d5 << "# n  q_prototype_%  q_patent_%  q_core_%   (worst relative error over the epicentre "
          "[0, atan(1/sqrt(n-1))], n = 1: [0, pi/3])\n";
    double proto_max = 0, proto_max_n = 0, proto1 = 0, patent_max = 0, patent_max_n = 0, core_max = 0, core_max_n = 0;
    for (unsigned n = 1; n <= 1000; ++n) {
        const double qp = q_error(n, 2), qk = e.q[n], qc = core_q(m, n, 2000);
        char buf[128];
        std::snprintf(buf, sizeof buf, "%u %.6f %.6f %.6f\n", n, 100 * qp, 100 * qk, 100 * qc);
        d5 << buf;
        if (n == 1) proto1 = qp;
        if (n >= 2 && qp > proto_max) { proto_max = qp; proto_max_n = n; }
        if (qk > patent_max) { patent_max = qk; patent_max_n = n; }
        if (qc > core_max) { core_max = qc; core_max_n = n; }
    }
    write_text(dir + "/fig5.dat", d5.str());

    // Fig. 9: signed relative error against the angle, as a fraction of the epicentre.
    const unsigned ns[] = {1, 3, 10, 100, 1000};
    std::ostringstream d9;
    d9 << "# x = angle / epicentre_end(n); then for n = 1, 3, 10, 100, 1000: prototype_%, patent_% "
          "(signed (approx - cos^n) / cos^n)\n";
    for (int i = 0; i <= 400; ++i) {
        const double x = i / 400.0;
        d9 << x;
        for (unsigned n : ns) {
            const double d = x * epicentre_end(n);
            const double ref = std::pow(std::cos(d), double(n));
            const double c = std::cos(std::sqrt(n / 2.0) * d);
            const double proto = std::sqrt(n / 2.0) * d >= kPi / 2 ? 0.0 : c * c;
            d9 << " " << 100 * (proto - ref) / ref << " " << 100 * (approx(n, k_of_n(n), d) - ref) / ref;
        }
        d9 << "\n";
    }
    write_text(dir + "/fig9.dat", d9.str());

    const std::string gp =
        "# written by specsim plots; gnuplot fig.gp (in this directory) redraws fig5.png and fig9.png\n"
        "set terminal pngcairo size 960,600 font 'sans,11'\n"
        "set output 'fig5.png.tmp'\n"
        "set title 'Fig. 5 redrawn: worst relative error of cos^n(d) approximations in the highlight epicentre'\n"
        "set xlabel 'specular exponent n'\n"
        "set ylabel 'max relative error in [0, atan(1/sqrt(n-1))], %'\n"
        "set logscale xy\n"
        "set xrange [1:1000]\n"
        "set yrange [0.001:100]\n"
        "set format y '%g'\n"
        "set grid\n"
        "set key bottom right box opaque\n"
        "plot 'fig5.dat' u 1:2 w l lw 2 lc rgb '#d62728' t 'prototype (Abbas et al.): cos^2(sqrt(n/2) d)', \\\n"
        "     '' every ::0::0 u 1:2 w p pt 7 ps 1.2 lc rgb '#d62728' notitle, \\\n"
        "     '' u 1:3 w l lw 2 lc rgb '#1f77b4' t 'patent: cos^k(sqrt(n/k) d), k = 1, 2, 4, 16 by Fig. 10', \\\n"
        "     '' u 1:4 w p pt 7 ps 0.25 lc rgb '#2ca02c' t 'patent, fixed-point core (bit-exact model = RTL)', \\\n"
        "     1 w l dt 2 lw 1.5 lc rgb 'black' t 'claim: 1 %', 10 w l dt 3 lw 1.5 lc rgb '#d62728' t '10 %'\n"
        "unset output\n"
        "reset\n"
        "set terminal pngcairo size 1200,520 font 'sans,11'\n"
        "set output 'fig9.png.tmp'\n"
        "set multiplot layout 1,2 title 'Fig. 9 redrawn: relative error against the angle, over the epicentre'\n"
        "set xlabel 'angle d / epicentre end atan(1/sqrt(n-1))   (n = 1: pi/3)'\n"
        "set ylabel 'relative error (approx - cos^n) / cos^n, %'\n"
        "set grid\n"
        "set key top left box opaque\n"
        "set xrange [0:1]\n"
        "set title 'prototype: cos^2(sqrt(n/2) d)'\n"
        "plot for [j=0:4] 'fig9.dat' u 1:(column(2+2*j)) w l lw 2 t sprintf('n = %s', word('1 3 10 100 1000', j+1))\n"
        "set title 'patent: cos^k(sqrt(n/k) d), k by Fig. 10'\n"
        "plot for [j=0:4] 'fig9.dat' u 1:(column(3+2*j)) w l lw 2 t sprintf('n = %s (k = %s)', "
        "word('1 3 10 100 1000', j+1), word('1 4 16 16 16', j+1))\n"
        "unset multiplot\n"
        "unset output\n";
    write_text(dir + "/fig.gp", gp);
    const std::string cmd = "cd '" + dir + "' && gnuplot fig.gp 2>gnuplot.log";
    const int st = std::system(cmd.c_str());
    const int code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    if (code != 0) {
        std::remove((dir + "/fig5.png.tmp").c_str());
        std::remove((dir + "/fig9.png.tmp").c_str());
        if (code == 127) throw std::runtime_error("gnuplot not found (make deps installs gnuplot-nox)");
        throw std::runtime_error("gnuplot failed, see " + dir + "/gnuplot.log");
    }
    for (const char* f : {"fig5.png", "fig9.png"}) {
        const std::string p = dir + "/" + f;
        if (std::rename((p + ".tmp").c_str(), p.c_str()) != 0) throw InputError("cannot write " + p);
    }
    std::remove((dir + "/gnuplot.log").c_str());
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "worst relative error in the epicentre, n = 1..1000:\n"
                  "  prototype cos^2(sqrt(n/2) d): %.2f %% at n = 1, at most %.2f %% for n >= 2 (n = %.0f)\n"
                  "  patent cos^k(sqrt(n/k) d):    at most %.3f %% (n = %.0f)\n"
                  "  fixed-point core:             at most %.3f %% (n = %.0f)\n",
                  100 * proto1, 100 * proto_max, proto_max_n, 100 * patent_max, patent_max_n, 100 * core_max,
                  core_max_n);
    report << buf;
    return report.str();
}

}  // namespace render
}  // namespace spec
