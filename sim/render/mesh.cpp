// mesh.cpp - meshes: validation and transforms, the procedural sphere and torus, Newell's teapot. OBJ files in
// and out are obj.cpp.
#include "mesh.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace spec {
namespace render {

namespace {
constexpr double kPi = 3.14159265358979323846;

bool finite(const dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Adds triangles (a, b, c) and (a, c, d) of a grid quad, skipping those of zero area (collapsed rows).
void add_quad(Mesh& m, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    for (const auto& t : {std::array<uint32_t, 3>{a, b, c}, std::array<uint32_t, 3>{a, c, d}}) {
        const dvec3 e = glm::cross(m.pos[t[1]] - m.pos[t[0]], m.pos[t[2]] - m.pos[t[0]]);
        if (glm::length(e) > 1e-14) m.tri.push_back(t);
    }
}

// Each triangle counter-clockwise around its vertices' mean normal (the front is where the normals point).
void orient_by_normals(Mesh& m) {
    for (auto& t : m.tri) {
        const dvec3 e = glm::cross(m.pos[t[1]] - m.pos[t[0]], m.pos[t[2]] - m.pos[t[0]]);
        if (glm::dot(e, m.nrm[t[0]] + m.nrm[t[1]] + m.nrm[t[2]]) < 0) std::swap(t[1], t[2]);
    }
}

// Cubic Bernstein polynomials and their derivatives.
void bernstein(double t, double b[4], double d[4]) {
    const double s = 1.0 - t;
    b[0] = s * s * s;
    b[1] = 3 * t * s * s;
    b[2] = 3 * t * t * s;
    b[3] = t * t * t;
    d[0] = -3 * s * s;
    d[1] = 3 * s * s - 6 * t * s;
    d[2] = 6 * t * s - 3 * t * t;
    d[3] = 3 * t * t;
}

// Point and derivatives of teapot patch p at (u, v); control point (i, j) = kTeapotPatches[p][4i + j].
void patch_eval(int p, double u, double v, dvec3* pt, dvec3* du, dvec3* dv) {
    double bu[4], du_[4], bv[4], dv_[4];
    bernstein(u, bu, du_);
    bernstein(v, bv, dv_);
    *pt = *du = *dv = dvec3(0);
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            const double* c = kTeapotVertices[kTeapotPatches[p][4 * i + j]];
            const dvec3 q(c[0], c[2], -c[1]);  // z-up data -> y-up
            *pt += bu[i] * bv[j] * q;
            *du += du_[i] * bv[j] * q;
            *dv += bu[i] * dv_[j] * q;
        }
    }
}

}  // namespace

void Mesh::transform(const glm::dmat4& m) {
    const glm::dmat3 nm = glm::transpose(glm::inverse(glm::dmat3(m)));
    for (auto& p : pos) p = dvec3(m * glm::dvec4(p, 1.0));
    for (auto& n : nrm) n = glm::normalize(nm * n);
}

void Mesh::validate(const std::string& what) const {
    if (tri.empty()) throw InputError(what + ": no triangles");
    if (nrm.size() != pos.size()) throw InputError(what + ": normals and positions differ in number");
    for (size_t i = 0; i < pos.size(); ++i) {
        if (!finite(pos[i])) throw InputError(what + ": vertex " + std::to_string(i + 1) + " is not finite");
        if (!finite(nrm[i])) throw InputError(what + ": normal of vertex " + std::to_string(i + 1) + " is not finite");
        if (glm::length(nrm[i]) < 1e-12) {
            throw InputError(what + ": normal of vertex " + std::to_string(i + 1) + " has zero length");
        }
    }
    for (size_t t = 0; t < tri.size(); ++t) {
        for (uint32_t v : tri[t]) {
            if (v >= pos.size()) throw InputError(what + ": triangle " + std::to_string(t + 1) + " has a bad index");
        }
    }
}

void Mesh::bounds(dvec3* lo, dvec3* hi) const {
    *lo = dvec3(INFINITY);
    *hi = dvec3(-INFINITY);
    for (const auto& p : pos) {
        *lo = glm::min(*lo, p);
        *hi = glm::max(*hi, p);
    }
}

Mesh make_sphere(int slices, int stacks) {
    Mesh m;
    for (int i = 0; i <= stacks; ++i) {
        const double th = kPi * i / stacks;  // from the north pole
        for (int j = 0; j <= slices; ++j) {
            const double ph = 2 * kPi * j / slices;
            const dvec3 p(std::sin(th) * std::sin(ph), std::cos(th), std::sin(th) * std::cos(ph));
            m.pos.push_back(p);
            m.nrm.push_back(p);
        }
    }
    const uint32_t w = uint32_t(slices) + 1;
    for (int i = 0; i < stacks; ++i) {
        for (int j = 0; j < slices; ++j) {
            const uint32_t a = i * w + j, b = (i + 1) * w + j, c = (i + 1) * w + j + 1, d = i * w + j + 1;
            add_quad(m, a, b, c, d);
        }
    }
    orient_by_normals(m);
    return m;
}

Mesh make_torus(double R, double r, int major, int minor) {
    Mesh m;
    for (int i = 0; i <= major; ++i) {
        const double u = 2 * kPi * i / major;
        const dvec3 dir(std::sin(u), 0, std::cos(u));
        for (int j = 0; j <= minor; ++j) {
            const double v = 2 * kPi * j / minor;
            const dvec3 n = dir * std::cos(v) + dvec3(0, std::sin(v), 0);
            m.pos.push_back(dir * R + n * r);
            m.nrm.push_back(n);
        }
    }
    const uint32_t w = uint32_t(minor) + 1;
    for (int i = 0; i < major; ++i) {
        for (int j = 0; j < minor; ++j) {
            const uint32_t a = i * w + j, b = i * w + j + 1, c = (i + 1) * w + j + 1, d = (i + 1) * w + j;
            add_quad(m, a, b, c, d);
        }
    }
    orient_by_normals(m);
    return m;
}

Mesh make_teapot(int subdiv) {
    Mesh m;
    const int s = subdiv;
    for (int p = 0; p < 32; ++p) {
        const uint32_t base = uint32_t(m.pos.size());
        for (int i = 0; i <= s; ++i) {
            for (int j = 0; j <= s; ++j) {
                const double u = double(i) / s, v = double(j) / s;
                dvec3 pt, du, dv;
                patch_eval(p, u, v, &pt, &du, &dv);
                dvec3 n = glm::cross(du, dv);
                if (glm::length(n) < 1e-9) {
                    // a collapsed edge (lid knob, bottom centre): the normal just inside the patch
                    dvec3 q, a, b;
                    patch_eval(p, u + (u < 0.5 ? 1e-4 : -1e-4), v + (v < 0.5 ? 1e-4 : -1e-4), &q, &a, &b);
                    n = glm::cross(a, b);
                }
                // the data's patches all have (du x dv) pointing inward, y-up flip included
                m.pos.push_back(pt);
                m.nrm.push_back(-glm::normalize(n));
            }
        }
        const uint32_t w = uint32_t(s) + 1;
        for (int i = 0; i < s; ++i) {
            for (int j = 0; j < s; ++j) {
                const uint32_t a = base + i * w + j, b = base + (i + 1) * w + j, c = base + (i + 1) * w + j + 1,
                               d = base + i * w + j + 1;
                add_quad(m, a, d, c, b);
            }
        }
    }
    orient_by_normals(m);
    return m;
}

}  // namespace render
}  // namespace spec
