#include "raster.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace spec {
namespace render {

namespace {
constexpr double kNear = 0.05, kFar = 1000.0;

struct ScreenVertex {
    double x = 0, y = 0, z = 0;  // pixels (y down), NDC depth
    dvec3 n, h;                  // unit normal and halfway vector
    bool ok = false;             // in front of the near plane
};

struct EdgePoint {
    double x, z;
    dvec3 n, h;
};

EdgePoint on_edge(const ScreenVertex& a, const ScreenVertex& b, double yc) {
    const double s = std::min(1.0, std::max(0.0, (yc - a.y) / (b.y - a.y)));
    return {a.x + s * (b.x - a.x), a.z + s * (b.z - a.z), host::slerp(a.n, b.n, s), host::slerp(a.h, b.h, s)};
}

void raster_triangle(Frame& f, std::vector<Span>& out, ScreenVertex v[3], uint32_t id, uint32_t obj) {
    std::sort(v, v + 3, [](const ScreenVertex& a, const ScreenVertex& b) { return a.y < b.y; });
    // pixel rows whose centre y + 0.5 is in [v0.y, v2.y); columns whose centre is in [xl, xr)
    const int y_lo = std::max(0, int(std::ceil(v[0].y - 0.5)));
    const int y_hi = std::min(f.h - 1, int(std::ceil(v[2].y - 0.5)) - 1);
    for (int y = y_lo; y <= y_hi; ++y) {
        const double yc = y + 0.5;
        EdgePoint p = on_edge(v[0], v[2], yc);
        EdgePoint q = yc < v[1].y ? on_edge(v[0], v[1], yc) : on_edge(v[1], v[2], yc);
        if (q.x < p.x) std::swap(p, q);
        const double span_w = q.x - p.x;
        if (!(span_w > 0)) continue;
        const int x_lo = std::max(0, int(std::ceil(p.x - 0.5)));
        const int x_hi = std::min(f.w - 1, int(std::ceil(q.x - 0.5)) - 1);
        if (x_hi < x_lo) continue;
        for (int x = x_lo; x <= x_hi; ++x) {
            const double u = (x + 0.5 - p.x) / span_w;
            const double z = p.z + u * (q.z - p.z);
            const size_t k = size_t(y) * size_t(f.w) + size_t(x);
            if (z < f.depth[k]) {
                f.depth[k] = z;
                f.tri_id[k] = int32_t(id);
            }
        }
        Span s;
        s.y = y;
        s.x0 = x_lo;
        s.l = uint32_t(x_hi - x_lo);
        s.tri = id;
        s.obj = obj;
        const double u0 = (x_lo + 0.5 - p.x) / span_w, u1 = (x_hi + 0.5 - p.x) / span_w;
        s.ends.n1 = host::slerp(p.n, q.n, u0);
        s.ends.n2 = host::slerp(p.n, q.n, u1);
        s.ends.h1 = host::slerp(p.h, q.h, u0);
        s.ends.h2 = host::slerp(p.h, q.h, u1);
        out.push_back(s);
    }
}
}  // namespace

Frame rasterize(const Scene& sc, int w, int h) {
    Frame f;
    f.w = w;
    f.h = h;
    f.tri_id.assign(size_t(w) * size_t(h), -1);
    f.depth.assign(size_t(w) * size_t(h), std::numeric_limits<double>::infinity());
    const Camera& cam = sc.camera;
    const glm::dmat4 view = glm::lookAt(cam.eye, cam.target, cam.up);
    const glm::dmat4 proj = glm::perspective(glm::radians(cam.fov_deg), double(w) / double(h), kNear, kFar);
    const glm::dmat4 pv = proj * view;
    f.light_dir = glm::normalize(sc.light.dir);
    std::vector<Span> all;
    uint32_t tri_base = 0;
    for (size_t o = 0; o < sc.objects.size(); ++o) {
        const Mesh& m = sc.objects[o].mesh;
        std::vector<ScreenVertex> sv(m.pos.size());
        for (size_t i = 0; i < m.pos.size(); ++i) {
            const glm::dvec4 c = pv * glm::dvec4(m.pos[i], 1.0);
            ScreenVertex& s = sv[i];
            s.ok = c.w >= kNear;
            if (!s.ok) continue;
            s.x = (c.x / c.w + 1.0) * 0.5 * w;
            s.y = (1.0 - c.y / c.w) * 0.5 * h;
            s.z = c.z / c.w;
            s.n = glm::normalize(m.nrm[i]);
            const dvec3 hv = f.light_dir + glm::normalize(cam.eye - m.pos[i]);
            // L = -V: no halfway vector; N.H is then irrelevant (the light is exactly behind the surface
            // point as seen from the eye), take H = N's direction so that nothing is undefined.
            s.h = glm::length(hv) > 1e-12 ? glm::normalize(hv) : s.n;
        }
        f.flipped.resize(tri_base + m.tri.size(), 0);
        for (size_t t = 0; t < m.tri.size(); ++t) {
            const auto& tr = m.tri[t];
            ScreenVertex v[3] = {sv[tr[0]], sv[tr[1]], sv[tr[2]]};
            ++f.triangles;
            if (!v[0].ok || !v[1].ok || !v[2].ok) {
                ++f.skipped_near;
                continue;
            }
            const double area = (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[2].x - v[0].x) * (v[1].y - v[0].y);
            if (std::fabs(area) < 1e-12) continue;
            if (area > 0) {
                // seen from behind (counter-clockwise in world = clockwise on a y-down screen is the front):
                // two-sided lighting, the normals face the viewer
                ++f.back_facing;
                f.flipped[tri_base + t] = 1;
                for (auto& x : v) x.n = -x.n;
            }
            raster_triangle(f, all, v, tri_base + uint32_t(t), uint32_t(o));
        }
        tri_base += uint32_t(m.tri.size());
    }
    for (const Span& s : all) {
        bool any = false;
        for (uint32_t i = 0; i <= s.l && !any; ++i) any = f.visible(s, i);
        if (any) f.spans.push_back(s);
        else ++f.hidden_spans;
    }
    return f;
}

}  // namespace render
}  // namespace spec
