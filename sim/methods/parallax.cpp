// parallax.cpp - the parallax methods in double precision (parallax.h).
#include "parallax.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace spec {
namespace methods {

namespace {
constexpr double kPi = 3.14159265358979323846;

const PmInfo kInfo[] = {
    {"none", "normal mapping, no offset", 0, false},
    {"kaneko", "Kaneko: s h(P0) / Vh", 1, false},
    {"welsh", "Welsh: offset limiting s h(P0)", 0, false},
    {"welsh-bias", "Welsh with scale and bias (mid-plane)", 1, false},
    {"paper", "the paper: iteration from the polygon", 0, true},
    {"paper-top", "the paper's iteration from the slab's top", 1, true},
    {"premecz", "Premecz: iteration with slope", 1, true},
    {"hybrid", "linear search + the iteration", 1, true},
    {"steep", "steep parallax: linear search", 1, false},
    {"pom", "parallax occlusion: linear + secant", 1, false},
    {"relief", "relief mapping: linear + bisection", 1, false},
    {"interval", "interval mapping: linear + regula falsi", 1, false},
    {"exact", "the exact nearest intersection", 1, false},
};

Hit at_t(double u0, double v0, const View& V, double t, int fetches, bool converged) {
    Hit h;
    h.t = t;
    h.u = u0 + t * V.u;
    h.v = v0 + t * V.v;
    h.fetches = fetches;
    h.converged = converged;
    return h;
}

int refine_steps(int budget) { return std::min(6, budget / 3); }
}  // namespace

const PmInfo& pm_info(Pm m) { return kInfo[int(m)]; }

Pm pm_from_key(const std::string& key) {
    for (int k = 0; k <= int(Pm::exact); ++k) {
        if (key == kInfo[k].key) return Pm(k);
    }
    throw std::invalid_argument("unknown parallax method '" + key + "'");
}

std::vector<Pm> pm_compared() {
    return {Pm::kaneko, Pm::welsh, Pm::welsh_bias, Pm::paper, Pm::paper_top, Pm::premecz, Pm::hybrid,
            Pm::steep,  Pm::pom,   Pm::relief,     Pm::interval};
}

View view_from_angles(double elevation_deg, double azimuth_deg) {
    const double e = elevation_deg * kPi / 180, a = azimuth_deg * kPi / 180;
    return View{std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
}

Hit kaneko(const HeightMap& m, double s, double u0, double v0, const View& V) {
    return at_t(u0, v0, V, s * m.at(u0, v0) / V.h, 1, true);
}

Hit welsh(const HeightMap& m, double s, double u0, double v0, const View& V) {
    return at_t(u0, v0, V, s * m.at(u0, v0), 1, true);
}

Hit welsh_bias(const HeightMap& m, double s, double u0, double v0, const View& V) {
    const double tm = 0.5 * s / V.h;
    return at_t(u0, v0, V, tm + s * (m.at(u0 + tm * V.u, v0 + tm * V.v) - 0.5), 1, true);
}

Hit iterative(const HeightMap& m, double s, double u0, double v0, const View& V, double threshold, int max_iter,
              double t0) {
    // (4)-(5) with hV_0 = t0 Vh: hV_i = hV_(i-1) + d_(i-1) Vh, d_i = s h(P_i) - hV_i, P_(i+1) = P_i + d_i V(u, v)
    double u = u0 + t0 * V.u, v = v0 + t0 * V.v, t = t0, hv = t0 * V.h, d_prev = 0;
    int fetches = 0;
    bool converged = false;
    for (int i = 0; i < max_iter; ++i) {
        hv += d_prev * V.h;
        const double d = s * m.at(u, v) - hv;
        ++fetches;
        if (std::fabs(d) <= threshold) {
            converged = true;
            break;
        }
        u += d * V.u;
        v += d * V.v;
        t += d;
        d_prev = d;
    }
    Hit r;
    r.u = u;
    r.v = v;
    r.t = t;
    r.fetches = fetches;
    r.converged = converged;
    return r;
}

Hit premecz(const HeightMap& m, double s, double u0, double v0, const View& V, double threshold, int max_iter) {
    double t = s / V.h;
    int fetches = 0;
    bool converged = false;
    for (int i = 0; i < max_iter; ++i) {
        const double u = u0 + t * V.u, v = v0 + t * V.v;
        double gu, gv;
        m.gradient(u, v, &gu, &gv);  // the normal map's texel, fetched with the height
        const double d = s * m.at(u, v) - t * V.h;
        ++fetches;
        if (std::fabs(d) <= threshold) {
            converged = true;
            break;
        }
        const double nz = 1.0 / std::sqrt(1.0 + s * s * (gu * gu + gv * gv));
        t += d * nz;
    }
    return at_t(u0, v0, V, t, fetches, converged);
}

Hit hybrid(const HeightMap& m, double s, double u0, double v0, const View& V, double threshold, int budget) {
    const double T = s / V.h;
    const int L = std::max(1, budget / 4);
    double lo = 0, hi = T, f_hi = 0;
    bool hi_known = false;
    int fetches = 0;
    for (int k = 1; k <= L; ++k) {
        const double t = T * (1.0 - double(k) / (L + 1));
        const double f = f_at(m, s, u0, v0, V, t);
        ++fetches;
        if (f <= 0) {
            lo = t;
            break;
        }
        hi = t;
        f_hi = f;
        hi_known = true;
    }
    // the iteration t <- t - f(t) from the bracket's upper end, inside [lo, hi]
    double t = hi, f = f_hi;
    bool have = hi_known, stepped = false, converged = false;
    for (;;) {
        if (!have) {
            if (fetches >= budget) break;
            f = f_at(m, s, u0, v0, V, t);
            ++fetches;
        }
        if (std::fabs(f) <= threshold) {
            converged = true;
            break;
        }
        t = std::min(hi, std::max(lo, t - f));
        have = false;
        stepped = true;
    }
    if (!stepped && !converged) t = 0.5 * (lo + hi);
    return at_t(u0, v0, V, t, fetches, converged);
}

Hit search(const HeightMap& m, double s, double u0, double v0, const View& V, int steps, int refine, bool secant,
           SearchEnd end, bool spend_all) {
    const double T = s / V.h;
    double lo = 0, hi = T, f_lo = 0, f_hi = 0;
    bool lo_known = false, hi_known = false;
    int fetches = 0;
    for (int k = 1; k <= steps; ++k) {
        const double t = T * (1.0 - double(k) / (steps + 1));
        const double f = f_at(m, s, u0, v0, V, t);
        ++fetches;
        if (f <= 0) {
            lo = t, f_lo = f, lo_known = true;
            break;
        }
        hi = t, f_hi = f, hi_known = true;
    }
    // f(hi) > 0 >= f(lo): the secant point lies strictly inside
    auto secant_point = [&] { return hi - f_hi * (hi - lo) / (f_hi - f_lo); };
    if (spend_all) refine = std::max(refine, steps + refine - fetches);  // what the linear search left
    for (int r = 0; r < refine; ++r) {
        const double t = secant && lo_known && hi_known ? secant_point() : 0.5 * (lo + hi);
        const double f = f_at(m, s, u0, v0, V, t);
        ++fetches;
        if (f <= 0) lo = t, f_lo = f, lo_known = true;
        else hi = t, f_hi = f, hi_known = true;
    }
    double t;
    switch (end) {
        case SearchEnd::first_below: t = lo; break;
        case SearchEnd::midpoint: t = 0.5 * (lo + hi); break;
        default: t = lo_known && hi_known ? secant_point() : 0.5 * (lo + hi); break;
    }
    return at_t(u0, v0, V, t, fetches, true);
}

Hit run_method(Pm m, const HeightMap& hm, double s, double u0, double v0, const View& V, int budget, double threshold) {
    budget = std::max(1, budget);
    const int B = refine_steps(budget);
    switch (m) {
        case Pm::none: return at_t(u0, v0, V, 0, 0, true);
        case Pm::kaneko: return kaneko(hm, s, u0, v0, V);
        case Pm::welsh: return welsh(hm, s, u0, v0, V);
        case Pm::welsh_bias: return welsh_bias(hm, s, u0, v0, V);
        case Pm::paper: return iterative(hm, s, u0, v0, V, threshold, budget);
        case Pm::paper_top: return iterative(hm, s, u0, v0, V, threshold, budget, s / V.h);
        case Pm::premecz: return premecz(hm, s, u0, v0, V, threshold, budget);
        case Pm::hybrid: return hybrid(hm, s, u0, v0, V, threshold, budget);
        case Pm::steep: return search(hm, s, u0, v0, V, budget, 0, false, SearchEnd::first_below);
        case Pm::pom: return search(hm, s, u0, v0, V, budget, 0, false, SearchEnd::secant);
        case Pm::relief: return search(hm, s, u0, v0, V, budget - B, B, false, SearchEnd::midpoint, true);
        case Pm::interval: return search(hm, s, u0, v0, V, budget - B, B, true, SearchEnd::secant, true);
        case Pm::exact: return exact(hm, s, u0, v0, V);
    }
    return at_t(u0, v0, V, 0, 0, true);
}

double f_at(const HeightMap& m, double s, double u0, double v0, const View& V, double t) {
    return t * V.h - s * m.at(u0 + t * V.u, v0 + t * V.v);
}

namespace {

// Largest root of a + b x + c x^2 in [0, 1] (small tolerance), or -1.
double largest_root01(double a, double b, double c) {
    const double tol = 1e-12;
    double best = -1;
    auto take = [&](double x) {
        if (x >= -tol && x <= 1 + tol) best = std::max(best, std::min(1.0, std::max(0.0, x)));
    };
    const double scale = std::fabs(a) + std::fabs(b) + std::fabs(c);
    if (scale == 0) return 1.0;  // f = 0 on the whole interval: touching from the top
    if (std::fabs(c) <= 1e-13 * scale) {
        if (b != 0) take(-a / b);
        return best;
    }
    const double disc = b * b - 4 * a * c;
    if (disc < 0) {
        // a double root lost to rounding: the vertex, when it touches zero
        const double x = -b / (2 * c);
        if (std::fabs(a + b * x + c * x * x) <= 1e-14 * scale) take(x);
        return best;
    }
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    if (q != 0) {
        take(q / c);
        take(a / q);
    } else {
        take(0.0);
    }
    return best;
}
}  // namespace

Hit exact(const HeightMap& m, double s, double u0, double v0, const View& V) {
    Hit h;
    h.fetches = 0;
    const double tmax = s / V.h;
    // breakpoints: where the ray's (x, y) in texel-centre coordinates crosses an integer
    const double x0 = u0 * m.size - 0.5, y0 = v0 * m.size - 0.5;
    const double ax = V.u * m.size, ay = V.v * m.size;
    std::vector<double> bp{0.0, tmax};
    auto crossings = [&](double p0, double dp) {
        if (std::fabs(dp) < 1e-300) return;
        const double p1 = p0 + dp * tmax;
        const double lo = std::min(p0, p1), hi = std::max(p0, p1);
        for (double k = std::ceil(lo); k <= hi; k += 1.0) {
            const double t = (k - p0) / dp;
            if (t > 0 && t < tmax) bp.push_back(t);
        }
    };
    crossings(x0, ax);
    crossings(y0, ay);
    std::sort(bp.begin(), bp.end());
    double f_hi = f_at(m, s, u0, v0, V, tmax);
    if (f_hi <= 0) {
        h.t = tmax;  // the relief reaches the slab's top here
    } else {
        h.t = 0;
        for (size_t k = bp.size() - 1; k > 0; --k) {
            const double tl = bp[k - 1], th = bp[k];
            if (th - tl <= 0) continue;
            const double f0 = f_at(m, s, u0, v0, V, tl), fm = f_at(m, s, u0, v0, V, 0.5 * (tl + th));
            const double f1 = f_hi;
            const double c = 2 * (f0 - 2 * fm + f1), b = -3 * f0 + 4 * fm - f1;
            const double x = largest_root01(f0, b, c);
            if (x >= 0) {
                h.t = tl + x * (th - tl);
                break;
            }
            f_hi = f0;
        }
    }
    h.u = u0 + h.t * V.u;
    h.v = v0 + h.t * V.v;
    return h;
}

Hit dense_search(const HeightMap& m, double s, double u0, double v0, const View& V, int samples) {
    Hit h;
    const double tmax = s / V.h;
    double t_prev = tmax;
    h.t = 0;
    if (f_at(m, s, u0, v0, V, tmax) <= 0) {
        h.t = tmax;
    } else {
        for (int k = 1; k <= samples; ++k) {
            const double t = tmax * (1.0 - double(k) / samples);
            if (f_at(m, s, u0, v0, V, t) <= 0) {
                double lo = t, hi = t_prev;  // f(lo) <= 0 < f(hi)
                for (int it = 0; it < 80; ++it) {
                    const double mid = 0.5 * (lo + hi);
                    if (f_at(m, s, u0, v0, V, mid) <= 0) lo = mid;
                    else hi = mid;
                }
                h.t = 0.5 * (lo + hi);
                break;
            }
            t_prev = t;
        }
    }
    h.u = u0 + h.t * V.u;
    h.v = v0 + h.t * V.v;
    return h;
}

}  // namespace methods
}  // namespace spec
