#include "setup_eval.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace spec {

namespace {

using host::Vec;

Vec code_vec(const SetupFormat& sf, const int32_t c[3]) {
    const double s = std::ldexp(1.0, -sf.vec_frac);
    return Vec(c[0] * s, c[1] * s, c[2] * s);
}

Vec random_unit(std::mt19937_64& rng) {
    std::normal_distribution<double> nd;
    while (true) {
        const Vec v(nd(rng), nd(rng), nd(rng));
        const double l = glm::length(v);
        if (l > 1e-3) return v / l;
    }
}

// u turned by angle a toward a random perpendicular direction.
Vec tilt(const Vec& u, double a, std::mt19937_64& rng) {
    Vec w = random_unit(rng);
    w -= u * glm::dot(u, w);
    const double l = glm::length(w);
    if (l < 1e-9) return tilt(u, a, rng);
    w /= l;
    return u * std::cos(a) + w * std::sin(a);
}

double log_uniform(std::mt19937_64& rng, double lo, double hi) {
    std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
    return std::exp(u(rng));
}

void put(const SetupFormat& sf, const Vec& v, double len, int32_t out[3]) {
    for (int k = 0; k < 3; ++k) out[k] = component_code(sf, v[k] * len);
}

struct Bound {
    double ref, bound;
};

std::vector<Bound> bounds(const Model& core, const host::SpanSetup& s, const CheckOptions& opt) {
    const ErrorTable& et = fig10_errors();
    const unsigned n = s.n;
    std::vector<Bound> b(size_t(s.l) + 1);
    for (uint32_t i = 0; i <= s.l; ++i) {
        const double ref = s.value(i);
        const double z = s.zeta0 + double(i) * s.dzeta;
        const bool in = std::fabs(z) <= epicentre_end(n);
        const double share = 0.002 + opt.setup_share;
        b[i].ref = ref;
        b[i].bound = in ? ref * (et.q[n] + share) + std::ldexp(1.0, -13) : s.c_used * (et.a[n] + share) + std::ldexp(1.0, -12);
    }
    (void)core;
    return b;
}

}  // namespace

int32_t component_code(const SetupFormat& sf, double v) {
    const double q = std::nearbyint(std::ldexp(v, sf.vec_frac));
    const double hi = std::ldexp(1.0, sf.vec_w - 1) - 1, lo = -std::ldexp(1.0, sf.vec_w - 1);
    return static_cast<int32_t>(std::min(hi, std::max(lo, q)));
}

host::SpanEnds host_ends(const SetupFormat& sf, const SetupInput& in) {
    return {code_vec(sf, in.n1), code_vec(sf, in.n2), code_vec(sf, in.h1), code_vec(sf, in.h2)};
}

double host_strength(const SetupFormat& sf, const SetupInput& in) {
    return std::ldexp(double(in.strength), -sf.str_frac);
}

host::GammaRule host_rule(const SetupInput& in) {
    return in.midpoint ? host::GammaRule::midpoint : host::GammaRule::patent;
}

SpanCheck check_span(const Model& core, const SetupFormat& sf, const SetupInput& in, const std::vector<uint32_t>& out,
                     std::mt19937_64& rng, const CheckOptions& opt) {
    const host::SpanEnds e = host_ends(sf, in);
    const double str = host_strength(sf, in);
    const host::GammaRule rule = host_rule(in);
    const host::SpanSetup s = host::setup_span(core, e, str, in.n, in.l, rule);
    std::vector<Bound> b = bounds(core, s, opt);
    SpanCheck c;
    if (out.size() != b.size()) {
        c.ratio = c.plain_ratio = INFINITY;
        return c;
    }
    std::vector<double> err(b.size());
    bool over = false;
    for (size_t i = 0; i < b.size(); ++i) {
        err[i] = std::fabs(core.out_value(out[i]) - b[i].ref);
        over |= err[i] > b[i].bound;
        c.plain_ratio = std::max(c.plain_ratio, err[i] / b[i].bound);
    }
    std::vector<double> wide(b.size());
    for (size_t i = 0; i < b.size(); ++i) wide[i] = b[i].bound;
    if (over) {   // ill-conditioned? the host for nearly the same span
        for (int k = 0; k < opt.samples; ++k) {
            const host::SpanEnds p{tilt(glm::normalize(e.n1), opt.eps, rng), tilt(glm::normalize(e.n2), opt.eps, rng),
                                   tilt(glm::normalize(e.h1), opt.eps, rng), tilt(glm::normalize(e.h2), opt.eps, rng)};
            const host::SpanSetup sp = host::setup_span(core, p, str, in.n, in.l, rule);
            const std::vector<Bound> bp = bounds(core, sp, opt);
            for (size_t i = 0; i < b.size(); ++i) wide[i] = std::max(wide[i], bp[i].bound + std::fabs(bp[i].ref - b[i].ref));
        }
        // and H1 tilted by eps toward +-d1, +-d2: d1 the direction of N1 across H1, d2 = H1 x d1 (where H2' is
        // near -H1 these turn the great circle from H1 to H2' the most; found by fuzz_setup: N2 = -N1, H2 = H1)
        const Vec n1 = glm::normalize(e.n1), h1 = glm::normalize(e.h1);
        Vec d1 = n1 - h1 * glm::dot(n1, h1), d2(0.0);
        if (glm::length(d1) > 1e-9) {
            d1 = glm::normalize(d1);
            d2 = glm::cross(h1, d1);
            const Vec dirs[4] = {d1, -d1, d2, -d2};
            for (const Vec& d : dirs) {
                const host::SpanEnds p{e.n1, e.n2, h1 * std::cos(opt.eps) + d * std::sin(opt.eps), e.h2};
                const host::SpanSetup sp = host::setup_span(core, p, str, in.n, in.l, rule);
                const std::vector<Bound> bp = bounds(core, sp, opt);
                for (size_t i = 0; i < b.size(); ++i) {
                    wide[i] = std::max(wide[i], bp[i].bound + std::fabs(bp[i].ref - b[i].ref));
                }
            }
            // gamma within the input's resolution of pi (H2' within 2^-14 of -H1, e.g. N2 = -N1 and H2 = H1 up
            // to the codes' last bit): the circle is the input's rounding's choice; widened over the circles
            // with tangent T = cos(phi) d1 + sin(phi) d2 at H1, phi = 0 .. pi in 33 steps (N1.T over its whole
            // range; C's saturation makes a pixel's value not monotonic in it), H2 moved by at most
            // 2 (pi - gamma) + eps so that H2' = -H1 + a T
            const double gap = 3.14159265358979323846 - s.gamma;
            if (!(s.flags & host::kFlat) && gap < opt.pi_gap) {
                c.ambiguous = true;
                for (int k = 0; k <= 32; ++k) {
                    const double phi = 3.14159265358979323846 * k / 32.0;
                    const Vec t = d1 * std::cos(phi) + d2 * std::sin(phi);
                    const Vec h2p = glm::normalize(-h1 + t * (2.0 * gap + opt.eps));
                    const host::SpanEnds p{e.n1, e.n2, e.h1,
                                           host::carry_to_n1(glm::normalize(e.n2), glm::normalize(e.n1), h2p)};
                    const host::SpanSetup sp = host::setup_span(core, p, str, in.n, in.l, rule);
                    const std::vector<Bound> bp = bounds(core, sp, opt);
                    for (size_t i = 0; i < b.size(); ++i) {
                        wide[i] = std::max(wide[i], bp[i].bound + std::fabs(bp[i].ref - b[i].ref));
                    }
                }
            }
        }
        // the midpoint rule's tests (midpoint_fit: fm > 1e-3, 0 <= r <= 1, gamma >= 1e-6, A <= 1) decided
        // within the backward error: N1.H1, N2.H2 and N.H each move by up to 2 eps when the vectors turn by
        // eps; where a corner of that box decides the other way, the span is held to either answer (the
        // fit kept, or the patent's gamma). Found at A = 1 + 5e-7, which random tilts of eps rarely cross.
        if (rule == host::GammaRule::midpoint && !(s.flags & host::kFlat)) {
            const Vec n1u = glm::normalize(e.n1), n2u = glm::normalize(e.n2);
            const double fm = glm::dot(host::slerp(n1u, n2u, 0.5),
                                       host::slerp(glm::normalize(e.h1), glm::normalize(e.h2), 0.5));
            const bool ok = !(s.flags & host::kGammaFallback);
            const double d = 2.0 * opt.eps;
            bool edge = false;
            for (int k = 0; k < 8 && !edge; ++k) {
                double g, as;
                edge = host::midpoint_fit(s.cos_t1 + (k & 1 ? d : -d), s.cos_t2 + (k & 2 ? d : -d),
                                          fm + (k & 4 ? d : -d), &g, &as) != ok;
            }
            if (edge) {
                c.ambiguous = true;
                const host::SpanSetup alt[2] = {host::setup_span(core, e, str, in.n, in.l, host::GammaRule::patent),
                                                host::setup_span(core, e, str, in.n, in.l, rule, false)};
                for (const host::SpanSetup& sp : alt) {
                    const std::vector<Bound> bp = bounds(core, sp, opt);
                    for (size_t i = 0; i < b.size(); ++i) {
                        wide[i] = std::max(wide[i], bp[i].bound + std::fabs(bp[i].ref - b[i].ref));
                    }
                }
            }
        }
        const Vec n1u = glm::normalize(e.n1), n2u = glm::normalize(e.n2);
        const double opp_gap = 2.0 * std::asin(std::min(1.0, glm::length(n1u + n2u) / 2.0));
        // N2 near -N1 (within 1/64 rad): the axis N1 x N2 turns by eps / sin(opp_gap) when N2 turns by eps, so
        // random tilts cover its directions poorly; widened over N2 (and N1) tilted by eps in 16 directions
        // around it (a setup whose cross product in f-bit coordinates errs by 2^-f is inside this backward
        // error; found in the up5k configuration, N2 1e-4 rad from -N1)
        if (opp_gap < 1.0 / 64) {
            for (int which = 0; which < 2; ++which) {
                const Vec v = which ? n1u : n2u;
                const double ax = std::fabs(v.x), ay = std::fabs(v.y), az = std::fabs(v.z);
                const Vec ek = (ax <= ay && ax <= az) ? Vec(1, 0, 0) : (ay <= az ? Vec(0, 1, 0) : Vec(0, 0, 1));
                const Vec a = glm::normalize(glm::cross(v, ek)), bb = glm::cross(v, a);
                for (int k = 0; k < 16; ++k) {
                    const double phi = 3.14159265358979323846 * k / 8.0;
                    const Vec vt = v * std::cos(opt.eps) + (a * std::cos(phi) + bb * std::sin(phi)) * std::sin(opt.eps);
                    const host::SpanEnds p{which ? vt : e.n1, which ? e.n2 : vt, e.h1, e.h2};
                    const host::SpanSetup sp = host::setup_span(core, p, str, in.n, in.l, rule);
                    const std::vector<Bound> bp = bounds(core, sp, opt);
                    for (size_t i = 0; i < b.size(); ++i) {
                        wide[i] = std::max(wide[i], bp[i].bound + std::fabs(bp[i].ref - b[i].ref));
                    }
                }
            }
        }
        // N2 within the input's resolution of -N1: the axis of the rotation N2 -> N1 is the input rounding's
        // choice (the host takes it from the last bits' residue, the setup from perpendicular(N1) below its
        // threshold); widened over 32 axes u perpendicular to N1, N2 moved to N1 turned by pi - pi_gap about u
        if ((s.flags & host::kOpposite) && opp_gap < opt.pi_gap) {
            c.ambiguous = true;
            const double ax = std::fabs(n1u.x), ay = std::fabs(n1u.y), az = std::fabs(n1u.z);
            const Vec ek = (ax <= ay && ax <= az) ? Vec(1, 0, 0) : (ay <= az ? Vec(0, 1, 0) : Vec(0, 0, 1));
            const Vec a = glm::normalize(glm::cross(n1u, ek)), bb = glm::cross(n1u, a);
            const double turn = 3.14159265358979323846 - opt.pi_gap;
            for (int k = 0; k < 32; ++k) {
                const double phi = 3.14159265358979323846 * k / 16.0;
                const Vec u = a * std::cos(phi) + bb * std::sin(phi);
                const Vec n2alt = n1u * std::cos(turn) + glm::cross(u, n1u) * std::sin(turn);
                const host::SpanEnds p{e.n1, n2alt, e.h1, e.h2};
                const host::SpanSetup sp = host::setup_span(core, p, str, in.n, in.l, rule);
                const std::vector<Bound> bp = bounds(core, sp, opt);
                for (size_t i = 0; i < b.size(); ++i) {
                    wide[i] = std::max(wide[i], bp[i].bound + std::fabs(bp[i].ref - b[i].ref));
                }
            }
        }
    }
    for (size_t i = 0; i < b.size(); ++i) {
        const double r = err[i] / wide[i];
        if (err[i] > b[i].bound) c.widened = true;
        if (r > c.ratio || i == 0) {
            c.ratio = std::max(c.ratio, r);
            c.worst_pixel = static_cast<uint32_t>(i);
            c.out = core.out_value(out[i]);
            c.ref = b[i].ref;
            c.bound = wide[i];
            c.inside = std::fabs(s.zeta0 + double(i) * s.dzeta) <= epicentre_end(in.n);
        }
    }
    return c;
}

const char* kind_name(SpanKind k) {
    switch (k) {
        case SpanKind::random: return "random";
        case SpanKind::near_equal: return "nearly equal ends";
        case SpanKind::flat_normal: return "constant normal";
        case SpanKind::near_opposite: return "nearly opposite normals";
        case SpanKind::facing_away: return "N.H <= 0";
        case SpanKind::gamma_zero: return "gamma -> 0";
        case SpanKind::single_pixel: return "l = 0";
        case SpanKind::saturating: return "C saturating";
        case SpanKind::count: break;
    }
    return "?";
}

SetupInput random_case(std::mt19937_64& rng, const SetupFormat& sf, SpanKind kind, unsigned n, uint32_t max_len) {
    std::uniform_real_distribution<double> u01(0.0, 1.0), len(0.5, 1.9);
    SetupInput in;
    in.n = n;
    const double r = u01(rng);
    in.l = r < 0.3 ? static_cast<uint32_t>(rng() % 4) : static_cast<uint32_t>(rng() % (uint64_t(max_len) + 1));
    in.strength = static_cast<uint32_t>(rng() % (uint32_t(1) << sf.str_frac));   // [0, 1)
    // A normal and a halfway vector near it: the highlight on or near the span for every n.
    const Vec n1 = random_unit(rng);
    const double near = epicentre_end(n);
    Vec h1 = tilt(n1, std::min(1.5, near * log_uniform(rng, 0.05, 8.0)), rng);
    Vec n2, h2;
    auto move = [&](const Vec& v, double lo, double hi) { return tilt(v, log_uniform(rng, lo, hi), rng); };
    switch (kind) {
        case SpanKind::random:
            if (u01(rng) < 0.2) h1 = random_unit(rng);
            n2 = move(n1, 1e-3, 1.0);
            h2 = move(h1, 1e-3, 1.0);
            break;
        case SpanKind::near_equal:
        case SpanKind::single_pixel:
        case SpanKind::saturating:
            n2 = move(n1, 1e-4, 3e-2);
            h2 = move(h1, 1e-4, 3e-2);
            break;
        case SpanKind::flat_normal:
            n2 = n1;
            h2 = move(h1, 1e-4, 0.3);
            break;
        case SpanKind::near_opposite:
            n2 = u01(rng) < 0.2 ? -n1 : move(-n1, 1e-4, 2e-3);
            h2 = move(h1, 1e-3, 0.3);
            break;
        case SpanKind::facing_away:
            h1 = tilt(n1, 1.5707963267948966 + log_uniform(rng, 1e-3, 1.5), rng);
            n2 = move(n1, 1e-3, 0.3);
            h2 = u01(rng) < 0.5 ? move(h1, 1e-3, 0.3) : tilt(n2, log_uniform(rng, 1e-3, 1.6), rng);
            break;
        case SpanKind::gamma_zero:
            n2 = u01(rng) < 0.5 ? n1 : move(n1, 1e-7, 1e-5);
            h2 = u01(rng) < 0.5 ? h1 : move(h1, 1e-7, 1e-5);
            break;
        case SpanKind::count:
            break;
    }
    const double l1 = len(rng);
    put(sf, n1, l1, in.n1);
    if (kind == SpanKind::flat_normal || (kind == SpanKind::gamma_zero && u01(rng) < 0.5)) {
        for (int k = 0; k < 3; ++k) in.n2[k] = in.n1[k];   // the same codes
    } else if (kind == SpanKind::near_opposite && n2 == -n1) {
        for (int k = 0; k < 3; ++k) in.n2[k] = -in.n1[k];
    } else {
        put(sf, n2, len(rng), in.n2);
    }
    put(sf, h1, len(rng), in.h1);
    if (kind == SpanKind::gamma_zero && u01(rng) < 0.5) {
        for (int k = 0; k < 3; ++k) in.h2[k] = in.h1[k];
    } else {
        put(sf, h2, len(rng), in.h2);
    }
    if (kind == SpanKind::single_pixel) in.l = 0;
    if (kind == SpanKind::saturating) in.strength = static_cast<uint32_t>((uint32_t(1) << sf.str_frac) + rng() % (uint32_t(1) << sf.str_frac));
    return in;
}

SetupInput random_raw(std::mt19937_64& rng, const SetupFormat& sf) {
    SetupInput in;
    const int32_t top = int32_t(1) << (sf.vec_w - 1);
    auto comp = [&]() -> int32_t {
        switch (rng() % 6) {
            case 0: return 0;
            case 1: return (rng() % 2) ? top - 1 : -top;
            case 2: return static_cast<int32_t>(rng() % 7) - 3;
            default: return static_cast<int32_t>(rng() % (2 * uint64_t(top))) - top;
        }
    };
    int32_t* v[4] = {in.n1, in.n2, in.h1, in.h2};
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 3; ++k) v[i][k] = comp();
    if (rng() % 8 == 0)
        for (int k = 0; k < 3; ++k) in.n2[k] = -in.n1[k] == top ? top - 1 : -in.n1[k];
    if (rng() % 8 == 0)
        for (int k = 0; k < 3; ++k) in.h2[k] = in.h1[k];
    in.strength = static_cast<uint32_t>(rng() % (uint64_t(1) << sf.str_w));
    in.n = static_cast<uint32_t>(rng() % 1024);
    in.l = (rng() % 4) ? static_cast<uint32_t>(rng() % 40) : static_cast<uint32_t>(rng() % 65536);
    in.midpoint = rng() % 4 == 0;
    return in;
}

}  // namespace spec
