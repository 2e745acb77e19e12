#include "parallax.h"

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

double fbm(double u, double v, int f0, int octaves, uint32_t seed) {
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
    const double grain = 0.06 * fbm(u, v, 16, 3, 11);
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
    const double h = stone * edge * dome + 0.12 * fbm(u, v, 8, 4, 31) - 0.04;
    return std::min(1.0, std::max(0.0, h));
}

int64_t shr_floor(int64_t x, int s) {
    // arithmetic shift right (floor division by 2^s), independent of the implementation's >> on negatives
    return x >= 0 ? (x >> s) : -(((-x) + (int64_t(1) << s) - 1) >> s);
}

int64_t wrap_bits(int64_t x, int w) {
    const uint64_t m = (uint64_t(1) << w) - 1;
    const uint64_t r = uint64_t(x) & m;
    return (r >> (w - 1)) ? int64_t(r) - (int64_t(1) << w) : int64_t(r);
}

int64_t sat_bits(int64_t x, int w) {
    const int64_t hi = (int64_t(1) << (w - 1)) - 1, lo = -(int64_t(1) << (w - 1));
    return std::min(hi, std::max(lo, x));
}
}  // namespace

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

View view_from_angles(double elevation_deg, double azimuth_deg) {
    const double e = elevation_deg * kPi / 180, a = azimuth_deg * kPi / 180;
    return View{std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
}

Hit kaneko(const HeightMap& m, double s, double u0, double v0, const View& V) {
    Hit h;
    h.t = s * m.at(u0, v0) / V.h;
    h.u = u0 + h.t * V.u;
    h.v = v0 + h.t * V.v;
    h.iterations = 1;
    return h;
}

Hit welsh(const HeightMap& m, double s, double u0, double v0, const View& V) {
    Hit h;
    h.t = s * m.at(u0, v0);
    h.u = u0 + h.t * V.u;
    h.v = v0 + h.t * V.v;
    h.iterations = 1;
    return h;
}

Hit iterative(const HeightMap& m, double s, double u0, double v0, const View& V, double threshold, int max_iter) {
    Hit r;
    double u = u0, v = v0, t = 0, hv = 0, d_prev = 0;
    r.converged = false;
    for (int i = 0; i < max_iter; ++i) {
        hv += d_prev * V.h;                // (5): hV_i = hV_(i-1) + d_(i-1) Vh
        const double d = s * m.at(u, v) - hv;  // (5): d_i = h_i - hV_i
        ++r.iterations;
        if (std::fabs(d) <= threshold) {
            r.converged = true;
            break;
        }
        u += d * V.u;                      // (4): P_(i+1) = P_i + d_i V(u, v)
        v += d * V.v;
        t += d;
        d_prev = d;
    }
    r.u = u;
    r.v = v;
    r.t = t;
    return r;
}

namespace {
// f(t) = t Vh - s h(P(t))
double f_at(const HeightMap& m, double s, double u0, double v0, const View& V, double t) {
    return t * V.h - s * m.at(u0 + t * V.u, v0 + t * V.v);
}

// Largest root of a + b x + c x^2 in [0, 1] (small tolerance), or -1.
double largest_root01(double a, double b, double c) {
    const double tol = 1e-12;
    double best = -1;
    auto take = [&](double x) {
        if (x >= -tol && x <= 1 + tol) best = std::max(best, std::min(1.0, std::max(0.0, x)));
    };
    const double scale = std::fabs(a) + std::fabs(b) + std::fabs(c);
    if (scale == 0) return 1.0;  // f = 0 on the whole interval: touching from the top
    if (std::fabs(c) <= 1e-13 * scale) {
        if (b != 0) take(-a / b);
        return best;
    }
    const double disc = b * b - 4 * a * c;
    if (disc < 0) {
        // a double root lost to rounding: the vertex, when it touches zero
        const double x = -b / (2 * c);
        if (std::fabs(a + b * x + c * x * x) <= 1e-14 * scale) take(x);
        return best;
    }
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    if (q != 0) {
        take(q / c);
        take(a / q);
    } else {
        take(0.0);
    }
    return best;
}
}  // namespace

Hit exact(const HeightMap& m, double s, double u0, double v0, const View& V) {
    Hit h;
    const double tmax = s / V.h;
    // breakpoints: where the ray's (x, y) in texel-centre coordinates crosses an integer
    const double x0 = u0 * m.size - 0.5, y0 = v0 * m.size - 0.5;
    const double ax = V.u * m.size, ay = V.v * m.size;
    std::vector<double> bp{0.0, tmax};
    auto crossings = [&](double p0, double dp) {
        if (std::fabs(dp) < 1e-300) return;
        const double p1 = p0 + dp * tmax;
        const double lo = std::min(p0, p1), hi = std::max(p0, p1);
        for (double k = std::ceil(lo); k <= hi; k += 1.0) {
            const double t = (k - p0) / dp;
            if (t > 0 && t < tmax) bp.push_back(t);
        }
    };
    crossings(x0, ax);
    crossings(y0, ay);
    std::sort(bp.begin(), bp.end());
    double f_hi = f_at(m, s, u0, v0, V, tmax);
    if (f_hi <= 0) {
        h.t = tmax;  // the relief reaches the slab's top here
    } else {
        h.t = 0;
        for (size_t k = bp.size() - 1; k > 0; --k) {
            const double tl = bp[k - 1], th = bp[k];
            if (th - tl <= 0) continue;
            const double f0 = f_at(m, s, u0, v0, V, tl), fm = f_at(m, s, u0, v0, V, 0.5 * (tl + th));
            const double f1 = f_hi;
            const double c = 2 * (f0 - 2 * fm + f1), b = -3 * f0 + 4 * fm - f1;
            const double x = largest_root01(f0, b, c);
            if (x >= 0) {
                h.t = tl + x * (th - tl);
                break;
            }
            f_hi = f0;
        }
    }
    h.u = u0 + h.t * V.u;
    h.v = v0 + h.t * V.v;
    return h;
}

Hit linear_search(const HeightMap& m, double s, double u0, double v0, const View& V, int steps, int bisections) {
    Hit h;
    const double tmax = s / V.h;
    double hi = tmax, lo = 0;  // f(hi) >= 0 (the slab's top), f(0) <= 0
    for (int k = 1; k <= steps; ++k) {
        const double t = tmax * (1.0 - double(k) / steps);
        ++h.iterations;
        if (f_at(m, s, u0, v0, V, t) <= 0) {
            lo = t;
            break;
        }
        hi = t;
    }
    for (int b = 0; b < bisections; ++b) {
        const double mid = 0.5 * (lo + hi);
        ++h.iterations;
        if (f_at(m, s, u0, v0, V, mid) <= 0) lo = mid;
        else hi = mid;
    }
    h.t = 0.5 * (lo + hi);
    h.u = u0 + h.t * V.u;
    h.v = v0 + h.t * V.v;
    return h;
}

Hit dense_search(const HeightMap& m, double s, double u0, double v0, const View& V, int samples) {
    Hit h;
    const double tmax = s / V.h;
    double t_prev = tmax;
    h.t = 0;
    if (f_at(m, s, u0, v0, V, tmax) <= 0) {
        h.t = tmax;
    } else {
        for (int k = 1; k <= samples; ++k) {
            const double t = tmax * (1.0 - double(k) / samples);
            if (f_at(m, s, u0, v0, V, t) <= 0) {
                double lo = t, hi = t_prev;  // f(lo) <= 0 < f(hi)
                for (int it = 0; it < 80; ++it) {
                    const double mid = 0.5 * (lo + hi);
                    if (f_at(m, s, u0, v0, V, mid) <= 0) lo = mid;
                    else hi = mid;
                }
                h.t = 0.5 * (lo + hi);
                break;
            }
            t_prev = t;
        }
    }
    h.u = u0 + h.t * V.u;
    h.v = v0 + h.t * V.v;
    return h;
}

StepOut step_fixed(const StepFormat& fmt, const StepIn& in) {
    StepOut o;
    o.hv = sat_bits(in.hv_prev + shr_floor(in.d_prev * in.vh, fmt.v_f), fmt.h_w);  // multiplication 1, addition 1
    o.d = sat_bits(in.h - o.hv, fmt.h_w);                                          // addition 2
    o.u = wrap_bits(in.u + shr_floor(o.d * in.vu, fmt.v_f), fmt.uv_w);              // multiplication 2, addition 3
    o.v = wrap_bits(in.v + shr_floor(o.d * in.vv, fmt.v_f), fmt.uv_w);              // multiplication 3, addition 4
    return o;
}

int64_t FixedParallax::lookup(int64_t u, int64_t v) const {
    int lg = 0;
    while ((1 << lg) < size) ++lg;
    const int sh = fmt.f - lg;
    const int64_t i = (u >> sh) & (size - 1), j = (v >> sh) & (size - 1);  // two's complement: wraps
    return height[size_t(j) * size_t(size) + size_t(i)];
}

FixedParallax make_fixed(const HeightMap& m, double s, const StepFormat& fmt) {
    if (m.size & (m.size - 1)) throw std::invalid_argument("the fixed-point lookup needs a power-of-two map");
    FixedParallax p;
    p.fmt = fmt;
    p.size = m.size;
    p.height.resize(m.texel.size());
    for (size_t k = 0; k < m.texel.size(); ++k) {
        const double h8 = std::round(double(m.texel[k]) * 255.0);
        p.height[k] = int64_t(std::llround(std::ldexp(s * h8 / 255.0, fmt.f)));
    }
    return p;
}

FixedHit iterative_fixed(const FixedParallax& p, int64_t u0, int64_t v0, int64_t vu, int64_t vv, int64_t vh,
                         int64_t threshold, int max_iter, std::vector<StepIn>* trace) {
    FixedHit r;
    StepIn in;
    in.u = u0;
    in.v = v0;
    in.vu = vu;
    in.vv = vv;
    in.vh = vh;
    for (int i = 0; i < max_iter; ++i) {
        in.h = p.lookup(in.u, in.v);
        if (trace) trace->push_back(in);
        const StepOut o = step_fixed(p.fmt, in);
        ++r.iterations;
        if (std::llabs(o.d) <= threshold) {
            r.converged = true;
            break;
        }
        in.u = o.u;
        in.v = o.v;
        in.hv_prev = o.hv;
        in.d_prev = o.d;
    }
    r.u = in.u;
    r.v = in.v;
    return r;
}

const char* parallax_method_name(ParallaxMethod m) {
    switch (m) {
        case ParallaxMethod::none: return "none";
        case ParallaxMethod::kaneko: return "kaneko";
        case ParallaxMethod::welsh: return "welsh";
        case ParallaxMethod::iterative: return "iterative";
        case ParallaxMethod::exact: return "exact";
    }
    return "?";
}

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

render::Image render_quad(const HeightMap& m, const QuadView& q, ParallaxMethod method, std::vector<double>* uv_err) {
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
            Hit hit;
            switch (method) {
                case ParallaxMethod::none: hit.u = u0, hit.v = v0; break;
                case ParallaxMethod::kaneko: hit = kaneko(m, q.s, u0, v0, V); break;
                case ParallaxMethod::welsh: hit = welsh(m, q.s, u0, v0, V); break;
                case ParallaxMethod::iterative: hit = iterative(m, q.s, u0, v0, V, threshold, int(q.max_iter)); break;
                case ParallaxMethod::exact: hit = exact(m, q.s, u0, v0, V); break;
            }
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
