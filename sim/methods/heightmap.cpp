// heightmap.cpp - the generated height maps (heightmap.h).
#include "heightmap.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace spec {
namespace methods {

namespace {
constexpr double kPi = 3.14159265358979323846;

int wrap(int i, int n) {
    const int r = i % n;
    return r < 0 ? r + n : r;
}

double frac(double x) { return x - std::floor(x); }

// Deterministic hash to [0, 1) (no library distribution: the same maps everywhere).
double hash01(uint32_t a, uint32_t b, uint32_t seed) {
    uint32_t h = a * 0x8da6b343u ^ b * 0xd8163841u ^ seed * 0xcb1ab31fu;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return double(h >> 8) / double(1u << 24);
}

double smoothstep(double e0, double e1, double x) {
    const double t = std::min(1.0, std::max(0.0, (x - e0) / (e1 - e0)));
    return t * t * (3.0 - 2.0 * t);
}

// Periodic value noise of integer frequency f on [0, 1)^2.
double value_noise(double u, double v, int f, uint32_t seed) {
    const double x = frac(u) * f, y = frac(v) * f;
    const int i = int(std::floor(x)), j = int(std::floor(y));
    const double fx = x - i, fy = y - j;
    auto at = [&](int a, int b) { return hash01(uint32_t(wrap(a, f)), uint32_t(wrap(b, f)), seed); };
    const double sx = fx * fx * (3 - 2 * fx), sy = fy * fy * (3 - 2 * fy);
    const double a = at(i, j) + sx * (at(i + 1, j) - at(i, j));
    const double b = at(i, j + 1) + sx * (at(i + 1, j + 1) - at(i, j + 1));
    return a + sy * (b - a);
}

double fbm_impl(double u, double v, int f0, int octaves, uint32_t seed) {
    double s = 0, amp = 0.5, norm = 0;
    for (int o = 0; o < octaves; ++o) {
        s += amp * value_noise(u, v, f0 << o, seed + uint32_t(o));
        norm += amp;
        amp *= 0.5;
    }
    return s / norm;
}


double h_waves(double u, double v) {
    return 0.5 + 0.25 * std::sin(2 * kPi * (2 * u + 0.25 * std::sin(2 * kPi * v))) + 0.25 * std::sin(2 * kPi * 3 * v);
}

double h_bumps(double u, double v) {
    const int g = 4;
    const double x = frac(u) * g, y = frac(v) * g;
    const double dx = x - std::floor(x) - 0.5, dy = y - std::floor(y) - 0.5;
    const double r = std::sqrt(dx * dx + dy * dy) / 0.42;
    return r < 1 ? std::sqrt(1 - r * r) : 0.0;
}

double h_bricks(double u, double v) {
    const int rows = 4;
    const double bw = 0.5, bh = 1.0 / rows, mortar = 0.012, bevel = 0.025;
    const double y = frac(v);
    const int row = int(std::floor(y / bh));
    const double x = frac(u + (row % 2 ? 0.25 : 0.0));
    const int col = int(std::floor(x / bw));
    const double lx = x - col * bw, ly = y - row * bh;
    const double e = std::min({lx, bw - lx, ly, bh - ly}) - mortar;
    const double brick = 0.82 + 0.18 * hash01(uint32_t(col), uint32_t(row), 7);
    const double grain = 0.06 * fbm_impl(u, v, 16, 3, 11);
    return std::min(1.0, std::max(0.0, smoothstep(0.0, bevel, e) * (brick - grain)));
}

double h_rocks(double u, double v) {
    const int g = 6;
    const double x = frac(u) * g, y = frac(v) * g;
    const int ci = int(std::floor(x)), cj = int(std::floor(y));
    double f1 = 1e9, f2 = 1e9;
    int id1 = 0;
    for (int dj = -1; dj <= 1; ++dj) {
        for (int di = -1; di <= 1; ++di) {
            const int a = ci + di, b = cj + dj;
            const uint32_t wa = uint32_t(wrap(a, g)), wb = uint32_t(wrap(b, g));
            const double px = a + 0.15 + 0.7 * hash01(wa, wb, 21), py = b + 0.15 + 0.7 * hash01(wa, wb, 22);
            const double d = std::hypot(x - px, y - py);
            if (d < f1) {
                f2 = f1;
                f1 = d;
                id1 = int(wb) * g + int(wa);
            } else if (d < f2) {
                f2 = d;
            }
        }
    }
    const double stone = 0.6 + 0.35 * hash01(uint32_t(id1), 3, 23);
    const double edge = smoothstep(0.0, 0.35, f2 - f1);
    const double dome = 1.0 - 0.25 * f1 * f1;
    const double h = stone * edge * dome + 0.12 * fbm_impl(u, v, 8, 4, 31) - 0.04;
    return std::min(1.0, std::max(0.0, h));
}
}  // namespace

double fbm(double u, double v, int f0, int octaves, uint32_t seed) { return fbm_impl(u, v, f0, octaves, seed); }

float HeightMap::tex(int i, int j) const { return texel[size_t(wrap(j, size)) * size_t(size) + size_t(wrap(i, size))]; }

double HeightMap::at(double u, double v) const {
    const double x = u * size - 0.5, y = v * size - 0.5;
    const double fi = std::floor(x), fj = std::floor(y);
    const int i = int(std::fmod(fi, double(size))), j = int(std::fmod(fj, double(size)));
    const double fx = x - fi, fy = y - fj;
    const double a = tex(i, j) + fx * (tex(i + 1, j) - tex(i, j));
    const double b = tex(i, j + 1) + fx * (tex(i + 1, j + 1) - tex(i, j + 1));
    return a + fy * (b - a);
}

void HeightMap::gradient(double u, double v, double* du, double* dv) const {
    const double x = u * size - 0.5, y = v * size - 0.5;
    const double fi = std::floor(x), fj = std::floor(y);
    const int i = int(std::fmod(fi, double(size))), j = int(std::fmod(fj, double(size)));
    const double fx = x - fi, fy = y - fj;
    *du = size * ((1 - fy) * (tex(i + 1, j) - tex(i, j)) + fy * (tex(i + 1, j + 1) - tex(i, j + 1)));
    *dv = size * ((1 - fx) * (tex(i, j + 1) - tex(i, j)) + fx * (tex(i + 1, j + 1) - tex(i + 1, j)));
}

std::vector<std::string> heightmap_names() { return {"waves", "bumps", "bricks", "rocks"}; }

HeightMap make_heightmap(const std::string& name, int size) {
    if (size < 16 || size > 2048) throw std::invalid_argument("height map size must be in 16..2048");
    double (*fn)(double, double) = nullptr;
    if (name == "waves") fn = h_waves;
    else if (name == "bumps") fn = h_bumps;
    else if (name == "bricks") fn = h_bricks;
    else if (name == "rocks") fn = h_rocks;
    else throw std::invalid_argument("unknown height map '" + name + "' (one of waves, bumps, bricks, rocks)");
    HeightMap m;
    m.name = name;
    m.size = size;
    m.texel.resize(size_t(size) * size_t(size));
    for (int j = 0; j < size; ++j) {
        for (int i = 0; i < size; ++i) {
            m.texel[size_t(j) * size_t(size) + size_t(i)] = float(fn((i + 0.5) / size, (j + 0.5) / size));
        }
    }
    double g = 0;
    for (int j = 0; j < size; ++j) {
        for (int i = 0; i < size; ++i) {
            const double a = std::max(std::fabs(m.tex(i + 1, j) - m.tex(i, j)), std::fabs(m.tex(i + 1, j + 1) - m.tex(i, j + 1)));
            const double b = std::max(std::fabs(m.tex(i, j + 1) - m.tex(i, j)), std::fabs(m.tex(i + 1, j + 1) - m.tex(i + 1, j)));
            g = std::max(g, std::hypot(a, b));
        }
    }
    m.lipschitz = g * size;
    return m;
}

}  // namespace methods
}  // namespace spec
