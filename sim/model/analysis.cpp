#include "analysis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <tuple>

#include "fit.h"
#include "spec_format.h"

namespace spec {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

double approx(unsigned n, int k, double d) {
    if (n == 0) return 1.0;
    const double z = std::sqrt(static_cast<double>(n) / k) * std::fabs(d);
    if (z >= kPi / 2.0) return 0.0;
    return std::pow(std::cos(z), k);
}

double q_error(unsigned n, int k) {
    if (n == 0) return 0.0;
    return maximize(
        [&](double d) {
            const double ref = std::pow(std::cos(d), static_cast<double>(n));
            return std::fabs(approx(n, k, d) - ref) / ref;
        },
        0.0, epicentre_end(n));
}

double a_error(unsigned n, int k) {
    if (n == 0) return 0.0;
    return maximize(
        [&](double d) { return std::fabs(approx(n, k, d) - std::pow(std::cos(d), static_cast<double>(n))); },
        0.0, kPi / 2.0, 4096);
}

const ErrorTable& fig10_errors() {
    static const ErrorTable t = [] {
        ErrorTable e;
        for (unsigned n = 0; n < 1024; ++n) {
            e.q.push_back(q_error(n, k_of_n(n)));
            e.a.push_back(a_error(n, k_of_n(n)));
        }
        return e;
    }();
    return t;
}

const ErrorTable& mode_errors(const Format& f) {
    if (f.mode == Mode::patent && f.tables == patent_tables() && f.n_w == Format().n_w) return fig10_errors();
    using Key = std::tuple<Mode, std::vector<int>, int>;
    static std::mutex mu;
    static std::map<Key, std::unique_ptr<ErrorTable>> cache;
    const std::vector<TableFit>& fits = table_fits(f);
    std::lock_guard<std::mutex> lock(mu);
    auto& slot = cache[Key(f.mode, f.tables, f.n_w)];
    if (!slot) {
        slot.reset(new ErrorTable);
        for (unsigned n = 0; n < fits.size(); ++n) {
            slot->q.push_back(rel_error(n, fits[n].k, fits[n].scale));
            slot->a.push_back(abs_error(n, fits[n].k, fits[n].scale));
        }
    }
    return *slot;
}

CoreErrors core_errors(const Model& m, uint32_t points, uint32_t epi_points, const SpanRunner& run) {
    const Format& f = m.format();
    const uint32_t craw = (1u << f.c_w) - 1;
    const double c = std::ldexp(double(craw), -f.c_w);
    const size_t count = size_t(1) << f.n_w;
    CoreErrors e;
    e.rel_in.assign(count, 0.0);
    e.abs_all.assign(count, 0.0);
    for (unsigned n = 0; n < count; ++n) {
        const double end = epicentre_end(n);
        for (int pass = 0; pass < (epi_points ? 2 : 1); ++pass) {
            const uint32_t len = pass == 0 ? points : epi_points;
            const double reach = pass == 0 ? kPi / 2 : end;
            SpanRegs r{craw, m.quantize_angle(reach / double(len)), 0, n, len};
            const std::vector<uint32_t> px = run ? run(r) : m.span(r);
            const std::vector<int64_t> ang = m.angles(r);
            for (size_t i = 0; i < px.size() && i < ang.size(); ++i) {
                const double x = m.angle_value(ang[i]);
                const double ref = c * std::pow(std::max(0.0, std::cos(x)), double(n));
                const double err = std::fabs(m.out_value(px[i]) - ref);
                e.abs_all[n] = std::max(e.abs_all[n], err / c);
                if (x <= end) e.rel_in[n] = std::max(e.rel_in[n], err / ref);
            }
        }
    }
    return e;
}

std::vector<Fig8Row> fig8(double limit, Mode mode) {
    std::vector<Fig8Row> rows;
    for (int k = 1; k <= 16; ++k) {
        Fig8Row r{k, 0, 0, true, 0};
        int last = 0;
        for (int n = 1; n <= 1000; ++n) {
            double q;
            if (mode == Mode::tuned) minimax_scale(unsigned(n), k, &q);
            else q = q_error(unsigned(n), k);
            if (q <= limit) {
                if (r.count == 0) r.n_lo = n;
                else if (n != last + 1) r.contiguous = false;
                r.n_hi = n;
                last = n;
                ++r.count;
            }
        }
        rows.push_back(r);
    }
    return rows;
}

std::string fig8_report(bool all_n, Mode mode) {
    const bool tuned = mode == Mode::tuned;
    static const char* patent[17] = {"",      "1",      "2",       "3..4",    "3..6",    "4..10",
                                     "4..17", "5..33",  "5..105",  "6..1000", "6..1000", "6..1000",
                                     "6..1000", "6..1000", "6..1000", "6..1000", "7..1000"};
    std::ostringstream o;
    char buf[256];
    if (tuned) {
        o << "Fig. 8 with the minimax scale (tuned mode): n in 1..1000 for which cos^k(s d), s the minimax scale\n"
          << "for n and k, stays within 1 % of cos^n(d) over the epicentre [0, atan(1/sqrt(n-1))] (n = 1: [0, pi/3]),\n"
          << "double precision; the patent's column is for s = sqrt(n/k).\n\n";
    } else {
        o << "Fig. 8 recomputed: n in 1..1000 for which cos^k(sqrt(n/k) d) stays within 1 % of cos^n(d)\n"
          << "over the epicentre [0, atan(1/sqrt(n-1))] (n = 1: [0, pi/3]), double precision.\n\n";
    }
    o << "   k | n with q <= 1 % (computed) | patent Fig. 8\n"
      << "-----+----------------------------+--------------\n";
    for (const auto& r : fig8(0.01, mode)) {
        std::string range = r.count == 0 ? "none"
                                         : std::to_string(r.n_lo) + ".." + std::to_string(r.n_hi) +
                                               (r.contiguous ? "" : " (with gaps)");
        std::snprintf(buf, sizeof buf, "  %2d | %-26s | %s\n", r.k, range.c_str(), patent[r.k]);
        o << buf;
    }
    Format fmt;
    fmt.mode = mode;
    const ErrorTable& e = mode_errors(fmt);
    struct Range {
        const char* name;
        unsigned lo, hi;
    } ranges[] = {{"n = 1      (k = 1)", 1, 1},       {"n = 2      (k = 2)", 2, 2},
                  {"n = 3..6   (k = 4)", 3, 6},       {"n = 7..1000 (k = 16)", 7, 1000},
                  {"n = 1001..1023 (k = 16)", 1001, 1023}, {"n = 1..1000 (all)", 1, 1000}};
    o << (tuned ? "\nTuned mode (tables k = 1, 2, 4, 16, minimax scale and table per n): worst errors per BRDF range\n"
                : "\nFig. 10 rule (k = 1, 2, 4, 16): worst errors per BRDF range\n")
      << "  range                    | q(n) max rel. in epicentre (at n) | a(n) max abs. on [0, pi/2] (at n)\n"
      << "  -------------------------+-----------------------------------+----------------------------------\n";
    for (const auto& r : ranges) {
        unsigned qn = r.lo, an = r.lo;
        for (unsigned n = r.lo; n <= r.hi; ++n) {
            if (e.q[n] > e.q[qn]) qn = n;
            if (e.a[n] > e.a[an]) an = n;
        }
        std::snprintf(buf, sizeof buf, "  %-24s | %8.4f %%  (n = %4u)             | %8.4f %%  (n = %4u)\n", r.name,
                      100.0 * e.q[qn], qn, 100.0 * e.a[an], an);
        o << buf;
    }
    unsigned over = 0;
    for (unsigned n = 1; n <= 1000; ++n) over += e.q[n] > 0.01;
    unsigned worst_n_from_6 = 6;
    for (unsigned n = 6; n <= 1000; ++n) if (e.q[n] > e.q[worst_n_from_6]) worst_n_from_6 = n;
    std::snprintf(buf, sizeof buf,
                  "\n%s: q <= 1 %% for n = 1..1000 -> %u value(s) of n exceed 1 %%;\n"
                  "                 q <= 0.6 %% for n >= 6    -> worst for n >= 6 is %.4f %% at n = %u.\n",
                  tuned ? "Patent's claims, tuned" : "Patent's claims", over, 100.0 * e.q[worst_n_from_6], worst_n_from_6);
    o << buf;
    if (all_n) {
        o << "\n   n   k   q(n) %     a(n) %   epicentre end (rad)\n";
        for (unsigned n = 0; n < 1024; ++n) {
            std::snprintf(buf, sizeof buf, "%4u %3d %9.5f %9.5f %10.6f\n", n, table_fits(fmt)[n].k, 100.0 * e.q[n],
                          100.0 * e.a[n], epicentre_end(n));
            o << buf;
        }
    }
    return o.str();
}

}  // namespace spec
