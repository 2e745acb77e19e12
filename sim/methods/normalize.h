// normalize.h - companion paper B (seeds/003): adaptive normalization of interpolated normals, and the ways of
// getting unit vectors along a span it has to beat.
//
// A Phong path (vectors interpolated along the span and normalized per pixel, the classic alternative to
// the patent's angle interpolation). Per span of l intervals (pixels 0..l), for N and for H alike:
//   full        every pixel: N = normalize(N1 + (N2 - N1) i / l)  (1 sqrt, 1 div, 6 mul, 2 add after the lerp)
//   rsqrt       the same with the GPU's inversesqrt: N * inversesqrt(N.N)  (1 rsqrt, 6 mul, 2 add)
//   newton      the span's ends normalized, the lerp in between corrected by one Newton step for 1 / |N|
//               (Lyon's truncated Taylor series, the paper's reference [1]): N (1.5 - 0.5 N.N)  (7 mul, 3 add)
//   recurrence  the span's ends normalized, then slerp by the recurrence N(i+1) = 2 cos(phi) N(i) - N(i-1),
//               phi = psi / l (the paper's reference [6]): 3 mul, 3 add a pixel; per span acos, cos, sin and
//               one more normalization for the second vector
//   halving     the paper's recursive halving (after its [5]) down to single pixels: the span is extended to
//               2^K intervals, and the midpoint of a segment with unit end vectors Na, Nb is
//               (Na + Nb) / z, z = |Na + Nb| = sqrt(2 (1 + cos psi)), with z_(j+1) = sqrt(2 + z_j) from
//               one level to the next (one sqrt and one div per level, shared by every segment of that level)
//   adaptive    the paper's method: halving stops at the first level whose segments meet the error bound,
//               and inside a segment the vectors are lerped without normalization (N_i = Na + i dN)
// The same scheme is applied to N and to H (the renderer's viewer is local, H varies along the span).
//
// Operation counts (NormOps): every vector a method makes is counted as built, per span (setup, the ends) and
// per pixel. The span's end vectors are taken as a hardware rasterizer gives them, interpolated along the
// edges and not of unit length: methods that need unit ends (all but full and rsqrt) normalize them per span.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "image.h"
#include "raster.h"
#include "scene.h"

namespace spec {
namespace methods {

using NVec = glm::dvec3;

// The paper's quantities. psi: angle between the span's end normals.
// eq. (2): d_(1/2^i) = 1 - sqrt((1 + cos(psi / 2^(i-1))) / 2) = 1 - cos(psi / 2^i), i >= 1: the length
// deficit of the unnormalized average of two unit vectors psi / 2^(i-1) apart
double deviation(double psi, int i);
// z_(1/2) = sqrt(2 (1 + cos psi)), and z_(1/2^(i+1)) = sqrt(2 + z_(1/2^i)) (eq. 1), i >= 1
double z_level(double psi, int i);
// The end-normal angle at which d_(1/2) equals d: 2 acos(1 - d)
double angle_for_deviation(double d);
// The paper's specular stopping rule: normalization may stop once cos(chi) >= 2 (1 - delta_s)^(2/n) - 1
double specular_cos_bound(double delta_s, unsigned n);

enum class NormMode { full, rsqrt, newton, recurrence, halving, adaptive };
const char* norm_mode_name(NormMode m);
std::vector<NormMode> norm_modes();  // in table order

struct NormBounds {
    double diffuse = 0.01;   // largest relative error of the diffuse term (= d of the unnormalized normal)
    double specular = 0.01;  // largest relative error of the specular term: 1 - (|N| |H|)^n
    // How a span of l intervals is extended to 2^k: false, the paper's normalize(N1 + (N2 - N1) 2^k / l)
    // (linear extrapolation: pixel l is then not where N2 is on the great circle); true, the vector at
    // angle psi 2^k / l on the great circle (one sin/cos pair per span; the halving then gives slerp(N1, N2,
    // i / l) at every pixel it reaches).
    bool slerp_extension = false;
};

// Arithmetic by class. trig: acos, sin, cos (and the sin/cos of the slerp extension).
struct OpClass {
    uint64_t add = 0, mul = 0, div = 0, sqrt = 0, rsqrt = 0, trig = 0;
    OpClass& operator+=(const OpClass& o);
    // add, mul 1; div, sqrt, rsqrt 4 (a GPU's special-function units run at a quarter of the arithmetic
    // rate); acos, sin, cos 8 (two special-function steps each)
    double weighted() const;
};

// Operation counts (added up over a frame).
struct NormOps {
    uint64_t vectors = 0;      // interpolated vectors made (pixels x 2: N and H)
    uint64_t spans = 0;        // spans x 2 (N and H)
    uint64_t normalized = 0;   // classic normalizations (sqrt + div): full mode, the ends, the extended end
    uint64_t halved = 0;       // halving midpoints (Na + Nb) * (1 / z): 3 add + 3 mul
    uint64_t lerped = 0;       // vectors lerped without normalization (3 add)
    uint64_t sqrts = 0;        // square roots: per normalization, and one per halving level
    OpClass span, pixel;       // per-span setup (ends included) and per-pixel work
    NormOps& operator+=(const NormOps& o);
};

// The l + 1 vectors of one span from unit a (pixel 0) to unit b (pixel l), interpolated both for N
// (n1 -> n2) and H (h1 -> h2) by the mode. For adaptive, the halving level is the first whose segments meet
// both bounds (the deficit of N alone for the diffuse bound, of N and H together for the specular bound
// with exponent n); both vectors share the segment structure.
struct SpanVectors {
    std::vector<NVec> n, h;
    int levels = 0;      // halving levels done (adaptive / halving)
    int stop_seg = 1;    // segment length at which lerping took over (pixels; 1 = every pixel halved)
};
void interpolate_span(const NVec& n1, const NVec& n2, const NVec& h1, const NVec& h2, uint32_t l, NormMode mode,
                      const NormBounds& b, unsigned n, SpanVectors* out, NormOps* ops);

// The Phong path over a rasterized frame: ambient + Lambert + Blinn-Phong with the interpolated N and H,
// as shade.h but with these vectors (no core). Returns the 8-bit image; double-precision terms per pixel
// are kept for the error statistics when terms != nullptr.
struct PhongTerms {
    std::vector<double> diffuse, specular;  // per pixel, the scalar factors max(0, N.L), Is ks max(0, N.H)^n
    std::vector<double> n_len;              // |N| per pixel
};
struct PhongRun {
    render::Image img;
    NormOps ops;
    double seconds = 0;  // the shading loop alone, CPU time of the thread (varies from run to run)
};
PhongRun shade_phong(const render::Scene& sc, const render::Frame& f, NormMode mode, const NormBounds& b,
                     PhongTerms* terms = nullptr);

// The rest of a Phong pixel beside the vectors (for the operation-count model of docs/methods.md): N.L and
// N.H, pow(N.H, n) as exp2(n log2 x), and the colour ambient + diffuse + specular in three channels.
OpClass phong_pixel_ops();

}  // namespace methods
}  // namespace spec
