#include "highlight.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "highlight_tests.h"
#include "nh_bound.h"
#include "span_host.h"

namespace spec {
namespace methods {

namespace {
constexpr double kPi = 3.14159265358979323846;

double angle(const Vec& a, const Vec& b) { return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)); }

double det3(const Vec& a, const Vec& b, const Vec& c) { return glm::dot(a, glm::cross(b, c)); }

nhb::Vec3<double> v3(const Vec& v) { return nhb::Vec3<double>{v.x, v.y, v.z}; }
}  // namespace

PaperTestResult paper_test(const Vec& na, const Vec& nb, const Vec& nc, const Vec& h, ProjPlane plane) {
    const PaperVerdict<double> v = paper_test_t(v3(na), v3(nb), v3(nc), v3(h), plane == ProjPlane::dominant);
    PaperTestResult r;
    r.inside = v.inside;
    r.degenerate = v.degenerate;
    return r;
}

double diameter(const Vec& a, const Vec& b, const Vec& c) {
    // the pair with the smallest dot product, its angle by atan2 (accurate for small angles too)
    const double ab = glm::dot(a, b), bc = glm::dot(b, c), ca = glm::dot(c, a);
    if (ab <= bc && ab <= ca) return angle(a, b);
    return bc <= ca ? angle(b, c) : angle(c, a);
}

Cone bounding_cone(const Vec& a, const Vec& b, const Vec& c) {
    const nhb::Cone<double> k = nhb::cone_of_triangle(v3(a), v3(b), v3(c));
    Cone r;
    r.axis = Vec(k.axis.x, k.axis.y, k.axis.z);
    r.valid = k.valid;
    r.radius = k.valid ? std::atan2(k.sin_r, k.cos_r) : kPi;
    return r;
}

bool spherical_inside(const Vec& na, const Vec& nb, const Vec& nc, const Vec& h) {
    // fast path: the centroid direction within 90 degrees of every normal (so they lie in an open
    // hemisphere), a proper triangle, H in that hemisphere: three triple products decide
    const int fast = spherical_sign_t(v3(na), v3(nb), v3(nc), v3(h));
    if (fast >= 0) return fast == 1;
    const Cone cone = bounding_cone(na, nb, nc);
    if (!cone.valid) return true;
    if (glm::dot(h, cone.axis) <= 0) return false;  // the other hemisphere (where -h would pass the signs)
    const double s = det3(na, nb, nc);
    if (std::fabs(s) < 1e-14) {
        // the three normals on one great circle (or equal): the "triangle" is an arc or a point
        return angle(h, cone.axis) <= cone.radius + 1e-12 && std::fabs(det3(na, nb, h)) + std::fabs(det3(nb, nc, h)) +
                                                                    std::fabs(det3(nc, na, h)) < 1e-12;
    }
    const double d1 = det3(na, nb, h), d2 = det3(nb, nc, h), d3 = det3(nc, na, h);
    if (s > 0) return d1 >= 0 && d2 >= 0 && d3 >= 0;
    return d1 <= 0 && d2 <= 0 && d3 <= 0;
}

TriangleBound triangle_bound(const Vec n[3], const Vec h[3], bool tight) {
    TriangleBound t;
    const nhb::Vec3<double> vn[3] = {v3(n[0]), v3(n[1]), v3(n[2])}, vh[3] = {v3(h[0]), v3(h[1]), v3(h[2])};
    const nhb::Cone<double> cn = tight ? nhb::cone_of_triangle(vn[0], vn[1], vn[2]) : nhb::cone_of_cluster(vn, 3);
    const nhb::Cone<double> ch = tight ? nhb::cone_of_triangle(vh[0], vh[1], vh[2]) : nhb::cone_of_cluster(vh, 3);
    if (!cn.valid || !ch.valid) return t;
    t.valid = true;
    t.nh_max = nhb::nh_max(cn, ch, 1e-12);
    // a span's end normals (halfway vectors) lie in the spherical triangle, so their angle is at most the
    // triangle's diameter; the host's sinusoid and the true N.H agree at both ends and have second
    // derivatives of at most (psi + phi)^2, so they differ by at most (psi + phi)^2 / 4 (docs/methods.md)
    const double s = diameter(n[0], n[1], n[2]) + diameter(h[0], h[1], h[2]);
    t.slack = 0.25 * s * s;
    t.b_host = std::min(1.0, t.nh_max + t.slack + 1e-9);
    return t;
}

uint32_t core_output_sup(const Model& m, unsigned n, double strength, double b_host, uint32_t max_len) {
    const Format& f = m.format();
    const double c_max = std::ldexp(std::ldexp(1.0, f.c_w) - 1.0, -f.c_w);
    auto qc = [&](double c) { return m.quantize_c(std::min(std::max(c, 0.0), c_max)); };
    if (n == 0) return m.pixel(qc(strength), 0, 0);  // cos^0: the core outputs C everywhere
    if (b_host < 0) return 0;  // N.H < 0 over every span: the host writes C = 0 (kNoHighlight)
    // the quantized register-8 angle is within (l + 1) / 2 LSB of the host's exact zeta0 + i dzeta
    const double margin = std::ldexp(double(max_len) + 2.0, -f.ang_frac) + 1e-9;
    const int grid = 4096;
    uint32_t sup = 0;
    for (int j = 0; j < grid; ++j) {
        const double a_lo = double(j) / grid, a_hi = double(j + 1) / grid;
        const uint32_t c = qc(strength * std::pow(a_hi, double(n)));
        if (c == 0) continue;
        // A cos(zeta) <= b_host: |zeta| >= acos(b_host / A), smallest at the interval's lowest A
        const double zmin = a_lo <= b_host ? 0.0 : std::acos(b_host / a_lo);
        const double z = std::max(0.0, zmin - margin);
        const int64_t raw = int64_t(std::floor(std::ldexp(z, f.ang_frac)));
        sup = std::max(sup, m.pixel(c, std::min(raw, m.angle_max()), n));
    }
    return sup;
}

double cull_threshold(const Model& m, unsigned n, double strength, uint32_t max_len) {
    if (n == 0) return core_output_sup(m, 0, strength, 1.0, max_len) == 0 ? 2.0 : -2.0;
    if (core_output_sup(m, n, strength, 1.0, max_len) == 0) return 2.0;  // nothing is ever lit
    if (core_output_sup(m, n, strength, 0.0, max_len) != 0) return 0.0;  // only N.H < 0 everywhere
    double lo = 0.0, hi = 1.0;  // sup(lo) == 0, sup(hi) != 0
    for (int it = 0; it < 32; ++it) {
        const double mid = 0.5 * (lo + hi);
        if (core_output_sup(m, n, strength, mid, max_len) == 0) lo = mid;
        else hi = mid;
    }
    return lo;
}

void triangle_vectors(const render::Scene& sc, const render::Frame& f, uint32_t tri_id, Vec n[3], Vec h[3]) {
    uint32_t base = 0;
    size_t o = 0;
    while (o < sc.objects.size() && tri_id >= base + sc.objects[o].mesh.tri.size()) {
        base += uint32_t(sc.objects[o].mesh.tri.size());
        ++o;
    }
    const render::Mesh& mesh = sc.objects.at(o).mesh;
    const auto& tr = mesh.tri.at(tri_id - base);
    const bool flip = tri_id < f.flipped.size() && f.flipped[tri_id];
    for (int k = 0; k < 3; ++k) {
        // as rasterize() does it
        const Vec p = mesh.pos[tr[k]];
        const Vec nn = glm::normalize(mesh.nrm[tr[k]]);
        const Vec hv = f.light_dir + glm::normalize(sc.camera.eye - p);
        h[k] = glm::length(hv) > 1e-12 ? glm::normalize(hv) : nn;
        n[k] = flip ? -nn : nn;
    }
}

CullResult cull_spans(const render::Scene& sc, const render::Frame& f, const Model& m, bool tight) {
    CullResult r;
    r.keep.assign(f.spans.size(), 1);
    std::vector<double> threshold(sc.objects.size());
    for (size_t o = 0; o < sc.objects.size(); ++o) {
        const auto& mat = sc.objects[o].mat;
        threshold[o] = cull_threshold(m, mat.n, sc.light.intensity * mat.ks, uint32_t(f.w));
    }
    std::vector<int8_t> decision(f.flipped.size(), -1);  // -1 unknown, 0 keep, 1 cull
    for (size_t k = 0; k < f.spans.size(); ++k) {
        const render::Span& sp = f.spans[k];
        int8_t& d = decision.at(sp.tri);
        if (d < 0) {
            Vec n[3], h[3];
            triangle_vectors(sc, f, sp.tri, n, h);
            const TriangleBound b = triangle_bound(n, h, tight);
            ++r.triangles;
            if (!b.valid) ++r.unbounded;
            d = b.b_host < threshold[sp.obj] ? 1 : 0;
            if (d) ++r.triangles_culled;
        }
        ++r.spans;
        r.pixels += sp.l + 1;
        if (d) {
            r.keep[k] = 0;
            ++r.spans_culled;
            r.pixels_culled += sp.l + 1;
        }
    }
    return r;
}

render::Frame kept_frame(const render::Frame& f, const CullResult& c) {
    render::Frame k = f;
    k.spans.clear();
    for (size_t i = 0; i < f.spans.size(); ++i) {
        if (c.keep[i]) k.spans.push_back(f.spans[i]);
    }
    return k;
}

}  // namespace methods
}  // namespace spec
