// rtl/parallax_iter.v (the paper's whole iteration around parallax_step, several fragments in flight) bit for
// bit against its model iterate_fixed, through a memory with random latency, out-of-order responses and
// stalls on every port; and its throughput against the number of slots.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "parallax.h"
#include "parallax_fixed.h"
#include "parallax_rtl.h"

using namespace spec::methods;

namespace {
// Fragments over the four maps, from the polygon and from the top, with the thresholds and caps a user might
// choose (0 and 63 included).
std::vector<IterJob> map_jobs(const FixedParallax& fp, double s, uint64_t seed, int n) {
    const StepFormat fmt;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    std::vector<IterJob> jobs;
    for (int k = 0; k < n; ++k) {
        const View V = view_from_angles(5 + 85 * u01(rng), 360 * u01(rng));
        const uint64_t thr = k % 5 == 0 ? 0 : uint64_t(to_fixed(s / 512, fmt.f)) * (1 + rng() % 4);
        const uint32_t cap = k % 17 == 0 ? 0 : k % 13 == 0 ? 63 : uint32_t(1 + rng() % 24);
        jobs.push_back(job_for(fmt, s, u01(rng), u01(rng), V.u, V.v, V.h, k % 2 == 1, thr, cap, uint32_t(k)));
    }
    (void)fp;
    return jobs;
}

void expect_matches_model(const std::vector<IterJob>& jobs, const HeightFetch& fetch, const IterRunResult& r,
                          const char* what) {
    const StepFormat fmt;
    ASSERT_FALSE(r.timed_out) << what;
    EXPECT_TRUE(r.stable) << what << ": an output register changed while stalled";
    uint64_t steps = 0;
    for (size_t k = 0; k < jobs.size(); ++k) {
        ASSERT_EQ(r.seen[k], 1) << what << ": fragment " << k << " came out " << r.seen[k] << " times";
        const FixedHit m = iterate_fixed(fmt, jobs[k], fetch);
        ASSERT_EQ(r.hits[k].u, m.u) << what << ": fragment " << k;
        ASSERT_EQ(r.hits[k].v, m.v) << what << ": fragment " << k;
        ASSERT_EQ(r.hits[k].iterations, m.iterations) << what << ": fragment " << k;
        ASSERT_EQ(r.hits[k].converged, m.converged) << what << ": fragment " << k;
        steps += uint64_t(m.iterations);
    }
    EXPECT_EQ(r.requests, steps) << what << ": one fetch per step";
}
}  // namespace

TEST(ParallaxIterRtl, BitExactOnTheMapsWithRandomLatencyAndStalls) {
    const double s = 0.05;
    for (const auto& name : heightmap_names()) {
        const FixedParallax fp = make_fixed(make_heightmap(name, 64), s);
        const HeightFetch fetch = [&](int64_t u, int64_t v) { return fp.lookup(u, v); };
        const std::vector<IterJob> jobs = map_jobs(fp, s, 11, 400);
        IterRunConfig cfg;
        cfg.latency_min = 1;
        cfg.latency_max = 12;
        cfg.in_order = false;
        cfg.p_req_stall = 0.2;
        cfg.p_out_stall = 0.3;
        cfg.p_in_gap = 0.2;
        cfg.p_bogus_rsp = 0.1;
        cfg.seed = 5;
        for (IterBuild b : {IterBuild::slots1, IterBuild::slots4, IterBuild::slots16}) {
            const IterRunResult r = run_parallax_iter(b, jobs, fetch, cfg);
            expect_matches_model(jobs, fetch, r, name.c_str());
        }
    }
}

// Every field at random over its whole range (saturating heights, wrapping coordinates, negative Vh, huge
// thresholds), against a memory that answers any H_W-bit word.
TEST(ParallaxIterRtl, BitExactOnRawWords) {
    const StepFormat fmt;
    std::mt19937_64 rng(23);
    auto word = [&](int w) {
        const uint64_t x = rng() & ((uint64_t(1) << w) - 1);
        return (x >> (w - 1)) ? int64_t(x) - (int64_t(1) << w) : int64_t(x);
    };
    std::vector<IterJob> jobs;
    for (int k = 0; k < 1500; ++k) {
        IterJob j;
        j.u = word(fmt.uv_w);
        j.v = word(fmt.uv_w);
        j.hv0 = word(fmt.h_w);
        j.vu = word(fmt.v_w);
        j.vv = word(fmt.v_w);
        j.vh = k % 9 == 0 ? -(int64_t(1) << (fmt.v_w - 1)) : word(fmt.v_w);
        j.threshold = k % 3 == 0 ? rng() % 64 : uint64_t(word(fmt.h_w)) & 0xffff;
        j.max_iter = uint32_t(rng() % 64);
        j.tag = uint32_t(k);
        jobs.push_back(j);
    }
    const HeightFetch fetch = [](int64_t u, int64_t v) {
        uint64_t h = uint64_t(u) * 0x9e3779b97f4a7c15ull ^ uint64_t(v) * 0xc2b2ae3d27d4eb4full;
        h ^= h >> 29;
        const int64_t w = int64_t(h & 0xffff);
        return w >= 0x8000 ? w - 0x10000 : w;
    };
    IterRunConfig cfg;
    cfg.latency_min = 1;
    cfg.latency_max = 20;
    cfg.in_order = false;
    cfg.p_req_stall = 0.3;
    cfg.p_out_stall = 0.3;
    cfg.p_in_gap = 0.1;
    cfg.p_bogus_rsp = 0.3;
    cfg.seed = 9;
    for (IterBuild b : {IterBuild::slots1, IterBuild::slots4, IterBuild::slots16}) {
        expect_matches_model(jobs, fetch, run_parallax_iter(b, jobs, fetch, cfg), "raw words");
    }
}

// With a fixed latency and no stalls a slot turns around in latency + 11 clocks (request register, memory,
// operand register, seven step stages, write-back register, slot update), so one slot gives 1 / (L + 11)
// steps per clock and latency + 11 slots give one.
TEST(ParallaxIterRtl, ThroughputFollowsTheSlots) {
    const double s = 0.05;
    const FixedParallax fp = make_fixed(make_heightmap("rocks", 64), s);
    const HeightFetch fetch = [&](int64_t u, int64_t v) { return fp.lookup(u, v); };
    std::vector<IterJob> jobs = map_jobs(fp, s, 3, 300);
    for (auto& j : jobs) j.max_iter = 16, j.threshold = 0;  // 16 steps each
    for (int lat : {1, 4}) {
        IterRunConfig cfg;
        cfg.latency_min = cfg.latency_max = lat;
        const IterRunResult one = run_parallax_iter(IterBuild::slots1, jobs, fetch, cfg);
        const IterRunResult many = run_parallax_iter(IterBuild::slots16, jobs, fetch, cfg);
        ASSERT_FALSE(one.timed_out);
        ASSERT_FALSE(many.timed_out);
        const double r1 = double(one.steps) / double(one.cycles), r16 = double(many.steps) / double(many.cycles);
        EXPECT_NEAR(r1, 1.0 / (lat + 11), 0.01) << "latency " << lat;
        EXPECT_GT(r16, 0.95) << "latency " << lat;
    }
}
