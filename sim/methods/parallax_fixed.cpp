// parallax_fixed.cpp - the fixed-point models of rtl/parallax_step.v and rtl/parallax_iter.v.
#include "parallax_fixed.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace spec {
namespace methods {

namespace {
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

StepOut step_fixed(const StepFormat& fmt, const StepIn& in) {
    StepOut o;
    o.hv = sat_bits(in.hv_prev + shr_floor(in.d_prev * in.vh, fmt.v_f), fmt.h_w);  // multiplication 1, addition 1
    o.d = sat_bits(in.h - o.hv, fmt.h_w);                                          // addition 2
    o.u = wrap_bits(in.u + shr_floor(o.d * in.vu, fmt.v_f), fmt.uv_w);              // multiplication 2, addition 3
    o.v = wrap_bits(in.v + shr_floor(o.d * in.vv, fmt.v_f), fmt.uv_w);              // multiplication 3, addition 4
    return o;
}

FixedHit iterate_fixed(const StepFormat& fmt, const IterJob& job, const HeightFetch& fetch, std::vector<StepIn>* trace) {
    FixedHit r;
    StepIn in;
    in.u = job.u;
    in.v = job.v;
    in.hv_prev = job.hv0;  // hV_0 = hV_(-1) + 0 * Vh
    in.vu = job.vu;
    in.vv = job.vv;
    in.vh = job.vh;
    for (uint32_t i = 0; i < job.max_iter; ++i) {
        in.h = fetch(in.u, in.v);
        if (trace) trace->push_back(in);
        const StepOut o = step_fixed(fmt, in);
        ++r.iterations;
        if (uint64_t(std::llabs(o.d)) <= job.threshold) {
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

int64_t to_fixed(double x, int frac_bits) { return std::llround(std::ldexp(x, frac_bits)); }

IterJob job_for(const StepFormat& fmt, double s, double u0, double v0, double vu, double vv, double vh, bool top,
                uint64_t threshold, uint32_t max_iter, uint32_t tag) {
    IterJob j;
    j.vu = to_fixed(vu, fmt.v_f);
    j.vv = to_fixed(vv, fmt.v_f);
    j.vh = to_fixed(vh, fmt.v_f);
    j.u = to_fixed(u0, fmt.f);
    j.v = to_fixed(v0, fmt.f);
    if (top) {
        // the host's division: P0 + s V(u, v) / Vh, from the same quantized operands the unit sees
        const int64_t sf = to_fixed(s, fmt.f);
        const double k = double(sf) / double(j.vh);
        j.u += std::llround(k * double(j.vu));
        j.v += std::llround(k * double(j.vv));
        j.hv0 = sf;
    }
    const int64_t uv_mask = (int64_t(1) << fmt.uv_w) - 1;
    auto wrap = [&](int64_t x) {
        const int64_t r = x & uv_mask;
        return (r >> (fmt.uv_w - 1)) ? r - (int64_t(1) << fmt.uv_w) : r;
    };
    j.u = wrap(j.u);
    j.v = wrap(j.v);
    j.threshold = threshold;
    j.max_iter = max_iter;
    j.tag = tag;
    return j;
}

FixedHit iterative_fixed(const FixedParallax& p, int64_t u0, int64_t v0, int64_t vu, int64_t vv, int64_t vh,
                         int64_t threshold, int max_iter, std::vector<StepIn>* trace) {
    IterJob j;
    j.u = u0;
    j.v = v0;
    j.vu = vu;
    j.vv = vv;
    j.vh = vh;
    j.threshold = uint64_t(std::max<int64_t>(0, threshold));
    j.max_iter = uint32_t(std::max(0, max_iter));
    return iterate_fixed(p.fmt, j, [&](int64_t u, int64_t v) { return p.lookup(u, v); }, trace);
}

}  // namespace methods
}  // namespace spec
