#include "span_host.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

namespace spec {
namespace host {

namespace {
constexpr double kPi = 3.14159265358979323846;

double clamp1(double x) { return std::min(1.0, std::max(-1.0, x)); }

// The great circle from unit a toward unit b: b = a cos(psi) + w sin(psi), w unit and perpendicular to a.
// Shared by slerp() and carry_to_n1() so that the host rotates about the same axis the normal travels on.
void slerp_frame(const Vec& a, const Vec& b, Vec* w, double* psi) {
    const double c = clamp1(glm::dot(a, b));
    Vec d = b - a * c;
    d -= a * glm::dot(a, d);  // once more: d exactly perpendicular to a even when b is close to +-a
    const double s = glm::length(d);
    *psi = std::atan2(s, c);
    if (s > 1e-12) {
        *w = d / s;
    } else if (c > 0) {
        *w = perpendicular(a);  // a = b: any direction, psi = 0
        *psi = 0.0;
    } else {
        *w = perpendicular(a);  // b = -a: the great circle through perpendicular(a)
        *psi = kPi;
    }
}
}  // namespace

void Counters::add(unsigned flags) {
    ++spans;
    if (flags & kFlat) ++flat;
    if (flags & kOpposite) ++opposite;
    if (flags & kCSaturated) ++c_saturated;
    if (flags & kSinglePixel) ++single_pixel;
    if (flags & kNoHighlight) ++no_highlight;
    if (flags & kGammaFallback) ++gamma_fallback;
}

Counters& Counters::operator+=(const Counters& o) {
    spans += o.spans;
    flat += o.flat;
    opposite += o.opposite;
    c_saturated += o.c_saturated;
    single_pixel += o.single_pixel;
    no_highlight += o.no_highlight;
    gamma_fallback += o.gamma_fallback;
    return *this;
}

Vec unit(const Vec& v, const char* what) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
        throw std::invalid_argument(std::string(what) + " is not finite");
    }
    const double m = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    if (!(m > 1e-300)) throw std::invalid_argument(std::string(what) + " has zero length");
    const Vec s = v / m;  // scaled first: no overflow or underflow in the length
    return s / glm::length(s);
}

Vec perpendicular(const Vec& a) {
    // cross with the coordinate axis along which a is smallest
    const double ax = std::fabs(a.x), ay = std::fabs(a.y), az = std::fabs(a.z);
    const Vec e = (ax <= ay && ax <= az) ? Vec(1, 0, 0) : (ay <= az ? Vec(0, 1, 0) : Vec(0, 0, 1));
    return glm::normalize(glm::cross(a, e));
}

Vec slerp(const Vec& a, const Vec& b, double t) {
    Vec w;
    double psi;
    slerp_frame(a, b, &w, &psi);
    return glm::normalize(a * std::cos(t * psi) + w * std::sin(t * psi));
}

Vec carry_to_n1(const Vec& n1, const Vec& n2, const Vec& h2, bool* opposite) {
    const double c = glm::dot(n1, n2);
    if (1.0 + c >= kOppositeEps) {
        if (opposite) *opposite = false;
        const Vec v = glm::cross(n1, n2);
        return h2 - glm::cross(v, h2) + glm::cross(v, glm::cross(v, h2)) / (1.0 + c);
    }
    // Nearly opposite normals: v -> 0 and 1 + c -> 0, the axis v/|v| is lost in rounding. Rotate by -psi
    // about n1 x w, w being the direction the slerp of the normal leaves n1 in (same axis up to rounding
    // whenever v still has one).
    if (opposite) *opposite = true;
    Vec w;
    double psi;
    slerp_frame(n1, n2, &w, &psi);
    const Vec u = glm::normalize(glm::cross(n1, w));
    return h2 * std::cos(psi) - glm::cross(u, h2) * std::sin(psi) + u * (glm::dot(u, h2) * (1.0 - std::cos(psi)));
}

bool midpoint_fit(double c1, double f1, double fm, double* gamma, double* a_sin, bool checked) {
    if (!(fm > (checked ? 1e-3 : 0.0))) return false;
    const double r = (c1 + f1) / (2.0 * fm);
    if (!(r >= 0.0 && r <= 1.0)) return false;
    const double g = 2.0 * std::acos(r);
    if (!(g >= (checked ? 1e-6 : 1e-300)) || !(std::sin(g) > 0.0)) return false;
    const double as = (f1 - c1 * std::cos(g)) / std::sin(g);
    if (checked && !(std::hypot(c1, as) <= 1.0)) return false;  // a unit N.H never exceeds 1
    *gamma = g;
    *a_sin = as;
    return true;
}

SpanSetup setup_span(const Model& m, const SpanEnds& e, double strength, unsigned n, uint32_t l, GammaRule rule,
                     bool midpoint_checked) {
    const Format& f = m.format();
    if (n >= (1u << f.n_w)) throw std::invalid_argument("n = " + std::to_string(n) + " does not fit register 4");
    if (uint64_t(l) >= (uint64_t(1) << f.l_w)) {
        throw std::invalid_argument("span of " + std::to_string(l) + " intervals does not fit counter 5");
    }
    if (!std::isfinite(strength) || strength < 0.0) {
        throw std::invalid_argument("specular strength Is*ks must be finite and >= 0");
    }
    const Vec n1 = unit(e.n1, "normal N1"), n2 = unit(e.n2, "normal N2");
    const Vec h1 = unit(e.h1, "halfway vector H1"), h2 = unit(e.h2, "halfway vector H2");

    SpanSetup s;
    s.n = n;
    s.l = l;
    bool opposite = false;
    const Vec h2p = glm::normalize(carry_to_n1(n1, n2, h2, &opposite));
    if (opposite) s.flags |= kOpposite;
    s.cos_t1 = clamp1(glm::dot(n1, h1));
    s.cos_t2 = clamp1(glm::dot(n1, h2p));
    const Vec x = glm::cross(h1, h2p);
    const double sg = glm::length(x);
    s.gamma = std::atan2(sg, glm::dot(h1, h2p));

    if (l == 0) s.flags |= kSinglePixel;
    if (l == 0 || s.gamma < kFlatGamma) {
        // N.H is constant along the span (or there is one pixel): represent it at angle 0, where every
        // table of ROM 12 is exact. A = cos(theta1); when that is <= 0 there is no highlight.
        s.flags |= kFlat;
        s.a = std::max(0.0, s.cos_t1);
        s.lambda = 0.0;
        s.zeta0 = 0.0;
        s.dzeta = 0.0;
        if (n > 0 && s.cos_t1 <= 0.0) s.flags |= kNoHighlight;
    } else {
        // Eq. (3) in the form that never divides by cos(theta1): A cos(lambda) = N1.H1 and
        // A sin(lambda) = N1.T, T the unit tangent at H1 of the great circle toward H2'
        // (T = (H2' - H1 cos(gamma)) / sin(gamma), written as (H1 x H2') x H1 / |H1 x H2'|).
        // H2' = -H1 (gamma = pi, x = 0): every great circle joins them; take the one slerp() takes
        // (slerp_frame: perpendicular(H1)). Found by make fuzz (fuzz/regress/host).
        Vec t = sg > 1e-200 ? glm::cross(x, h1) / sg : perpendicular(h1);
        t = glm::normalize(t - h1 * glm::dot(h1, t));  // for small gamma x carries rounding of order 1e-16/gamma
        double a_sin = glm::dot(n1, t);
        if (rule == GammaRule::midpoint) {
            // f(t) = A cos(t*gamma - lambda) gives f(0) + f(1) = 2 cos(gamma/2) f(1/2)
            const double fm = glm::dot(slerp(n1, n2, 0.5), slerp(h1, h2, 0.5));
            // N2.H2 = N1.H2' (a rotation keeps dot products)
            double g = 0, as = 0;
            if (midpoint_fit(s.cos_t1, s.cos_t2, fm, &g, &as, midpoint_checked)) {
                s.gamma = g;
                a_sin = as;
            } else {
                s.flags |= kGammaFallback;
            }
        }
        // |N1| = 1 and H1, T orthonormal: A <= 1 up to rounding. Where rounding takes it past 1, shorten
        // A sin(lambda), never A cos(lambda) = cos(theta1), which the span's first pixel depends on.
        if (std::hypot(s.cos_t1, a_sin) > 1.0) a_sin = std::copysign(std::sqrt(1.0 - s.cos_t1 * s.cos_t1), a_sin);
        s.a = std::min(1.0, std::hypot(s.cos_t1, a_sin));
        s.lambda = std::atan2(a_sin, s.cos_t1);
        // Register 3 = -lambda (unscaled), register 2 = gamma / l (docs/decisions.md #1). The angle
        // interval [zeta0, zeta0 + gamma] (gamma <= pi) is put where its middle is in [-pi, pi], so that
        // every angle with cos > 0 lies in (-pi/2, pi/2), where the core looks for it (it uses |angle|).
        double z0 = -s.lambda;
        const double mid = z0 + 0.5 * s.gamma;
        if (mid > kPi) z0 -= 2.0 * kPi;
        if (mid < -kPi) z0 += 2.0 * kPi;
        s.zeta0 = z0;
        s.dzeta = s.gamma / double(l);
        const double z1 = z0 + s.gamma;
        if (n > 0 && (z1 <= -kPi / 2 || z0 >= kPi / 2)) s.flags |= kNoHighlight;
    }

    // Eq. (5): C = Is * ks * A^n. No highlight on the span: C = 0, so that the core's table approximation
    // (which for n = 3 reaches slightly past pi/2) cannot light it.
    s.c = (s.flags & kNoHighlight) ? 0.0 : strength * std::pow(s.a, double(n));
    const double c_max = std::ldexp(std::ldexp(1.0, f.c_w) - 1.0, -f.c_w);
    s.c_used = s.c;
    if (s.c >= 1.0) {
        s.flags |= kCSaturated;
        s.c_used = c_max;
    }
    s.regs.c = m.quantize_c(std::min(s.c_used, c_max));
    s.regs.zeta0 = m.quantize_angle(s.zeta0);
    s.regs.dzeta = m.quantize_angle(s.dzeta);
    s.regs.n = n;
    s.regs.len = l;
    return s;
}

double SpanSetup::value(uint32_t i) const {
    const double z = zeta0 + double(i) * dzeta;
    return c_used * std::pow(std::max(0.0, std::cos(z)), double(n));
}

double SpanSetup::value_quantized(const Model& m, uint32_t i) const {
    const double z = m.angle_value(regs.zeta0 + int64_t(i) * regs.dzeta);
    const double c_q = std::ldexp(double(regs.c), -m.format().c_w);
    return c_q * std::pow(std::max(0.0, std::cos(z)), double(n));
}

double brute_force(const SpanEnds& e, double strength, unsigned n, uint32_t l, uint32_t i) {
    const Vec n1 = unit(e.n1, "normal N1"), n2 = unit(e.n2, "normal N2");
    const Vec h1 = unit(e.h1, "halfway vector H1"), h2 = unit(e.h2, "halfway vector H2");
    const double t = l ? double(i) / double(l) : 0.0;
    const double d = glm::dot(slerp(n1, n2, t), slerp(h1, h2, t));
    return strength * std::pow(std::max(0.0, d), double(n));
}

}  // namespace host
}  // namespace spec
