// Companion paper C: parallax mapping. The exact intersection against brute force, the methods' formulas,
// the iteration's convergence condition, and rtl/parallax_step.v bit for bit against its model.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "Vparallax_step.h"
#include "parallax.h"
#include "harness.h"
#include "parallax_fixed.h"

using namespace spec::methods;

namespace {
double f_of(const HeightMap& m, double s, double u0, double v0, const View& V, double t) {
    return t * V.h - s * m.at(u0 + t * V.u, v0 + t * V.v);
}

// A map with h linear along u in the middle of the texture (slope `k` per texture unit, 0.5 at u = 0.5).
HeightMap ramp(int size, double k) {
    HeightMap m;
    m.name = "ramp";
    m.size = size;
    m.texel.resize(size_t(size) * size_t(size));
    for (int j = 0; j < size; ++j) {
        for (int i = 0; i < size; ++i) m.texel[size_t(j) * size + i] = float(0.5 + k * ((i + 0.5) / size - 0.5));
    }
    m.lipschitz = k;
    return m;
}
}  // namespace

// The exact walk finds the largest root of f(t) = t Vh - s h(P(t)): f there is 0, no sample of f above it is
// negative, and a dense search from the top (which may only miss thin crossings, never invent a higher one)
// agrees in nearly every case.
TEST(Parallax, ExactIsTheNearestIntersectionBruteForce) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (const auto& name : heightmap_names()) {
        const HeightMap m = make_heightmap(name, 64);
        const double s = 0.06;
        int agree = 0, total = 0;
        for (int k = 0; k < 300; ++k) {
            const View V = view_from_angles(8 + 80 * u01(rng), 360 * u01(rng));
            const double u0 = u01(rng), v0 = u01(rng);
            const Hit e = exact(m, s, u0, v0, V);
            const double tmax = s / V.h;
            ASSERT_GE(e.t, 0.0);
            ASSERT_LE(e.t, tmax + 1e-12);
            EXPECT_NEAR(f_of(m, s, u0, v0, V, e.t), 0.0, 1e-9) << name;
            double worst = 0;
            for (int i = 1; i <= 4000; ++i) {
                const double t = e.t + (tmax - e.t) * i / 4000.0;
                worst = std::min(worst, f_of(m, s, u0, v0, V, t));
            }
            EXPECT_GE(worst, -1e-9) << name << ": a point above the found root is below the relief";
            const Hit d = dense_search(m, s, u0, v0, V, 4000);
            EXPECT_GE(e.t, d.t - 1e-9) << name;
            ++total;
            agree += std::fabs(e.t - d.t) < 1e-7;
        }
        EXPECT_GE(agree, total * 98 / 100) << name;
    }
}

// The linear search with many steps finds the exact (nearest) intersection; it counts its fetches.
TEST(Parallax, LinearSearchConvergesToTheExactIntersection) {
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (const auto& name : heightmap_names()) {
        const HeightMap m = make_heightmap(name, 64);
        int agree = 0;
        for (int k = 0; k < 200; ++k) {
            const View V = view_from_angles(10 + 75 * u01(rng), 360 * u01(rng));
            const double u0 = u01(rng), v0 = u01(rng);
            const Hit e = exact(m, 0.06, u0, v0, V);
            const Hit l = search(m, 0.06, u0, v0, V, 3000, 30, false, SearchEnd::midpoint);
            EXPECT_LE(l.fetches, 3030);
            EXPECT_LE(l.t, e.t + 1e-9) << name;  // never above the nearest intersection
            agree += std::fabs(l.t - e.t) < 1e-8;
        }
        EXPECT_GE(agree, 196) << name;
    }
}

TEST(Parallax, KanekoWelshAndTheFirstIterationStep) {
    const HeightMap m = make_heightmap("rocks", 64);
    const View V = view_from_angles(35, 120);
    const double s = 0.05, u0 = 0.3, v0 = 0.7, h0 = m.at(u0, v0);
    const Hit k = kaneko(m, s, u0, v0, V), w = welsh(m, s, u0, v0, V);
    EXPECT_DOUBLE_EQ(k.u, u0 + s * h0 * V.u / V.h);
    EXPECT_DOUBLE_EQ(k.v, v0 + s * h0 * V.v / V.h);
    EXPECT_DOUBLE_EQ(w.u, u0 + s * h0 * V.u);
    EXPECT_DOUBLE_EQ(w.v, v0 + s * h0 * V.v);
    const Hit i1 = iterative(m, s, u0, v0, V, 0.0, 1);  // one step of (4)-(5) is offset limiting
    EXPECT_DOUBLE_EQ(i1.u, w.u);
    EXPECT_DOUBLE_EQ(i1.v, w.v);
    // two steps by hand: hV_1 = d_0 Vh, d_1 = s h(P1) - hV_1
    const double d1 = s * m.at(w.u, w.v) - s * h0 * V.h;
    const Hit i2 = iterative(m, s, u0, v0, V, 0.0, 2);
    EXPECT_NEAR(i2.u, w.u + d1 * V.u, 1e-15);
    EXPECT_NEAR(i2.v, w.v + d1 * V.v, 1e-15);
}

// t_(i+1) = t_i - f(t_i): on a plane of slope f' the error is multiplied by 1 - f' each step, so the iteration
// converges for 0 < f' < 2 and not beyond (docs/methods.md).
TEST(Parallax, ConvergesExactlyWhenTheSlopeIsBetweenZeroAndTwo) {
    const double s = 0.1;
    struct Case {
        double k, el;
        bool converges;
    };
    // f' = Vh - s k Vu with the view along +u (azimuth 0) or -u (180)
    for (const Case c : {Case{0.0, 30, true}, Case{5.0, 60, true}, Case{-5.0, 20, true}, Case{-20.0, 30, false},
                         Case{-40.0, 60, false}}) {
        const HeightMap m = ramp(256, c.k);
        const View V = view_from_angles(c.el, 0);
        const double fp = V.h - s * c.k * V.u;
        ASSERT_EQ(fp > 0 && fp < 2, c.converges) << "case set-up: f' = " << fp;
        const Hit it = iterative(m, s, 0.45, 0.5, V, 1e-9, 400);
        const Hit ex = exact(m, s, 0.45, 0.5, V);
        if (c.converges) {
            EXPECT_TRUE(it.converged) << "f' = " << fp;
            EXPECT_NEAR(it.u, ex.u, 1e-6);
        } else {
            EXPECT_FALSE(it.converged) << "f' = " << fp;
        }
    }
}

// The fixed-point loop tracks the double iteration with the same (nearest-texel, 8-bit) height lookup.
TEST(Parallax, FixedPointLoopTracksDoubleIteration) {
    const StepFormat fmt;
    const double s = 0.05;
    for (const auto& name : heightmap_names()) {
        const HeightMap m = make_heightmap(name, 256);
        const FixedParallax fp = make_fixed(m, s, fmt);
        std::mt19937_64 rng(9);
        std::uniform_real_distribution<double> u01(0.0, 1.0);
        double worst = 0, sum = 0;
        int n = 0;
        for (int k = 0; k < 400; ++k) {
            const View V = view_from_angles(20 + 60 * u01(rng), 360 * u01(rng));
            const double u0 = u01(rng), v0 = u01(rng);
            const int64_t vu = std::llround(std::ldexp(V.u, fmt.v_f)), vv = std::llround(std::ldexp(V.v, fmt.v_f)),
                          vh = std::llround(std::ldexp(V.h, fmt.v_f));
            const FixedHit fh = iterative_fixed(fp, std::llround(std::ldexp(u0, fmt.f)),
                                                std::llround(std::ldexp(v0, fmt.f)), vu, vv, vh, 0, 6);
            // the same six steps in double with the same lookup
            double u = u0, v = v0, hv = 0, dp = 0;
            for (int i = 0; i < 6; ++i) {
                hv += dp * V.h;
                const int ti = int(std::floor(u * 256)) & 255, tj = int(std::floor(v * 256)) & 255;
                const double d = std::ldexp(double(fp.height[size_t(tj) * 256 + size_t(ti)]), -fmt.f) - hv;
                if (d == 0) break;
                u += d * V.u;
                v += d * V.v;
                dp = d;
            }
            const double e = std::hypot(std::ldexp(double(fh.u), -fmt.f) - u, std::ldexp(double(fh.v), -fmt.f) - v) * 256;
            worst = std::max(worst, e);
            sum += e;
            ++n;
        }
        // a texel lookup may flip where rounding moves P across a texel edge: rare, and bounded by the map
        EXPECT_LT(sum / n, 0.2) << name << " (worst " << worst << " texels)";
    }
}

namespace {
// the one harness (sim/rtl/harness.h), reset applied once
struct Dut : spec::Harness<Vparallax_step> {
    Dut() : Harness(spec::active_high<Vparallax_step>([](Vparallax_step& v) -> CData& { return v.rst; })) {
        reset();
    }
};

uint32_t bits(int64_t x, int w) { return uint32_t(uint64_t(x) & ((uint64_t(1) << w) - 1)); }
int64_t sext(uint64_t x, int w) {
    const uint64_t m = (uint64_t(1) << w) - 1;
    x &= m;
    return (x >> (w - 1)) ? int64_t(x) - (int64_t(1) << w) : int64_t(x);
}
}  // namespace

// rtl/parallax_step.v against step_fixed: random words of every width (saturation and wrap included),
// in-range steps, and whole iterations traced from iterative_fixed; one step per clock, seven cycles latency.
TEST(ParallaxStepRtl, BitExactAgainstModel) {
    const StepFormat fmt;
    Dut d;
    std::mt19937_64 rng(17);
    std::vector<StepIn> ins;
    auto rnd = [&](int w) { return sext(rng(), w); };
    for (int k = 0; k < 20000; ++k) {  // raw words: every corner of the formats
        StepIn in;
        in.u = rnd(fmt.uv_w);
        in.v = rnd(fmt.uv_w);
        in.h = rnd(fmt.h_w);
        in.hv_prev = rnd(fmt.h_w);
        in.d_prev = rnd(fmt.h_w);
        in.vu = rnd(fmt.v_w);
        in.vv = rnd(fmt.v_w);
        in.vh = rnd(fmt.v_w);
        if (k % 7 == 0) in.d_prev = (k & 8) ? (int64_t(1) << (fmt.h_w - 1)) - 1 : -(int64_t(1) << (fmt.h_w - 1));
        if (k % 11 == 0) in.vh = -(int64_t(1) << (fmt.v_w - 1));
        ins.push_back(in);
    }
    for (const auto& name : heightmap_names()) {  // traced iterations: the values a real loop presents
        const FixedParallax fp = make_fixed(make_heightmap(name, 256), 0.05, fmt);
        std::uniform_real_distribution<double> u01(0.0, 1.0);
        for (int k = 0; k < 200; ++k) {
            const View V = view_from_angles(5 + 85 * u01(rng), 360 * u01(rng));
            iterative_fixed(fp, std::llround(std::ldexp(u01(rng), fmt.f)), std::llround(std::ldexp(u01(rng), fmt.f)),
                            std::llround(std::ldexp(V.u, fmt.v_f)), std::llround(std::ldexp(V.v, fmt.v_f)),
                            std::llround(std::ldexp(V.h, fmt.v_f)), 0, 12, &ins);
        }
    }
    constexpr size_t kLatency = 7;  // parallax_step's pipeline stages
    size_t checked = 0;
    for (size_t k = 0; k < ins.size() + kLatency; ++k) {
        if (k < ins.size()) {
            const StepIn& in = ins[k];
            d->in_valid = 1;
            d->u_i = bits(in.u, fmt.uv_w);
            d->v_i = bits(in.v, fmt.uv_w);
            d->h_i = bits(in.h, fmt.h_w);
            d->hv_prev_i = bits(in.hv_prev, fmt.h_w);
            d->d_prev_i = bits(in.d_prev, fmt.h_w);
            d->vu_i = bits(in.vu, fmt.v_w);
            d->vv_i = bits(in.vv, fmt.v_w);
            d->vh_i = bits(in.vh, fmt.v_w);
        } else {
            d->in_valid = 0;
        }
        d.tick();
        if (k + 1 >= kLatency && k + 1 - kLatency < ins.size()) {
            // outputs now (after k + 1 edges) belong to the input presented at k + 1 - kLatency
            const size_t j = k + 1 - kLatency;
            ASSERT_TRUE(d->out_valid) << k;
            const StepOut o = step_fixed(fmt, ins[j]);
            ASSERT_EQ(sext(d->u_o, fmt.uv_w), o.u) << "step " << j;
            ASSERT_EQ(sext(d->v_o, fmt.uv_w), o.v) << "step " << j;
            ASSERT_EQ(sext(d->hv_o, fmt.h_w), o.hv) << "step " << j;
            ASSERT_EQ(sext(d->d_o, fmt.h_w), o.d) << "step " << j;
            ++checked;
        } else {
            ASSERT_FALSE(d->out_valid) << k;
        }
    }
    EXPECT_EQ(checked, ins.size());
    d.tick();
    EXPECT_FALSE(d->out_valid);
}

// The model's arithmetic: in range, each result equals the real-number formula truncated as documented.
TEST(ParallaxStepRtl, ModelMatchesFormula) {
    const StepFormat fmt;
    std::mt19937_64 rng(3);
    std::uniform_int_distribution<int64_t> h(-(1 << 13), 1 << 13), vv(-(1 << 14), 1 << 14), uv(-(1 << 20), 1 << 20);
    for (int k = 0; k < 10000; ++k) {
        StepIn in{uv(rng), uv(rng), h(rng), h(rng), h(rng), vv(rng), vv(rng), vv(rng)};
        const StepOut o = step_fixed(fmt, in);
        const int64_t hv = in.hv_prev + int64_t(std::floor(double(in.d_prev * in.vh) / 16384.0));
        EXPECT_EQ(o.hv, hv);
        EXPECT_EQ(o.d, in.h - hv);
        EXPECT_EQ(o.u, in.u + int64_t(std::floor(double(o.d * in.vu) / 16384.0)));
        EXPECT_EQ(o.v, in.v + int64_t(std::floor(double(o.d * in.vv) / 16384.0)));
    }
}
