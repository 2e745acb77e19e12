#include "polygon.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace spec {
namespace render {

using glm::dvec3;

dvec3 newell_normal(const std::vector<dvec3>& pts) {
    dvec3 c(0.0);
    for (const dvec3& p : pts) c += p / double(pts.size());
    dvec3 n(0.0);
    for (size_t i = 0; i < pts.size(); ++i) n += glm::cross(pts[i] - c, pts[(i + 1) % pts.size()] - c);
    return n;
}

namespace {
struct P2 {
    double x, y;
};
double orient(const P2& a, const P2& b, const P2& c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

// p inside or on the boundary of the counter-clockwise triangle (a, b, c), within eps
bool in_triangle(const P2& p, const P2& a, const P2& b, const P2& c, double eps) {
    return orient(a, b, p) >= -eps && orient(b, c, p) >= -eps && orient(c, a, p) >= -eps;
}
bool same(const P2& a, const P2& b) { return a.x == b.x && a.y == b.y; }
}  // namespace

std::vector<std::array<uint32_t, 3>> triangulate_polygon(const std::vector<dvec3>& pts) {
    std::vector<std::array<uint32_t, 3>> out;
    const size_t n = pts.size();
    if (n < 3) return out;
    const dvec3 nn = newell_normal(pts);
    const double len = glm::length(nn);
    if (!(len > 0) || !std::isfinite(len)) return out;
    const dvec3 w = nn / len;
    // u, v in the face's plane with u x v = w: the polygon winds counter-clockwise in (u, v)
    const dvec3 a = std::fabs(w.x) < 0.6 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
    const dvec3 u = glm::normalize(glm::cross(a, w));
    const dvec3 v = glm::cross(w, u);
    std::vector<P2> q(n);
    double ext = 0;
    for (size_t i = 0; i < n; ++i) {
        q[i] = {glm::dot(pts[i], u), glm::dot(pts[i], v)};
        ext = std::max({ext, std::fabs(q[i].x), std::fabs(q[i].y)});
    }
    double minx = q[0].x, maxx = q[0].x, miny = q[0].y, maxy = q[0].y;
    for (const P2& p : q) {
        minx = std::min(minx, p.x), maxx = std::max(maxx, p.x), miny = std::min(miny, p.y), maxy = std::max(maxy, p.y);
    }
    const double size = std::max(maxx - minx, maxy - miny);
    const double eps = 1e-12 * size * size;   // areas below this are zero (rounding of the projection)
    // the ring of vertices still to clip, without repeated points
    std::vector<uint32_t> ring;
    for (uint32_t i = 0; i < n; ++i) {
        if (ring.empty() || !same(q[ring.back()], q[i])) ring.push_back(i);
    }
    while (ring.size() > 1 && same(q[ring.front()], q[ring.back()])) ring.pop_back();
    size_t k = 0;
    size_t misses = 0;   // vertices tried since the last clip
    while (ring.size() > 3) {
        const size_t m = ring.size();
        k %= m;
        const uint32_t ia = ring[(k + m - 1) % m], ib = ring[k], ic = ring[(k + 1) % m];
        const double o = orient(q[ia], q[ib], q[ic]);
        bool ear = false;
        if (std::fabs(o) <= eps) {
            // a, b, c on a line (b between them, or a spike): no area to cover, drop b without a triangle
            ring.erase(ring.begin() + long(k));
            misses = 0;
            continue;
        }
        if (o > eps) {
            ear = true;
            for (size_t j = 0; j < m && ear; ++j) {
                const uint32_t ip = ring[j];
                if (ip == ia || ip == ib || ip == ic) continue;
                if (same(q[ip], q[ia]) || same(q[ip], q[ib]) || same(q[ip], q[ic])) continue;
                if (in_triangle(q[ip], q[ia], q[ib], q[ic], eps)) ear = false;
            }
        }
        if (ear) {
            out.push_back({ia, ib, ic});
            ring.erase(ring.begin() + long(k));
            misses = 0;
            continue;
        }
        if (++misses > m) {
            // no ear left (a self-intersecting or badly non-planar polygon): a fan of what remains
            for (size_t j = 1; j + 1 < ring.size(); ++j) {
                if (orient(q[ring[0]], q[ring[j]], q[ring[j + 1]]) > eps) out.push_back({ring[0], ring[j], ring[j + 1]});
            }
            return out;
        }
        ++k;
    }
    if (ring.size() == 3 && orient(q[ring[0]], q[ring[1]], q[ring[2]]) > eps) out.push_back({ring[0], ring[1], ring[2]});
    return out;
}

}  // namespace render
}  // namespace spec
