// nh_bound.h - a conservative bound on N.H over a triangle or a cluster of triangles, for skipping the
// specular work where the highlight cannot be (companion paper A, docs/methods.md). Standalone: C++11 and
// <cmath> only, templated on the scalar (float, double, or a counting type: the operation counts in
// docs/methods.md come from instantiating it with sim/methods/opcount.h).
//
// The unit vectors given (vertex normals, or the halfway vectors at the vertices) end in a cap of the unit
// sphere: a cone (axis, radius r). A cap smaller than a hemisphere is geodesically convex, so it contains the
// spherical triangle (or polygon) the vectors span, hence every normal a rasterizer interpolates spherically
// between them. For N in the normals' cap and H in the halfway vectors' cap,
//     N.H <= cos(max(0, angle(axis_N, axis_H) - r_N - r_H)),
// computed here without trigonometry from the cones' (cos r, sin r) by the angle-sum formulas.
//
// Usage:
//     nhb::Vec3<float> n[3] = ..., h[3] = ...;              // unit vectors
//     auto cn = nhb::cone_of_triangle(n[0], n[1], n[2]);    // or cone_of_cluster(ptr, count) for a meshlet
//     auto ch = nhb::cone_of_triangle(h[0], h[1], h[2]);
//     if (nhb::nh_max(cn, ch, 1e-3f) < cull_below) skip();  // cull_below: where pow(N.H, n) is invisible
// margin: added to the bound to cover rounding: 1e-12 for double, 1e-3 for float (sin r = sqrt(1 - cos^2 r)
// loses digits near r = 0; tests/test_glsl.cpp measures float against double at up to 5e-4).
#pragma once

#include <cmath>

namespace nhb {

template <class T>
struct Vec3 {
    T x, y, z;
};

template <class T>
T dot(const Vec3<T>& a, const Vec3<T>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T>
Vec3<T> add(const Vec3<T>& a, const Vec3<T>& b) {
    return Vec3<T>{a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class T>
Vec3<T> sub(const Vec3<T>& a, const Vec3<T>& b) {
    return Vec3<T>{a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class T>
Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
    return Vec3<T>{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// A cap: every vector v it holds has axis.v >= cos_r. valid: radius below 90 degrees (cos_r > 0); an invalid
// cone bounds nothing.
template <class T>
struct Cone {
    Vec3<T> axis;
    T cos_r, sin_r;
    bool valid;
};

namespace detail {
// The cap around `dir` (any length) holding v[0..k-1]: its radius is set by the farthest vector.
template <class T>
bool cap_around(const Vec3<T>& dir, const Vec3<T>* v, int k, Cone<T>* c) {
    using std::sqrt;
    const T len2 = dot(dir, dir);
    if (!(len2 > T(0))) return false;
    const T inv = T(1) / sqrt(len2);
    c->axis = Vec3<T>{dir.x * inv, dir.y * inv, dir.z * inv};
    T lo = dot(c->axis, v[0]);
    for (int i = 1; i < k; ++i) {
        const T d = dot(c->axis, v[i]);
        if (d < lo) lo = d;
    }
    c->cos_r = lo;
    return true;
}

template <class T>
Cone<T> finish(Cone<T> c, bool found) {
    using std::sqrt;
    c.valid = found && c.cos_r > T(0);
    c.sin_r = c.valid ? sqrt(T(1) - c.cos_r * c.cos_r) : T(1);
    return c;
}
}  // namespace detail

// Per cluster: the cap around the normalized sum of the k unit vectors (not the smallest cap, one pass).
template <class T>
Cone<T> cone_of_cluster(const Vec3<T>* v, int k) {
    Vec3<T> s = v[0];
    for (int i = 1; i < k; ++i) s = add(s, v[i]);
    Cone<T> c{};
    const bool found = detail::cap_around(s, v, k, &c);
    return detail::finish(c, found);
}

// Per triangle: the tightest of five caps (each edge as a diameter, the circumscribed cap, the centroid's).
template <class T>
Cone<T> cone_of_triangle(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
    const Vec3<T> v[3] = {a, b, c};
    const Vec3<T> sum = add(add(a, b), c);
    Vec3<T> circ = cross(sub(b, a), sub(c, a));
    if (dot(circ, sum) < T(0)) circ = Vec3<T>{-circ.x, -circ.y, -circ.z};
    const Vec3<T> dirs[5] = {add(a, b), add(b, c), add(c, a), circ, sum};
    Cone<T> best{};
    bool found = false;
    for (int i = 0; i < 5; ++i) {
        Cone<T> t{};
        if (detail::cap_around(dirs[i], v, 3, &t) && (!found || t.cos_r > best.cos_r)) {
            best = t;
            found = true;
        }
    }
    return detail::finish(best, found);
}

// >= N.H for every N in cone n and H in cone h (1 when either cone is invalid, or they overlap).
template <class T>
T nh_max(const Cone<T>& n, const Cone<T>& h, T margin) {
    using std::sqrt;
    if (!n.valid || !h.valid) return T(1);
    const T c_th = dot(n.axis, h.axis);
    const Vec3<T> x = cross(n.axis, h.axis);
    const T s_th = sqrt(dot(x, x));
    // alpha = r_N + r_H < 180 degrees
    const T c_al = n.cos_r * h.cos_r - n.sin_r * h.sin_r;
    const T s_al = n.sin_r * h.cos_r + n.cos_r * h.sin_r;
    if (c_th >= c_al) return T(1);  // the axes' angle is at most alpha: the caps overlap
    const T b = c_th * c_al + s_th * s_al + margin;
    return b < T(1) ? b : T(1);
}

}  // namespace nhb
