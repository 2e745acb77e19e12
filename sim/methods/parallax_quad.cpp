// parallax_quad.cpp - the relief-mapped quad of `specsim parallax --out-dir` (parallax_quad.h).
#include "parallax_quad.h"

#include <algorithm>
#include <cmath>

namespace spec {
namespace methods {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

namespace {
struct Rgb {
    double r, g, b;
};

Rgb albedo(const std::string& map, double h, double u, double v) {
    auto mix = [](Rgb a, Rgb b, double t) {
        return Rgb{a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
    };
    const double n = fbm(u, v, 32, 3, 41);
    if (map == "bricks") {
        return h < 0.35 ? mix(Rgb{0.55, 0.55, 0.52}, Rgb{0.7, 0.7, 0.66}, n)
                        : mix(Rgb{0.55, 0.2, 0.12}, Rgb{0.8, 0.38, 0.22}, 0.6 * n + 0.4 * h);
    }
    if (map == "rocks") return mix(Rgb{0.25, 0.22, 0.2}, Rgb{0.78, 0.72, 0.62}, 0.7 * h + 0.3 * n);
    if (map == "bumps") {
        const bool check = (int(std::floor(u * 16)) + int(std::floor(v * 16))) % 2 == 0;
        return mix(check ? Rgb{0.2, 0.3, 0.6} : Rgb{0.85, 0.85, 0.9}, Rgb{0.9, 0.6, 0.2}, h * h);
    }
    return mix(Rgb{0.1, 0.3, 0.5}, Rgb{0.7, 0.9, 0.95}, h);
}
}  // namespace

render::Image render_quad(const HeightMap& m, const QuadView& q, Pm method, std::vector<double>* uv_err) {
    render::Image img(q.width, q.height, 12, 14, 20);
    if (uv_err) uv_err->assign(size_t(q.width) * size_t(q.height), -1.0);
    const double e = q.elevation_deg * kPi / 180;
    const double dist = 1.75;
    const double ex = 0, ey = -dist * std::cos(e), ez = dist * std::sin(e);  // eye; looks at the origin
    // camera basis: forward to the origin, up as close to +z as possible
    double fx = -ex, fy = -ey, fz = -ez;
    const double fl = std::sqrt(fx * fx + fy * fy + fz * fz);
    fx /= fl, fy /= fl, fz /= fl;
    double rx = fy * 1 - fz * 0, ry = fz * 0 - fx * 1, rz = 0;  // forward x (0, 0, 1)
    const double rl = std::sqrt(rx * rx + ry * ry + rz * rz);
    rx /= rl, ry /= rl;
    const double ux = ry * fz - rz * fy, uy = rz * fx - rx * fz, uz = rx * fy - ry * fx;
    const double tan_half = std::tan(0.5 * 40.0 * kPi / 180);
    const double aspect = double(q.width) / q.height;
    const double threshold = q.threshold > 0 ? q.threshold : q.s / 512;
    double lx = -0.45, ly = 0.35, lz = 0.82;
    const double ll = std::sqrt(lx * lx + ly * ly + lz * lz);
    lx /= ll, ly /= ll, lz /= ll;
    for (int py = 0; py < q.height; ++py) {
        for (int px = 0; px < q.width; ++px) {
            const double sx = (2 * (px + 0.5) / q.width - 1) * tan_half * aspect;
            const double sy = (1 - 2 * (py + 0.5) / q.height) * tan_half;
            const double dx = fx + sx * rx + sy * ux, dy = fy + sx * ry + sy * uy, dz = fz + sx * rz + sy * uz;
            if (dz >= 0) continue;
            const double t = -ez / dz;
            const double wx = ex + t * dx, wy = ey + t * dy;
            if (std::fabs(wx) > 1 || std::fabs(wy) > 1) continue;
            const double u0 = (wx + 1) * 0.5 * q.repeats, v0 = (wy + 1) * 0.5 * q.repeats;
            double vx = ex - wx, vy = ey - wy, vz = ez;
            const double vl = std::sqrt(vx * vx + vy * vy + vz * vz);
            const View V{vx / vl, vy / vl, vz / vl};
            const Hit hit = run_method(method, m, q.s, u0, v0, V, q.budget, threshold);
            if (uv_err) {
                const Hit ex_hit = exact(m, q.s, u0, v0, V);
                (*uv_err)[size_t(py) * size_t(q.width) + size_t(px)] =
                    std::hypot(hit.u - ex_hit.u, hit.v - ex_hit.v) * m.size;
            }
            double gu, gv;
            m.gradient(hit.u, hit.v, &gu, &gv);
            double nx = -q.s * gu, ny = -q.s * gv, nz = 1;
            const double nl = std::sqrt(nx * nx + ny * ny + nz * nz);
            nx /= nl, ny /= nl, nz /= nl;
            double hx = lx + V.u, hy = ly + V.v, hz = lz + V.h;
            const double hl = std::sqrt(hx * hx + hy * hy + hz * hz);
            hx /= hl, hy /= hl, hz /= hl;
            const double diff = std::max(0.0, nx * lx + ny * ly + nz * lz);
            const double spec = 0.25 * std::pow(std::max(0.0, nx * hx + ny * hy + nz * hz), 40.0);
            const Rgb a = albedo(m.name, m.at(hit.u, hit.v), hit.u, hit.v);
            uint8_t* p = img.at(px, py);
            const double c[3] = {a.r * (0.18 + 0.82 * diff) + spec, a.g * (0.18 + 0.82 * diff) + spec,
                                 a.b * (0.18 + 0.82 * diff) + spec};
            for (int k = 0; k < 3; ++k) p[k] = uint8_t(std::lround(std::min(1.0, std::max(0.0, c[k])) * 255));
        }
    }
    return img;
}

}  // namespace methods
}  // namespace spec
