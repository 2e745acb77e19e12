// parallax.h - companion paper C (seeds/002): iterative parallax mapping against Kaneko's parallax mapping,
// Welsh's offset limiting and the exact intersection of the view ray with the height field.
//
// Tangent space, texture units: the polygon is the plane z = 0 and the relief is z = s h(u, v), h in [0, 1]
// (a height map, bilinearly interpolated, repeating), s the relief depth. V = (Vu, Vv, Vh) is the unit vector
// from the fragment P0 = (u0, v0) toward the viewer (Vh > 0). The view ray through P0 is, going back toward
// the viewer, P(t) = P0 + t (Vu, Vv) at height t Vh; the visible relief point is the intersection with the
// largest t (nearest the viewer): the largest root of f(t) = t Vh - s h(P(t)) in [0, s / Vh].
//   Kaneko (2001):   t = s h(P0) / Vh              (u', v') = P0 + s h(P0) (Vu, Vv) / Vh
//   Welsh (2004):    t = s h(P0)                   offset limiting, no division
//   the paper (4)-(5): P_(i+1) = P_i + d_i (Vu, Vv), d_i = s h(P_i) - hV_i, hV_i = hV_(i-1) + d_(i-1) Vh,
//                    hV_0 = 0: t_(i+1) = t_i + f-like step (s h(P(t_i)) - t_i Vh); the first step is Welsh's
//   exact:           the largest root, cell by cell (bilinear h is quadratic along the ray in each cell)
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image.h"

namespace spec {
namespace methods {

struct HeightMap {
    std::string name;
    int size = 0;                 // size x size texels, repeating
    std::vector<float> texel;     // [0, 1], row-major (v rows, u columns)
    double lipschitz = 0;         // bound on |grad h| in texture units (h per unit of u, v)

    // Bilinear between texel centres ((i + 0.5) / size), repeating.
    double at(double u, double v) const;
    // The gradient of the bilinear interpolant (texture units), for normals.
    void gradient(double u, double v, double* du, double* dv) const;
    float tex(int i, int j) const;  // texel (column i, row j), wrapped
};

// "waves" (smooth sines), "bumps" (round domes), "bricks" (bevelled bricks, steep), "rocks" (cobblestones
// from a seeded Voronoi pattern plus value noise: the real-looking one). size: 16..2048. Throws
// std::invalid_argument for another name.
HeightMap make_heightmap(const std::string& name, int size);
std::vector<std::string> heightmap_names();

struct View {
    double u = 0, v = 0, h = 1;  // unit, h > 0
};
View view_from_angles(double elevation_deg, double azimuth_deg);

struct Hit {
    double u = 0, v = 0;  // texture coordinates found
    double t = 0;         // ray parameter
    int iterations = 0;   // the paper's method: steps taken
    bool converged = true;
};

Hit kaneko(const HeightMap& m, double s, double u0, double v0, const View& V);
Hit welsh(const HeightMap& m, double s, double u0, double v0, const View& V);
// The paper's iteration: stops when |d_i| <= threshold (texture units of height) or after max_iter steps
// (converged = false). max_iter = 1 is Welsh's offset limiting.
Hit iterative(const HeightMap& m, double s, double u0, double v0, const View& V, double threshold, int max_iter);
// The exact nearest intersection (largest root of f), by walking the texel cells from the top of the relief
// slab down and solving the quadratic in each.
Hit exact(const HeightMap& m, double s, double u0, double v0, const View& V);
// Linear search from the top of the slab in `steps` equal steps to the first point below the relief, then
// `bisections` halvings of that interval (relief mapping / parallax occlusion mapping): steps + bisections
// height fetches, the standard way to spend a fixed budget. Finds the nearest intersection unless a thin
// feature lies between two steps.
Hit linear_search(const HeightMap& m, double s, double u0, double v0, const View& V, int steps, int bisections);
// Brute force for the tests: f sampled at `samples` points from t_max down, the first sign change refined by
// bisection.
Hit dense_search(const HeightMap& m, double s, double u0, double v0, const View& V, int samples);
// The smallest |t - t_root| over every root of f in [0, s / Vh] (sampled densely): how far t is from any
// intersection (tells a farther intersection from a wrong answer).
double distance_to_any_root(const HeightMap& m, double s, double u0, double v0, const View& V, double t,
                            int samples);

// ---- one iteration step in fixed point: the bit-exact model of rtl/parallax_step.v ----
// Formats (parameters of the RTL): texture coordinates UV_W-bit two's complement with F fraction bits
// (1.0 = one texture repeat, wrapping); heights h, hV, d H_W-bit two's complement with the same F fraction
// bits, saturating; view components V_W-bit two's complement with V_F fraction bits. Products are truncated
// (arithmetic shift right by V_F): three multiplications, four additions (and two saturations).
struct StepFormat {
    int uv_w = 24, f = 16, h_w = 16, v_w = 16, v_f = 14;
};
struct StepIn {
    int64_t u = 0, v = 0;       // P_i
    int64_t h = 0;              // s h(P_i), the height sample
    int64_t hv_prev = 0;        // hV_(i-1)
    int64_t d_prev = 0;         // d_(i-1)
    int64_t vu = 0, vv = 0, vh = 0;
};
struct StepOut {
    int64_t u = 0, v = 0;       // P_(i+1)
    int64_t hv = 0;             // hV_i = hV_(i-1) + d_(i-1) Vh
    int64_t d = 0;              // d_i = h_i - hV_i
};
StepOut step_fixed(const StepFormat& fmt, const StepIn& in);

// The whole iteration in fixed point with a nearest-texel height lookup from an 8-bit copy of the map
// (height code h8 -> s h8 / 255 in F fraction bits): what a hardware loop around the step unit computes.
struct FixedParallax {
    StepFormat fmt;
    std::vector<int64_t> height;  // per texel: s * texel in F fraction bits
    int size = 0;
    int64_t lookup(int64_t u, int64_t v) const;  // nearest texel to (u, v)
};
FixedParallax make_fixed(const HeightMap& m, double s, const StepFormat& fmt = StepFormat());
struct FixedHit {
    int64_t u = 0, v = 0;
    int iterations = 0;
    bool converged = false;
};
FixedHit iterative_fixed(const FixedParallax& p, int64_t u0, int64_t v0, int64_t vu, int64_t vv, int64_t vh,
                         int64_t threshold, int max_iter, std::vector<StepIn>* trace = nullptr);

// ---- the relief-mapped quad, one image per method ----
enum class ParallaxMethod { none, kaneko, welsh, iterative, exact };
const char* parallax_method_name(ParallaxMethod m);
struct QuadView {
    int width = 256, height = 192;
    double elevation_deg = 30;  // camera elevation over the quad
    double s = 0.06;            // relief depth (texture units)
    double repeats = 2;         // texture repeats across the quad
    double threshold = 0, max_iter = 8;  // the paper's iteration (threshold 0: s / 512)
};
// Renders the quad with the method's texture coordinates: albedo and normal (from the height map's gradient)
// at (u', v'), Blinn-Phong with one light. uv_err (optional): per pixel |(u', v') - exact| in texels.
render::Image render_quad(const HeightMap& m, const QuadView& q, ParallaxMethod method,
                          std::vector<double>* uv_err = nullptr);

}  // namespace methods
}  // namespace spec
