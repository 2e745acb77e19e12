#include "fit.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <tuple>

namespace spec {

namespace {
constexpr double kPi = 3.14159265358979323846;

// Golden-section search for the maximum of f in [a, b].
double golden_max(const std::function<double(double)>& f, double a, double b, int iterations = 60) {
    const double g = (std::sqrt(5.0) - 1.0) / 2.0;
    double c = b - g * (b - a), d = a + g * (b - a);
    double fc = f(c), fd = f(d);
    for (int it = 0; it < iterations; ++it) {
        if (fc > fd) {
            b = d; d = c; fd = fc; c = b - g * (b - a); fc = f(c);
        } else {
            a = c; c = d; fc = fd; d = a + g * (b - a); fd = f(d);
        }
    }
    return std::max(fc, fd);
}

// The relative error e(d) = cos^k(s d) / cos^n(d) - 1 on the epicentre of n, sampled once per n.
class RelError {
public:
    RelError(unsigned n, int k) : n_(n), k_(k), end_(epicentre_end(n)) {
        ref_.resize(kSamples + 1);
        for (int i = 0; i <= kSamples; ++i) ref_[i] = std::pow(std::cos(at(i)), double(n));
    }
    double at(int i) const { return end_ * i / kSamples; }
    double e(double s, double d) const {
        return approx_scaled(k_, s, d) / std::pow(std::cos(d), double(n_)) - 1.0;
    }
    // Largest and smallest e over the epicentre (hi >= 0 >= lo: e(0) = 0).
    void extremes(double s, double* hi, double* lo) const {
        int imax = 0, imin = 0;
        double vmax = 0, vmin = 0;
        for (int i = 1; i <= kSamples; ++i) {
            const double v = approx_scaled(k_, s, at(i)) / ref_[i] - 1.0;
            if (v > vmax) { vmax = v; imax = i; }
            if (v < vmin) { vmin = v; imin = i; }
        }
        auto refine = [&](int i, double sign, double v) {
            if (i == 0) return v;
            const double a = at(std::max(0, i - 1)), b = at(std::min(kSamples, i + 1));
            return sign * std::max(sign * v, golden_max([&](double d) { return sign * e(s, d); }, a, b, 40));
        };
        *hi = refine(imax, 1.0, vmax);
        *lo = refine(imin, -1.0, vmin);
    }

private:
    static constexpr int kSamples = 256;
    unsigned n_;
    int k_;
    double end_;
    std::vector<double> ref_;
};
}  // namespace

double epicentre_end(unsigned n) {
    if (n == 0) return kPi / 2.0;
    if (n == 1) return kPi / 3.0;
    return std::atan(1.0 / std::sqrt(static_cast<double>(n) - 1.0));
}

double maximize(const std::function<double(double)>& f, double lo, double hi, int samples) {
    double best = -1.0;
    int bi = 0;
    for (int i = 0; i <= samples; ++i) {
        double x = lo + (hi - lo) * i / samples;
        double v = f(x);
        if (v > best) {
            best = v;
            bi = i;
        }
    }
    const double a = lo + (hi - lo) * std::max(0, bi - 1) / samples;
    const double b = lo + (hi - lo) * std::min(samples, bi + 1) / samples;
    return std::max(best, golden_max(f, a, b));
}

double approx_scaled(int k, double s, double d) {
    const double z = s * std::fabs(d);
    if (z >= kPi / 2.0) return 0.0;
    return std::pow(std::cos(z), k);
}

double rel_error(unsigned n, int k, double s) {
    if (n == 0) return 0.0;
    return maximize(
        [&](double d) {
            const double ref = std::pow(std::cos(d), static_cast<double>(n));
            return std::fabs(approx_scaled(k, s, d) - ref) / ref;
        },
        0.0, epicentre_end(n));
}

double abs_error(unsigned n, int k, double s) {
    if (n == 0) return 0.0;
    return maximize(
        [&](double d) { return std::fabs(approx_scaled(k, s, d) - std::pow(std::cos(d), static_cast<double>(n))); },
        0.0, kPi / 2.0, 4096);
}

double minimax_scale(unsigned n, int k, double* q) {
    if (n == 0 || unsigned(k) == n) {
        if (q) *q = 0.0;
        return n == 0 ? 0.0 : 1.0;
    }
    // e(d; s) falls as s grows (cos^k(s d) does, for s d < pi/2): the largest error hi(s) falls, the most
    // negative one -lo(s) grows, and the minimax scale is where they are equal. Bisection on hi + lo.
    const RelError r(n, k);
    const double s0 = std::sqrt(double(n) / k);
    double a = s0 * 0.9, b = s0 * 1.1, hi, lo;
    for (int widen = 0;; ++widen) {
        double ha, la, hb, lb;
        r.extremes(a, &ha, &la);
        r.extremes(b, &hb, &lb);
        if (ha + la > 0 && hb + lb < 0) break;
        if (widen == 8) throw std::runtime_error("minimax_scale: no bracket for n = " + std::to_string(n));
        a *= 0.8;
        b *= 1.25;
    }
    for (int it = 0; it < 44; ++it) {
        const double m = 0.5 * (a + b);
        r.extremes(m, &hi, &lo);
        (hi + lo > 0 ? a : b) = m;
    }
    const double s = 0.5 * (a + b);
    r.extremes(s, &hi, &lo);
    if (q) *q = std::max(hi, -lo);
    return s;
}

const std::vector<TableFit>& table_fits(const Format& f) {
    const std::vector<int>& ks = f.tables;
    if (ks.empty()) throw std::invalid_argument("the table set is empty");
    for (size_t i = 0; i < ks.size(); ++i) {
        if (ks[i] < 1 || (i > 0 && ks[i] <= ks[i - 1])) {
            throw std::invalid_argument("the table set must be strictly increasing powers k >= 1");
        }
    }
    using Key = std::tuple<Mode, std::vector<int>, int>;
    static std::mutex mu;
    static std::map<Key, std::unique_ptr<std::vector<TableFit>>> cache;
    std::lock_guard<std::mutex> lock(mu);
    auto& slot = cache[Key(f.mode, ks, f.n_w)];
    if (slot) return *slot;

    std::vector<TableFit> fits(size_t(1) << f.n_w);
    const bool fig10 = f.mode == Mode::patent && ks == patent_tables();
    for (unsigned n = 0; n < fits.size(); ++n) {
        TableFit& t = fits[n];
        if (n == 0) {  // scale 0: position 0 of any table is 1.0; the last table, as decoder 10 has it
            t.table = fig10 ? table_of_n(0) : int(ks.size()) - 1;
            t.k = ks[t.table];
            t.scale = 0.0;
            continue;
        }
        if (fig10) {
            t.table = table_of_n(n);
            t.k = ks[t.table];
            t.scale = std::sqrt(double(n) / t.k);
            continue;
        }
        // candidates: the tables next to n
        int below = -1, above = -1;
        for (int i = 0; i < int(ks.size()); ++i) {
            if (ks[i] <= int(n)) below = i;
            if (ks[i] >= int(n) && above < 0) above = i;
        }
        double best = HUGE_VAL;
        for (int i : {below, above}) {
            if (i < 0) continue;
            double q, s;
            if (f.mode == Mode::tuned) {
                s = minimax_scale(n, ks[i], &q);
            } else {
                s = std::sqrt(double(n) / ks[i]);
                q = rel_error(n, ks[i], s);
            }
            if (q < best) {
                best = q;
                t.table = i;
                t.k = ks[i];
                t.scale = s;
            }
        }
    }
    slot.reset(new std::vector<TableFit>(std::move(fits)));
    return *slot;
}

}  // namespace spec
