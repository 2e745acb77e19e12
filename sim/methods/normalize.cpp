#include "normalize.h"

#include <algorithm>
#include <ctime>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

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
        case NormMode::halving: return "halving";
        case NormMode::adaptive: return "adaptive";
    }
    return "?";
}

NormOps& NormOps::operator+=(const NormOps& o) {
    vectors += o.vectors;
    normalized += o.normalized;
    halved += o.halved;
    lerped += o.lerped;
    sqrts += o.sqrts;
    return *this;
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

void span_full(const NVec& n1, const NVec& n2, const NVec& h1, const NVec& h2, uint32_t l, SpanVectors* out,
               NormOps* ops) {
    const double inv = 1.0 / double(l);
    const NVec dn = (n2 - n1) * inv, dh = (h2 - h1) * inv;
    NVec cn = n1, ch = h1;
    for (uint32_t i = 1; i < l; ++i) {
        cn += dn;
        ch += dh;
        out->n[i] = glm::normalize(cn);
        out->h[i] = glm::normalize(ch);
    }
    ops->normalized += 2 * uint64_t(l - 1);
    ops->sqrts += 2 * uint64_t(l - 1);
}

void interpolate(const NVec& n1, const NVec& n2, const NVec& h1, const NVec& h2, uint32_t l, NormMode mode,
                 const StopRule& rule, SpanVectors* out, NormOps* ops) {
    out->levels = 0;
    out->stop_seg = 1;
    ops->vectors += 2 * (uint64_t(l) + 1);
    if (l <= 1) {
        out->n.resize(l + 1);
        out->h.resize(l + 1);
        out->n[0] = n1;
        out->h[0] = h1;
        out->n[l] = n2;
        out->h[l] = h2;
        return;
    }
    if (mode == NormMode::full) {
        out->n.resize(l + 1);
        out->h.resize(l + 1);
        out->n[0] = n1;
        out->h[0] = h1;
        out->n[l] = n2;
        out->h[l] = h2;
        span_full(n1, n2, h1, h2, l, out, ops);
        return;
    }
    int k = 0;
    while ((uint32_t(1) << k) < l) ++k;
    const uint32_t L2 = uint32_t(1) << k;
    out->n.resize(L2 + 1);
    out->h.resize(L2 + 1);
    std::vector<NVec>& pn = out->n;
    std::vector<NVec>& ph = out->h;
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
                pn.resize(l + 1);
                ph.resize(l + 1);
                pn[l] = n2;
                ph[l] = h2;
                span_full(n1, n2, h1, h2, l, out, ops);
                return;
            }
            pn[L2] = host::slerp(n1, n2, s);
            ph[L2] = host::slerp(h1, h2, s);
        } else {
            // the span extended to 2^k intervals: the vector lerped on to the new end, normalized (the paper)
            pn[L2] = glm::normalize(n1 + (n2 - n1) * s);
            ph[L2] = glm::normalize(h1 + (h2 - h1) * s);
        }
        ops->normalized += 2;
        ops->sqrts += 2;
    }
    double zn = std::sqrt(2.0 + 2.0 * glm::dot(pn[0], pn[L2]));
    double zh = std::sqrt(2.0 + 2.0 * glm::dot(ph[0], ph[L2]));
    ops->sqrts += 2;
    if (zn < 1e-6 || zh < 1e-6) {
        // (nearly) opposite end vectors: no midpoint direction; normalize every pixel instead
        out->n.resize(l + 1);
        out->h.resize(l + 1);
        out->n[l] = n2;
        out->h[l] = h2;
        span_full(n1, n2, h1, h2, l, out, ops);
        return;
    }
    uint32_t seg = L2;
    while (seg > 1) {
        // segments of `seg` intervals, end vectors psi / 2^level apart, z = |Na + Nb| = 2 cos(angle / 2):
        // the lerp's shortest vector (at the segment's middle) has length z / 2
        if (mode == NormMode::adaptive && 0.5 * zn >= rule.diffuse_len && 0.25 * zn * zh >= rule.specular_len) break;
        const double rn = 1.0 / zn, rh = 1.0 / zh;
        const uint32_t half = seg / 2;
        for (uint32_t a = 0; a < l; a += seg) {
            pn[a + half] = (pn[a] + pn[a + seg]) * rn;
            ph[a + half] = (ph[a] + ph[a + seg]) * rh;
            ops->halved += 2;
        }
        zn = std::sqrt(2.0 + zn);  // eq. (1): z for the next level
        zh = std::sqrt(2.0 + zh);
        ops->sqrts += 2;
        seg = half;
        ++out->levels;
    }
    out->stop_seg = int(seg);
    if (seg > 1) {
        const double inv = 1.0 / double(seg);  // a shift in fixed point
        for (uint32_t a = 0; a < l; a += seg) {
            const NVec dn = (pn[a + seg] - pn[a]) * inv, dh = (ph[a + seg] - ph[a]) * inv;
            NVec cn = pn[a], ch = ph[a];
            const uint32_t end = std::min(seg, l - a);
            for (uint32_t i = 1; i < end; ++i) {
                cn += dn;
                ch += dh;
                pn[a + i] = cn;
                ph[a + i] = ch;
            }
            ops->lerped += 2 * uint64_t(end - 1);
        }
    }
    pn.resize(l + 1);
    ph.resize(l + 1);
    pn[l] = n2;  // the span's real end vectors are known
    ph[l] = h2;
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

render::Scene normalize_scene(const std::string& name) {
    using render::dvec3;
    auto place = [](double scale, double yaw, double pitch) {
        glm::dmat4 m = glm::rotate(glm::dmat4(1.0), glm::radians(yaw), dvec3(0, 1, 0));
        m = glm::rotate(m, glm::radians(pitch), dvec3(1, 0, 0));
        return glm::scale(m, dvec3(scale));
    };
    if (name == "sphere-lo") {
        render::Scene s = render::make_scene("sphere");
        s.name = name;
        s.objects[0].mesh = render::make_sphere(24, 12);
        return s;
    }
    if (name == "torus-lo") {
        render::Scene s = render::make_scene("torus");
        s.name = name;
        render::Mesh m = render::make_torus(1.0, 0.4, 32, 16);
        m.transform(place(1.0, 0, 35));  // as the built-in torus scene
        s.objects[0].mesh = m;
        return s;
    }
    if (name == "teapot-lo") {
        render::Scene s = render::make_scene("teapot");
        s.name = name;
        render::Mesh m = render::make_teapot(3);
        m.transform(glm::translate(glm::dmat4(1.0), dvec3(-0.2625, 0.0, 0.0)));  // centred, as the built-in one
        m.transform(place(0.55, -30, 0));
        s.objects[0].mesh = m;
        return s;
    }
    return render::make_scene(name);
}

}  // namespace methods
}  // namespace spec
