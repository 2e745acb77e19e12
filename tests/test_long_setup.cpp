// test_long_setup.cpp - make test-long for spec_setup and spec_shader (issue 13, docs/setup.md): random and
// degenerate span ends (every SpanKind of setup_eval.h, n 0..1023, both gamma rules, and raw bit patterns)
// through the Verilated RTL against the bit-exact models, bit for bit. Not part of make test.
//
// SPEC_LONG_SPANS (default 1000000) spans through each configuration: spec_setup (the multiplier setup, ecp5)
// and spec_setup_small (the small CORDIC setup, up5k) through their AXI4-Stream ports with random stalls on both
// sides, and a tenth of that through spec_shader in each configuration (every pixel, tlast and tuser checked).
// SPEC_LONG_SEED (default 1) picks the run. Each test prints what it checked.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <deque>
#include <limits>
#include <random>

#include "Vspec_setup.h"
#include "Vspec_setup_small.h"
#include "Vspec_shader.h"
#include "Vspec_shader_up5k.h"
#include "cli.h"
#include "common.h"
#include "setup_config.h"
#include "setup_driver.h"
#include "setup_eval.h"

using namespace spec;

namespace {
const uint64_t kSpans = spec::test::env_u64("SPEC_LONG_SPANS", 1000000);
const uint64_t kSeed = spec::test::env_u64("SPEC_LONG_SEED", 1);

// A quarter raw bit patterns, the rest span ends of every kind with n 0..1023 and either gamma rule.
SetupInput long_input(std::mt19937_64& rng, const SetupFormat& sf, uint32_t max_len) {
    SetupInput in = rng() % 4 == 0 ? random_raw(rng, sf)
                                   : random_case(rng, sf, SpanKind(rng() % unsigned(SpanKind::count)),
                                                 static_cast<unsigned>(rng() % 1024), max_len);
    if (rng() % 4 == 0) in.midpoint = !in.midpoint;
    in.l %= max_len + 1;
    return in;
}

bool same(const SetupOut& o, const SetupResult& r) {
    return o.regs.c == r.regs.c && o.regs.zeta0 == r.regs.zeta0 && o.regs.dzeta == r.regs.dzeta &&
           o.regs.n == r.regs.n && o.regs.len == r.regs.len && o.flags == r.flags;
}

template <class V>
void shader_run(const char* name, SetupConfig c, uint64_t spans, uint32_t max_len, uint64_t seed) {
    const ConfigSetupModel sm(c);
    const Model core(shader_core_format(c));
    std::mt19937_64 rng(seed);
    ShaderDriver<V> d;
    const double modes[][2] = {{1.0, 1.0}, {0.9, 0.9}, {0.5, 1.0}, {1.0, 0.5}, {0.3, 0.3}, {1.0, 0.1}, {0.97, 0.97}};
    uint64_t done = 0, pixels = 0;
    for (size_t batch = 0; done < spans; ++batch) {
        const auto& m = modes[batch % (sizeof modes / sizeof modes[0])];
        std::vector<SetupInput> in;
        for (uint64_t i = 0; i < 500 && done + i < spans; ++i) in.push_back(long_input(rng, sm.format(), max_len));
        const std::vector<ShaderPixel> px = d.run(in, m[0], m[1], rng);
        size_t k = 0;
        for (size_t s = 0; s < in.size(); ++s) {
            const SetupResult r = sm.run(in[s]);
            const std::vector<uint32_t> want = core.span(r.regs);
            for (size_t i = 0; i < want.size(); ++i, ++k) {
                ASSERT_LT(k, px.size()) << name << ": missing pixels, span " << done + s;
                ASSERT_EQ(px[k].value, want[i]) << name << ": span " << done + s << " pixel " << i;
                ASSERT_EQ(px[k].last, i + 1 == want.size()) << name << ": tlast, span " << done + s << " pixel " << i;
                ASSERT_EQ(px[k].flags, r.flags) << name << ": tuser, span " << done + s << " pixel " << i;
            }
        }
        ASSERT_EQ(k, px.size()) << name << ": extra pixels";
        done += in.size();
        pixels += px.size();
    }
    std::printf("%s: %llu spans, %llu pixels, bit for bit the models (%llu clocks)\n", name,
                (unsigned long long)done, (unsigned long long)pixels, (unsigned long long)d.cycle());
}

// A setup through its AXI4-Stream ports with random stalls on both sides.
template <class V>
void setup_run(const char* name, SetupConfig c, uint64_t spans, uint64_t seed) {
    const ConfigSetupModel sm(c);
    std::mt19937_64 rng(seed);
    SetupStreamDriver<V> d;
    const double modes[][2] = {{1.0, 1.0}, {0.7, 0.3}, {0.3, 0.9}, {0.97, 0.97}};
    uint64_t done = 0;
    for (size_t batch = 0; done < spans; ++batch) {
        std::vector<SetupInput> in;
        for (uint64_t i = 0; i < 2000 && done + i < spans; ++i) in.push_back(long_input(rng, sm.format(), 1023));
        const auto& m = modes[batch % 4];
        const std::vector<SetupOut> out = d.run(in, m[0], m[1], rng);
        ASSERT_EQ(out.size(), in.size());
        for (size_t i = 0; i < in.size(); ++i) {
            ASSERT_TRUE(same(out[i], sm.run(in[i]))) << name << ": span " << done + i;
            ASSERT_TRUE(out[i].reserved_zero) << name << ": span " << done + i << ": reserved descriptor bits";
        }
        done += in.size();
    }
    std::printf("%s: %llu spans through AXI4-Stream with stalls, bit for bit the model (%llu clocks)\n", name,
                (unsigned long long)done, (unsigned long long)d.cycle());
}
}  // namespace

TEST(LongSetup, MultiplierSetupAgainstModel) {
    setup_run<Vspec_setup>("spec_setup (ecp5)", SetupConfig::ecp5, kSpans, kSeed * 1000 + 12);
}

TEST(LongSetup, SmallSetupAgainstModel) {
    setup_run<Vspec_setup_small>("spec_setup_small (up5k)", SetupConfig::up5k, kSpans, kSeed * 1000 + 15);
}

TEST(LongSetup, ShaderEcp5AgainstModels) {
    shader_run<Vspec_shader>("spec_shader (ecp5)", SetupConfig::ecp5, kSpans / 10, 24, kSeed * 1000 + 13);
}

TEST(LongSetup, ShaderUp5kAgainstModels) {
    shader_run<Vspec_shader_up5k>("spec_shader (up5k)", SetupConfig::up5k, kSpans / 10, 24, kSeed * 1000 + 14);
}
