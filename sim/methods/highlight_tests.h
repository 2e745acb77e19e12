// highlight_tests.h - the per-triangle tests of companion paper A, templated on the scalar so that
// sim/methods/opcount.h can count their operations (highlight.h wraps them for glm vectors).
//   paper_test_t      the paper's projected test: lines through the projected arc midpoints, parallel to the
//                     projected chords; H' inside iff on the opposite vertex's side of all three
//   spherical_sign_t  the exact test for normals in an open hemisphere: three triple products
#pragma once

#include <cmath>

#include "nh_bound.h"

namespace spec {
namespace methods {

template <class T>
struct PaperVerdict {
    bool inside = false;      // H' inside the triangle abc of the three lines
    bool degenerate = false;  // a projected vertex on its line (zero-area projection): reported inside
};

// drop: the coordinate dropped by the projection (0 x, 1 y, 2 z; the paper's XOY is 2); dominant = true
// chooses the coordinate in which |h| is largest instead.
template <class T>
PaperVerdict<T> paper_test_t(const nhb::Vec3<T>& na, const nhb::Vec3<T>& nb, const nhb::Vec3<T>& nc,
                             const nhb::Vec3<T>& h, bool dominant) {
    using std::fabs;
    using std::sqrt;
    int drop = 2;
    if (dominant) {
        const T ax = fabs(h.x), ay = fabs(h.y), az = fabs(h.z);
        drop = (ax >= ay && ax >= az) ? 0 : (ay >= az ? 1 : 2);
    }
    struct P2 {
        T x, y;
    };
    auto proj = [&](const nhb::Vec3<T>& v) {
        return drop == 0 ? P2{v.y, v.z} : drop == 1 ? P2{v.z, v.x} : P2{v.x, v.y};
    };
    // the arc midpoint, eq. (3): (Na + Nb) / (2 cos(psi / 2)) = (Na + Nb) / |Na + Nb| for unit vectors
    auto mid = [&](const nhb::Vec3<T>& a, const nhb::Vec3<T>& b) {
        const nhb::Vec3<T> s = nhb::add(a, b);
        const P2 p = proj(s);
        const T len2 = nhb::dot(s, s);
        if (!(len2 > T(1e-300))) return proj(a);
        const T inv = T(1) / sqrt(len2);
        return P2{p.x * inv, p.y * inv};
    };
    const nhb::Vec3<T>* n[3] = {&na, &nb, &nc};
    const P2 hp = proj(h);
    PaperVerdict<T> r;
    r.inside = true;
    for (int k = 0; k < 3; ++k) {
        const nhb::Vec3<T>& b = *n[(k + 1) % 3];
        const nhb::Vec3<T>& c = *n[(k + 2) % 3];
        const P2 pb = proj(b), pc = proj(c), pk = proj(*n[k]);
        const P2 dir{pc.x - pb.x, pc.y - pb.y};
        const P2 m = mid(b, c);
        const T sv = dir.x * (pk.y - m.y) - dir.y * (pk.x - m.x);  // side of the opposite vertex
        const T sh = dir.x * (hp.y - m.y) - dir.y * (hp.x - m.x);  // side of H'
        if (fabs(sv) < T(1e-15) || dir.x * dir.x + dir.y * dir.y < T(1e-30)) {
            r.degenerate = true;  // no area here: no decision, say inside
            continue;
        }
        if ((sv > T(0) && sh < T(0)) || (sv < T(0) && sh > T(0))) r.inside = false;
    }
    return r;
}

// The exact test where it is fast: 1 inside (or on the boundary), 0 outside, -1 undecided here (the
// normals not within an open hemisphere around their sum, or nearly on one great circle).
template <class T>
int spherical_sign_t(const nhb::Vec3<T>& na, const nhb::Vec3<T>& nb, const nhb::Vec3<T>& nc,
                     const nhb::Vec3<T>& h) {
    using std::fabs;
    const nhb::Vec3<T> g = nhb::add(nhb::add(na, nb), nc);
    const T s0 = nhb::dot(na, nhb::cross(nb, nc));
    if (!(nhb::dot(g, na) > T(0) && nhb::dot(g, nb) > T(0) && nhb::dot(g, nc) > T(0)) || fabs(s0) < T(1e-14)) {
        return -1;
    }
    if (nhb::dot(h, g) <= T(0)) return 0;
    const T d1 = nhb::dot(na, nhb::cross(nb, h)), d2 = nhb::dot(nb, nhb::cross(nc, h)),
            d3 = nhb::dot(nc, nhb::cross(na, h));
    if (s0 > T(0)) return d1 >= T(0) && d2 >= T(0) && d3 >= T(0);
    return d1 <= T(0) && d2 <= T(0) && d3 <= T(0);
}

}  // namespace methods
}  // namespace spec
