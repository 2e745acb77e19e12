// normalize.cpp - the paper's quantities and the span interpolations with their operation counts (normalize.h).
#include "normalize.h"

#include <algorithm>
#include <cmath>
#include <ctime>

#include <glm/geometric.hpp>

#include "span_host.h"

namespace spec {
namespace methods {

double deviation(double psi, int i) { return 1.0 - std::cos(psi / std::ldexp(1.0, i)); }

double z_level(double psi, int i) {
    double z = std::sqrt(2.0 * (1.0 + std::cos(psi)));
    for (int k = 1; k < i; ++k) z = std::sqrt(2.0 + z);
    return z;
}

double angle_for_deviation(double d) { return 2.0 * std::acos(1.0 - d); }

double specular_cos_bound(double delta_s, unsigned n) {
    return 2.0 * std::pow(1.0 - delta_s, 2.0 / double(n)) - 1.0;
}

const char* norm_mode_name(NormMode m) {
    switch (m) {
        case NormMode::full: return "full";
        case NormMode::rsqrt: return "rsqrt";
        case NormMode::newton: return "newton";
        case NormMode::recurrence: return "recurrence";
        case NormMode::halving: return "halving";
        case NormMode::adaptive: return "adaptive";
    }
    return "?";
}

std::vector<NormMode> norm_modes() {
    return {NormMode::full, NormMode::rsqrt, NormMode::newton, NormMode::recurrence, NormMode::halving,
            NormMode::adaptive};
}

OpClass& OpClass::operator+=(const OpClass& o) {
    add += o.add, mul += o.mul, div += o.div, sqrt += o.sqrt, rsqrt += o.rsqrt, trig += o.trig;
    return *this;
}

double OpClass::weighted() const {
    return double(add + mul) + 4.0 * double(div + sqrt + rsqrt) + 8.0 * double(trig);
}

NormOps& NormOps::operator+=(const NormOps& o) {
    vectors += o.vectors, spans += o.spans, normalized += o.normalized, halved += o.halved, lerped += o.lerped;
    sqrts += o.sqrts;
    span += o.span;
    pixel += o.pixel;
    return *this;
}

OpClass phong_pixel_ops() {
    OpClass c;
    c.mul = 3 + 3 + 1 + 6;  // N.L, N.H, n log2(x), the three channels: ambient + diffuse d + tint s (2 mul each)
    c.add = 2 + 2 + 6;      // the two dot products, the three channels (2 add each)
    c.trig = 2;             // pow(x, n) = exp2(n log2 x)
    return c;
}

namespace {
// What the adaptive stop test compares against, per material.
struct StopRule {
    double diffuse_len = 1.0;   // |N| >= this: relative diffuse error <= bound
    double specular_len = 1.0;  // |N| |H| >= this: relative specular error <= bound
    bool slerp_extension = false;
};

StopRule stop_rule(const NormBounds& b, unsigned n) {
    StopRule r;
    r.slerp_extension = b.slerp_extension;
    r.diffuse_len = 1.0 - b.diffuse;
    r.specular_len = n > 0 ? std::pow(1.0 - b.specular, 1.0 / double(n)) : 0.0;
    return r;
}

// Counting helpers, per vector.
void count_normalize(OpClass& c, NormOps* o) {  // dot (3 mul 2 add), sqrt, 1 / len, 3 mul
    c.mul += 6, c.add += 2, c.sqrt += 1, c.div += 1;
    ++o->normalized;
    ++o->sqrts;
}
void count_delta(OpClass& c) { c.add += 3, c.mul += 3, c.div += 1; }  // (N2 - N1) * (1 / l)

// One vector along the span by full, rsqrt, newton or recurrence; v has l + 1 entries, v[0] = a, v[l] = b
// (unit: the true end vectors).
void span_one(const NVec& a, const NVec& b, uint32_t l, NormMode mode, std::vector<NVec>& v, NormOps* o) {
    const double inv = 1.0 / double(l);
    const NVec d = (b - a) * inv;
    switch (mode) {
        case NormMode::full:
        case NormMode::rsqrt: {
            count_delta(o->span);
            NVec c = a;
            for (uint32_t i = 0; i <= l; ++i) {
                if (i > 0) {
                    c += d;
                    o->pixel.add += 3;
                }
                if (i > 0 && i < l) v[i] = glm::normalize(c);
                if (mode == NormMode::full) {
                    count_normalize(o->pixel, o);
                } else {
                    o->pixel.mul += 6, o->pixel.add += 2, o->pixel.rsqrt += 1;  // N * inversesqrt(dot(N, N))
                }
            }
            return;
        }
        case NormMode::newton: {
            count_normalize(o->span, o);
            count_normalize(o->span, o);
            count_delta(o->span);
            NVec c = a;
            for (uint32_t i = 1; i < l; ++i) {
                c += d;
                v[i] = c * (1.5 - 0.5 * glm::dot(c, c));
                o->pixel.add += 3 + 2 + 1, o->pixel.mul += 3 + 1 + 3;
            }
            return;
        }
        default: {  // recurrence
            count_normalize(o->span, o);
            count_normalize(o->span, o);
            const double cpsi = std::min(1.0, std::max(-1.0, glm::dot(a, b)));
            o->span.mul += 3, o->span.add += 2;
            const NVec w = b - a * cpsi;
            o->span.mul += 3, o->span.add += 3;
            const double wl = glm::length(w);
            if (wl < 1e-9 || cpsi < -0.999) {
                // (nearly) equal ends: nothing to turn; (nearly) opposite: no plane. Lerp and normalize each.
                NVec c = a;
                count_delta(o->span);
                for (uint32_t i = 1; i < l; ++i) {
                    c += d;
                    v[i] = glm::normalize(c);
                    o->pixel.add += 3;
                    count_normalize(o->pixel, o);
                }
                return;
            }
            count_normalize(o->span, o);
            const double phi = std::acos(cpsi) * inv;
            o->span.trig += 3, o->span.div += 1;  // acos, cos, sin; / l
            const double k = 2.0 * std::cos(phi);
            o->span.mul += 1;
            v[1] = a * std::cos(phi) + (w / wl) * std::sin(phi);
            o->span.mul += 6, o->span.add += 3;
            for (uint32_t i = 2; i < l; ++i) {
                v[i] = v[i - 1] * k - v[i - 2];
                o->pixel.mul += 3, o->pixel.add += 3;
            }
            return;
        }
    }
}

// halving and adaptive: N and H share the segment structure; every count is for both vectors.
void span_halving(const NVec& n1, const NVec& n2, const NVec& h1, const NVec& h2, uint32_t l, NormMode mode,
                  const StopRule& rule, SpanVectors* out, NormOps* ops) {
    std::vector<NVec>& pn = out->n;
    std::vector<NVec>& ph = out->h;
    for (int k = 0; k < 4; ++k) count_normalize(ops->span, ops);  // the four ends
    int k = 0;
    while ((uint32_t(1) << k) < l) ++k;
    const uint32_t L2 = uint32_t(1) << k;
    pn.assign(L2 + 1, NVec(0));
    ph.assign(L2 + 1, NVec(0));
    pn[0] = n1;
    ph[0] = h1;
    if (L2 == l) {
        pn[L2] = n2;
        ph[L2] = h2;
    } else {
        const double s = double(L2) / double(l);
        if (rule.slerp_extension) {
            // on the great circle, at s times the end vectors' angle (host::slerp extrapolates for s > 1);
            // past 0.9 pi the halving's midpoints would take the other way round: normalize every pixel
            const double an = std::acos(std::min(1.0, glm::dot(n1, n2))), ah = std::acos(std::min(1.0, glm::dot(h1, h2)));
            if (std::max(an, ah) * s > 0.9 * 3.14159265358979323846) {
                pn.assign(l + 1, n1);
                ph.assign(l + 1, h1);
                pn[l] = n2;
                ph[l] = h2;
                span_one(n1, n2, l, NormMode::full, pn, ops);
                span_one(h1, h2, l, NormMode::full, ph, ops);
                return;
            }
            pn[L2] = host::slerp(n1, n2, s);
            ph[L2] = host::slerp(h1, h2, s);
            ops->span.trig += 2 * 3, ops->span.mul += 2 * 12, ops->span.add += 2 * 6, ops->span.div += 2;
        } else {
            // the span extended to 2^k intervals: the vector lerped on to the new end, normalized (the paper)
            pn[L2] = glm::normalize(n1 + (n2 - n1) * s);
            ph[L2] = glm::normalize(h1 + (h2 - h1) * s);
            ops->span.add += 2 * 6, ops->span.mul += 2 * 3, ops->span.div += 1;  // 2^k / l shared
            count_normalize(ops->span, ops);
            count_normalize(ops->span, ops);
        }
    }
    double zn = std::sqrt(2.0 + 2.0 * glm::dot(pn[0], pn[L2]));
    double zh = std::sqrt(2.0 + 2.0 * glm::dot(ph[0], ph[L2]));
    ops->span.mul += 2 * 4, ops->span.add += 2 * 3, ops->span.sqrt += 2;
    ops->sqrts += 2;
    if (zn < 1e-6 || zh < 1e-6) {
        // (nearly) opposite end vectors: no midpoint direction; normalize every pixel instead
        pn.resize(l + 1);
        ph.resize(l + 1);
        pn[l] = n2;
        ph[l] = h2;
        span_one(n1, n2, l, NormMode::full, pn, ops);
        span_one(h1, h2, l, NormMode::full, ph, ops);
        return;
    }
    uint32_t seg = L2;
    while (seg > 1) {
        // segments of `seg` intervals, end vectors psi / 2^level apart, z = |Na + Nb| = 2 cos(angle / 2):
        // the lerp's shortest vector (at the segment's middle) has length z / 2
        if (mode == NormMode::adaptive) {
            ops->span.mul += 2, ops->span.add += 2;  // 0.25 zN zH, and the two comparisons
            if (0.5 * zn >= rule.diffuse_len && 0.25 * zn * zh >= rule.specular_len) break;
        }
        const double rn = 1.0 / zn, rh = 1.0 / zh;
        ops->span.div += 2;
        const uint32_t half = seg / 2;
        for (uint32_t a = 0; a < l; a += seg) {
            pn[a + half] = (pn[a] + pn[a + seg]) * rn;
            ph[a + half] = (ph[a] + ph[a + seg]) * rh;
            ops->halved += 2;
            ops->pixel.add += 2 * 3, ops->pixel.mul += 2 * 3;
        }
        zn = std::sqrt(2.0 + zn);  // eq. (1): z for the next level
        zh = std::sqrt(2.0 + zh);
        ops->span.add += 2, ops->span.sqrt += 2;
        ops->sqrts += 2;
        seg = half;
        ++out->levels;
    }
    out->stop_seg = int(seg);
    if (seg > 1) {
        const double inv = 1.0 / double(seg);  // a shift in fixed point
        for (uint32_t a = 0; a < l; a += seg) {
            const NVec dn = (pn[a + seg] - pn[a]) * inv, dh = (ph[a + seg] - ph[a]) * inv;
            ops->span.add += 2 * 3;  // the segment's step (the shift is free)
            NVec cn = pn[a], ch = ph[a];
            const uint32_t end = std::min(seg, l - a);
            for (uint32_t i = 1; i < end; ++i) {
                cn += dn;
                ch += dh;
                pn[a + i] = cn;
                ph[a + i] = ch;
            }
            ops->lerped += 2 * uint64_t(end - 1);
            ops->pixel.add += 2 * 3 * uint64_t(end - 1);
        }
    }
    pn.resize(l + 1);
    ph.resize(l + 1);
    pn[l] = n2;  // the span's real end vectors are known
    ph[l] = h2;
}

void interpolate(const NVec& n1, const NVec& n2, const NVec& h1, const NVec& h2, uint32_t l, NormMode mode,
                 const StopRule& rule, SpanVectors* out, NormOps* ops) {
    out->levels = 0;
    out->stop_seg = 1;
    ops->vectors += 2 * (uint64_t(l) + 1);
    ops->spans += 2;
    if (l <= 1) {
        // one or two pixels: their vectors are the ends, normalized once each (every method)
        out->n.assign(l + 1, n1);
        out->h.assign(l + 1, h1);
        out->n[l] = n2;
        out->h[l] = h2;
        for (uint32_t k = 0; k < 2 * (l + 1); ++k) {
            if (mode == NormMode::rsqrt) ops->pixel.mul += 6, ops->pixel.add += 2, ops->pixel.rsqrt += 1;
            else count_normalize(ops->pixel, ops);
        }
        return;
    }
    if (mode == NormMode::halving || mode == NormMode::adaptive) {
        span_halving(n1, n2, h1, h2, l, mode, rule, out, ops);
        return;
    }
    out->n.assign(l + 1, n1);
    out->h.assign(l + 1, h1);
    out->n[l] = n2;
    out->h[l] = h2;
    span_one(n1, n2, l, mode, out->n, ops);
    span_one(h1, h2, l, mode, out->h, ops);
}
}  // namespace

void interpolate_span(const NVec& n1, const NVec& n2, const NVec& h1, const NVec& h2, uint32_t l, NormMode mode,
                      const NormBounds& b, unsigned n, SpanVectors* out, NormOps* ops) {
    interpolate(n1, n2, h1, h2, l, mode, stop_rule(b, n), out, ops);
}

PhongRun shade_phong(const render::Scene& sc, const render::Frame& f, NormMode mode, const NormBounds& b,
                     PhongTerms* terms) {
    PhongRun r;
    const size_t np = size_t(f.w) * size_t(f.h);
    std::vector<float> rgb(np * 3);
    for (size_t p = 0; p < np; ++p) {
        for (int c = 0; c < 3; ++c) rgb[3 * p + c] = float(sc.background[c]);
    }
    if (terms) {
        terms->diffuse.assign(np, 0.0);
        terms->specular.assign(np, 0.0);
        terms->n_len.assign(np, 0.0);
    }
    std::vector<StopRule> rules;
    for (const auto& o : sc.objects) rules.push_back(stop_rule(b, o.mat.n));
    const NVec L = f.light_dir;
    SpanVectors v;
    timespec c0{}, c1{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &c0);
    for (const render::Span& sp : f.spans) {
        const render::Material& m = sc.objects[sp.obj].mat;
        interpolate(sp.ends.n1, sp.ends.n2, sp.ends.h1, sp.ends.h2, sp.l, mode, rules[sp.obj], &v, &r.ops);
        const NVec amb = m.ka * sc.ambient * m.color;
        const NVec dif = m.kd * sc.light.intensity * sc.light.color * m.color;
        const NVec tint = sc.light.color * m.spec_color;
        const double strength = sc.light.intensity * m.ks;
        const double ex = double(m.n);
        const size_t row = size_t(sp.y) * size_t(f.w) + size_t(sp.x0);
        for (uint32_t i = 0; i <= sp.l; ++i) {
            if (!f.visible(sp, i)) continue;
            const double d = std::max(0.0, glm::dot(v.n[i], L));
            const double s = strength * std::pow(std::max(0.0, glm::dot(v.n[i], v.h[i])), ex);
            const NVec c = amb + dif * d + tint * s;
            const size_t p = row + i;
            for (int k = 0; k < 3; ++k) rgb[3 * p + k] = float(c[k]);
            if (terms) {
                terms->diffuse[p] = d;
                terms->specular[p] = s;
                terms->n_len[p] = glm::length(v.n[i]);
            }
        }
    }
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &c1);
    r.seconds = double(c1.tv_sec - c0.tv_sec) + 1e-9 * double(c1.tv_nsec - c0.tv_nsec);
    r.img = render::Image(f.w, f.h);
    for (size_t k = 0; k < rgb.size(); ++k) {
        r.img.rgb[k] = uint8_t(std::lround(std::min(1.0, std::max(0.0, double(rgb[k]))) * 255.0));
    }
    return r;
}


}  // namespace methods
}  // namespace spec
