// parallax_fixed.h - companion paper C in fixed point: the bit-exact models of rtl/parallax_step.v (one step of
// the paper's iteration) and rtl/parallax_iter.v (the whole iteration around it, several fragments in flight).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "heightmap.h"

namespace spec {
namespace methods {

// Formats (parameters of the RTL): texture coordinates UV_W-bit two's complement with F fraction bits
// (1.0 = one texture repeat, wrapping); heights h, hV, d H_W-bit two's complement with the same F fraction
// bits, saturating; view components V_W-bit two's complement with V_F fraction bits; iteration counts and
// the cap ITER_W bits. Products are truncated (arithmetic shift right by V_F): three multiplications, four
// additions (and two saturations).
struct StepFormat {
    int uv_w = 24, f = 16, h_w = 16, v_w = 16, v_f = 14, iter_w = 6;
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

// One fragment for rtl/parallax_iter.v: the start point and the ray's height there (hv0 = 0 and P0: the
// paper; hv0 = s and P0 + (s / Vh) V(u, v): from the slab's top), the view, the stop rule (|d| <= threshold,
// H_W bits unsigned; at most max_iter steps, ITER_W bits, 0 = none) and a tag carried along.
struct IterJob {
    int64_t u = 0, v = 0, hv0 = 0;
    int64_t vu = 0, vv = 0, vh = 0;
    uint64_t threshold = 0;
    uint32_t max_iter = 0;
    uint32_t tag = 0;
};
struct FixedHit {
    int64_t u = 0, v = 0;   // converged: the point whose fetch met the threshold; else the point after the last step
    int iterations = 0;     // height fetches (= steps)
    bool converged = false;
};
// The height fetch: s h at (u, v) in the H format (whatever filtering the memory does).
using HeightFetch = std::function<int64_t(int64_t u, int64_t v)>;
// The iteration of one job: what rtl/parallax_iter.v returns for it, bit for bit. trace: the step inputs.
FixedHit iterate_fixed(const StepFormat& fmt, const IterJob& job, const HeightFetch& fetch,
                       std::vector<StepIn>* trace = nullptr);

// A height map as the fixed-point loop reads it: nearest texel, 8-bit heights (h8 -> s h8 / 255, F fraction
// bits).
struct FixedParallax {
    StepFormat fmt;
    std::vector<int64_t> height;  // per texel: s * texel in F fraction bits
    int size = 0;
    int64_t lookup(int64_t u, int64_t v) const;  // nearest texel to (u, v)
};
FixedParallax make_fixed(const HeightMap& m, double s, const StepFormat& fmt = StepFormat());
// Fixed-point operands from doubles (round to nearest).
int64_t to_fixed(double x, int frac_bits);
// The host's part for a fragment at (u0, v0) seen along V: the paper's start (hv0 = 0) or the slab's top
// (hv0 = s, P0 + round(s Vu / Vh), one division).
IterJob job_for(const StepFormat& fmt, double s, double u0, double v0, double vu, double vv, double vh, bool top,
                uint64_t threshold, uint32_t max_iter, uint32_t tag = 0);
// The paper's loop (start at P0, hV_0 = 0) with the map's lookup.
FixedHit iterative_fixed(const FixedParallax& p, int64_t u0, int64_t v0, int64_t vu, int64_t vv, int64_t vh,
                         int64_t threshold, int max_iter, std::vector<StepIn>* trace = nullptr);

}  // namespace methods
}  // namespace spec
