#include "analysis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>
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

double pow_approx(const Format& f, unsigned n, double d) {
    if (n == 0) return 1.0;
    const double a = std::ldexp(std::fabs(d), f.ang_frac);
    const double k = double(f.pow_half_pi());
    if (a > k) return 0.0;
    const int side = a >= std::ldexp(1.0, f.ang_frac) ? 1 : 0;
    const double t = side ? k - a : a;
    const int ns = 1 << f.pow_seg_w;
    int seg = ns - 1;
    for (int j = 0; j < ns - 1; ++j) {
        if (t >= std::ldexp(1.0, f.ang_frac - 1 - j)) {
            seg = j;
            break;
        }
    }
    const double start = pow_grid_t(f, seg, 0), step = pow_grid_t(f, seg, 1) - start;
    const double x = (t - start) / step;
    const double i = std::min(std::floor(x), double((1 << f.pow_idx_w) - 1));
    const double fr = x - i;
    const double l = (1 - fr) * pow_log_entry(f, side, seg, i) + fr * pow_log_entry(f, side, seg, i + 1);
    return std::exp2(-double(n) * l);
}

namespace {
// pow mode's errors in double precision (pow_approx): every n, at the ends and the quarter points of every
// interval of the log table's grid
ErrorTable pow_mode_errors(const Format& f) {
    ErrorTable e;
    std::vector<double> ds;
    const int ns = 1 << f.pow_seg_w, m = 1 << f.pow_idx_w;
    for (int side = 0; side < 2; ++side) {
        for (int seg = 0; seg < ns; ++seg) {
            for (int i = 0; i < m; ++i) {
                for (double q : {0.0, 0.25, 0.5, 0.75}) {
                    const double d = pow_angle(f, side, pow_grid_t(f, seg, i + q));
                    if (d >= 0 && d <= kPi / 2) ds.push_back(d);
                }
            }
        }
    }
    for (unsigned n = 0; n < (1u << f.n_w); ++n) {
        double q = 0, a = 0;
        const double end = epicentre_end(n);
        for (double d : ds) {
            const double ref = std::pow(std::cos(d), double(n));
            const double err = std::fabs(pow_approx(f, n, d) - ref);
            a = std::max(a, err);
            if (d <= end && ref > 0) q = std::max(q, err / ref);
        }
        e.q.push_back(q);
        e.a.push_back(a);
    }
    return e;
}
}  // namespace

PowExhaustive pow_exhaustive(const Model& m, unsigned threads) {
    const Format& f = m.format();
    if (!f.pow()) throw std::invalid_argument("pow_exhaustive: the model is not in pow mode");
    const int af = f.ang_frac, ns = 1 << f.pow_seg_w, iw = f.pow_idx_w, fa = f.pow_frac;
    const int low = af - 1 - iw - fa;   // the fraction's LSB in the normalized t (Format::validate: >= 0)
    const int64_t k = f.pow_half_pi();
    const unsigned count = 1u << f.n_w;
    struct Part {
        std::vector<double> abs_err, abs_at, rel_in;
        uint64_t positions = 0;
    };
    const uint32_t entries = uint32_t(2) << (f.pow_seg_w + iw);   // (side, segment, entry)
    auto work = [&](uint32_t from, uint32_t to, Part* out) {
        out->abs_err.assign(count, 0.0);
        out->abs_at.assign(count, 0.0);
        out->rel_in.assign(count, 0.0);
        std::vector<double> end(count);
        for (unsigned n = 0; n < count; ++n) end[n] = epicentre_end(n);
        for (uint32_t e = from; e < to; ++e) {
            PowPos p;
            p.side = int(e >> (f.pow_seg_w + iw));
            p.seg = int((e >> iw) & ((1u << f.pow_seg_w) - 1));
            p.idx = e & ((1u << iw) - 1);
            const int sh = std::min(p.seg, ns - 2);
            const uint64_t hidden = p.seg < ns - 1 ? uint64_t(1) << (af - 1) : 0;
            for (uint32_t fr = 0; fr < (1u << fa); ++fr) {
                p.frac = fr;
                const uint64_t u_lo = hidden + (uint64_t(p.idx) << (af - 1 - iw)) + (uint64_t(fr) << low);
                const uint64_t u_hi = u_lo + (uint64_t(1) << low) - 1;
                int64_t t_lo = int64_t((u_lo + (uint64_t(1) << sh) - 1) >> sh), t_hi = int64_t(u_hi >> sh);
                if (p.side == 1) t_hi = std::min<int64_t>(t_hi, k - (int64_t(1) << af));   // 1 rad <= a <= K
                if (t_lo > t_hi) continue;
                ++out->positions;
                const double d1 = pow_angle(f, p.side, double(t_lo)), d2 = pow_angle(f, p.side, double(t_hi));
                const double c1 = std::cos(d1), c2 = std::cos(d2);
                uint32_t shift;
                const uint32_t v = m.pow_log(p, &shift);
                double r1 = 1.0, r2 = 1.0;
                for (unsigned n = 0; n < count; ++n) {
                    bool ovf, big;
                    const uint32_t b = m.pow_exp(m.pow_y(v, shift, n, &ovf), &big);
                    const double val = ovf || big ? 0.0 : std::ldexp(double(b), -f.tbl_frac);
                    const double e1 = std::fabs(val - r1), e2 = std::fabs(val - r2);
                    if (e1 > out->abs_err[n]) {
                        out->abs_err[n] = e1;
                        out->abs_at[n] = d1;
                    }
                    if (e2 > out->abs_err[n]) {
                        out->abs_err[n] = e2;
                        out->abs_at[n] = d2;
                    }
                    if (d1 <= end[n]) out->rel_in[n] = std::max(out->rel_in[n], e1 / r1);
                    if (d2 <= end[n]) out->rel_in[n] = std::max(out->rel_in[n], e2 / r2);
                    r1 *= c1;
                    r2 *= c2;
                }
            }
        }
    };
    threads = std::max(1u, threads);
    std::vector<Part> parts(threads);
    std::vector<std::thread> pool;
    for (unsigned i = 0; i < threads; ++i) {
        pool.emplace_back(work, uint32_t(uint64_t(entries) * i / threads), uint32_t(uint64_t(entries) * (i + 1) / threads),
                          &parts[i]);
    }
    for (std::thread& t : pool) t.join();
    PowExhaustive r;
    r.abs_err.assign(count, 0.0);
    r.abs_at.assign(count, 0.0);
    r.rel_in.assign(count, 0.0);
    for (const Part& p : parts) {
        r.positions += p.positions;
        for (unsigned n = 0; n < count; ++n) {
            if (p.abs_err[n] > r.abs_err[n]) {
                r.abs_err[n] = p.abs_err[n];
                r.abs_at[n] = p.abs_at[n];
            }
            r.rel_in[n] = std::max(r.rel_in[n], p.rel_in[n]);
        }
    }
    return r;
}

const ErrorTable& mode_errors(const Format& f) {
    if (f.pow()) {
        using PowKey = std::tuple<int, int, int, int>;
        static std::mutex pmu;
        static std::map<PowKey, std::unique_ptr<ErrorTable>> pcache;
        std::lock_guard<std::mutex> lock(pmu);
        auto& slot = pcache[PowKey(f.pow_seg_w, f.pow_idx_w, f.ang_frac, f.n_w)];
        if (!slot) slot.reset(new ErrorTable(pow_mode_errors(f)));
        return *slot;
    }
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

namespace {
// core_errors' spans (angle 0 to pi/2 in `points` intervals and, with epi > 0, 0 to the epicentre's end in `epi`),
// C = 1 - 2^-c_w, every n, and the errors against C cos^n at the angles register 8 holds of the outputs `out`
// gives for a span (each a fraction of 1, one per pixel)
using SpanOutputs = std::function<std::vector<double>(const SpanRegs&, const std::vector<int64_t>& angles)>;
CoreErrors span_errors(const Model& m, uint32_t points, uint32_t epi, const SpanOutputs& out) {
    const Format& f = m.format();
    const uint32_t craw = (1u << f.c_w) - 1;
    const double c = std::ldexp(double(craw), -f.c_w);
    const size_t count = size_t(1) << f.n_w;
    CoreErrors e;
    e.rel_in.assign(count, 0.0);
    e.abs_all.assign(count, 0.0);
    for (unsigned n = 0; n < count; ++n) {
        const double end = epicentre_end(n);
        for (int pass = 0; pass < (epi ? 2 : 1); ++pass) {
            const uint32_t len = pass == 0 ? points : epi;
            const double reach = pass == 0 ? kPi / 2 : end;
            SpanRegs r{craw, m.quantize_angle(reach / double(len)), 0, n, len};
            const std::vector<int64_t> ang = m.angles(r);
            const std::vector<double> px = out(r, ang);
            for (size_t i = 0; i < px.size() && i < ang.size(); ++i) {
                const double x = m.angle_value(ang[i]);
                const double ref = c * std::pow(std::max(0.0, std::cos(x)), double(n));
                const double err = std::fabs(px[i] - ref);
                e.abs_all[n] = std::max(e.abs_all[n], err / c);
                if (x <= end) e.rel_in[n] = std::max(e.rel_in[n], err / ref);
            }
        }
    }
    return e;
}
}  // namespace

CoreErrors core_errors(const Model& m, uint32_t points, uint32_t epi_points, const SpanRunner& run) {
    return span_errors(m, points, epi_points, [&](const SpanRegs& r, const std::vector<int64_t>&) {
        const std::vector<uint32_t> px = run ? run(r) : m.span(r);
        std::vector<double> v;
        for (uint32_t p : px) v.push_back(m.out_value(p));
        return v;
    });
}

MaterialLut::MaterialLut(unsigned n_) : n(n_) {
    t.resize(kEntries + 1);
    for (int i = 0; i <= kEntries; ++i) t[i] = std::pow(double(i) / kEntries, double(n));   // pow(0, 0) = 1
    for (int i = 0; i < kEntries; ++i) {
        value.push_back(uint32_t(std::min(4095.0, std::nearbyint(std::ldexp(t[i], kValueBits)))));
        const double d = std::nearbyint(std::ldexp(t[i + 1] - t[i], kDiffFrac));
        diff.push_back(int32_t(std::max(-2048.0, std::min(2047.0, d))));
    }
}

double MaterialLut::value_double(double x) const {
    const double u = std::max(0.0, std::min(1.0, x)) * kEntries;
    const int i = std::min(int(u), kEntries - 1);
    return t[i] + (t[i + 1] - t[i]) * (u - i);
}

uint32_t MaterialLut::pixel_fixed(uint32_t c, double x, int c_w, int out_w) const {
    const uint32_t q = uint32_t(std::nearbyint(std::ldexp(std::max(0.0, std::min(1.0, x)), 16)));   // UQ0.16, 1.0 = 2^16
    const int i = std::min(int(q >> kFracBits), kEntries - 1);
    const int64_t f = int64_t(q) - (int64_t(i) << kFracBits);   // 0 .. 256 (x = 1: the last entry's far end)
    // value (2^-12 units) + diff (2^-11) * f / 2^8, rounded to 2^-12: (2 diff f + 2^7) >> 8
    int64_t v = int64_t(value[i]) + ((2 * int64_t(diff[i]) * f + 128) >> kFracBits);
    v = std::max<int64_t>(0, std::min<int64_t>(4095, v));
    const int sh = c_w + kValueBits - out_w;
    return uint32_t((uint64_t(c) * uint64_t(v) + (uint64_t(1) << (sh - 1))) >> sh);
}

CoreErrors lut_errors(const Model& m, uint32_t points, uint32_t epi, bool fixed) {
    const Format& f = m.format();
    return span_errors(m, points, epi, [&](const SpanRegs& r, const std::vector<int64_t>& ang) {
        const MaterialLut lut(r.n);
        std::vector<double> v;
        for (int64_t a : ang) {
            const double nh = std::max(0.0, std::cos(m.angle_value(a)));
            v.push_back(fixed ? m.out_value(lut.pixel_fixed(r.c, nh, f.c_w, f.out_w))
                              : m.out_value(r.c) * lut.value_double(nh));
        }
        return v;
    });
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

namespace {
// The table of worst q(n), a(n) per range of n that fig8_report prints
struct NRange {
    const char* name;
    unsigned lo, hi;
};
std::string ranges_table(const ErrorTable& e, const std::vector<NRange>& ranges) {
    std::ostringstream o;
    char buf[256];
    o << "  range                    | q(n) max rel. in epicentre (at n) | a(n) max abs. on [0, pi/2] (at n)\n"
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
    return o.str();
}

// Fig. 8 in pow mode: no table k, no scale; every n from the one log table (docs/pow.md)
std::string fig8_report_pow(bool all_n) {
    Format fmt;
    fmt.mode = Mode::pow;
    const ErrorTable& e = mode_errors(fmt);
    std::ostringstream o;
    char buf[256];
    o << "Fig. 8 in pow mode: no table cos^k and no scale. cos^n(d) = exp2(-n L(d)), L = -log2 cos from one log\n"
      << "table (2 x " << (1 << fmt.pow_seg_w) << " segments x " << (1 << fmt.pow_idx_w)
      << " entries, interpolated), for every n: Fig. 8's question (which n a table k serves within 1 %)\n"
      << "has one answer, n = 0..1023. Below: the approximation in double precision (the log table's linear\n"
      << "interpolation between exact -log2 cos, exact exp2; docs/pow.md), per BRDF range.\n";
    o << "\nPow mode: worst errors per BRDF range\n"
      << ranges_table(e, {{"n = 1", 1, 1}, {"n = 2", 2, 2}, {"n = 3..6", 3, 6}, {"n = 7..1000", 7, 1000},
                          {"n = 1001..1023", 1001, 1023}, {"n = 1..1000 (all)", 1, 1000}});
    unsigned over = 0;
    for (unsigned n = 1; n <= 1000; ++n) over += e.q[n] > 0.01;
    std::snprintf(buf, sizeof buf, "\nPatent's claims, pow mode: q <= 1 %% for n = 1..1000 -> %u value(s) of n exceed 1 %%.\n",
                  over);
    o << buf;
    if (all_n) {
        o << "\n   n   k   q(n) %     a(n) %   epicentre end (rad)\n";
        for (unsigned n = 0; n < 1024; ++n) {
            std::snprintf(buf, sizeof buf, "%4u   - %9.5f %9.5f %10.6f\n", n, 100.0 * e.q[n], 100.0 * e.a[n],
                          epicentre_end(n));
            o << buf;
        }
    }
    return o.str();
}
}  // namespace

std::string fig8_report(bool all_n, Mode mode) {
    if (mode == Mode::pow) return fig8_report_pow(all_n);
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
    o << (tuned ? "\nTuned mode (tables k = 1, 2, 4, 16, minimax scale and table per n): worst errors per BRDF range\n"
                : "\nFig. 10 rule (k = 1, 2, 4, 16): worst errors per BRDF range\n")
      << ranges_table(e, {{"n = 1      (k = 1)", 1, 1}, {"n = 2      (k = 2)", 2, 2}, {"n = 3..6   (k = 4)", 3, 6},
                          {"n = 7..1000 (k = 16)", 7, 1000}, {"n = 1001..1023 (k = 16)", 1001, 1023},
                          {"n = 1..1000 (all)", 1, 1000}});
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
