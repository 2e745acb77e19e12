// test_long_setup.cpp - make test-long for spec_setup and spec_shader (issue 13, docs/setup.md): random and
// degenerate span ends (every SpanKind of setup_eval.h, n 0..1023, both gamma rules, and raw bit patterns)
// through the Verilated RTL against the bit-exact models, bit for bit. Not part of make test.
//
// SPEC_LONG_SPANS (default 1000000) spans through spec_setup_pipe (the fully pipelined arithmetic, a span a
// clock with random bubbles), a tenth of that through spec_setup and spec_shader (pipelined, random stalls on
// both sides, every pixel, tlast and tuser checked) and a thousandth through the small configuration (one span
// at a time: thousands of clocks a span, make bench-shader). SPEC_LONG_SEED (default 1) picks the run. Each
// test prints what it checked.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <deque>
#include <limits>
#include <random>

#include "Vspec_setup.h"
#include "Vspec_setup_pipe.h"
#include "Vspec_shader.h"
#include "Vspec_shader_small.h"
#include "cli.h"
#include "common.h"
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
void shader_run(const char* name, const Model& core, uint64_t spans, uint32_t max_len, uint64_t seed) {
    const SetupModel sm;
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
}  // namespace

// spec_setup_pipe: a span (or a bubble, 1 in 8) every clock; each descriptor and its flags against the model in order.
TEST(LongSetup, PipeAgainstModel) {
    const SetupModel sm;
    std::mt19937_64 rng(kSeed * 1000 + 11);
    SetupPipeDriver<Vspec_setup_pipe> d;
    std::deque<SetupInput> pending;
    uint64_t sent = 0, checked = 0;
    auto drain = [&] {
        for (const SetupOut& o : d.out()) {
            ASSERT_FALSE(pending.empty()) << "a descriptor nobody sent, after " << checked;
            const SetupResult r = sm.run(pending.front());
            ASSERT_TRUE(same(o, r)) << "span " << checked << ": c " << o.regs.c << " / " << r.regs.c << ", zeta0 "
                                    << o.regs.zeta0 << " / " << r.regs.zeta0 << ", dzeta " << o.regs.dzeta << " / "
                                    << r.regs.dzeta << ", flags " << o.flags << " / " << r.flags;
            pending.pop_front();
            ++checked;
        }
        d.out().clear();
    };
    while (sent < kSpans) {
        if (rng() % 8 == 0) {
            d.push(nullptr);
        } else {
            pending.push_back(long_input(rng, sm.format(), 1023));
            d.push(&pending.back());
            ++sent;
        }
        drain();
        if (HasFatalFailure()) return;
    }
    for (int i = 0; i < 1000 && !pending.empty(); ++i) {
        d.push(nullptr);
        drain();
        if (HasFatalFailure()) return;
    }
    ASSERT_TRUE(pending.empty()) << pending.size() << " spans never came out";
    std::printf("spec_setup_pipe: %llu spans, bit for bit the model\n", (unsigned long long)checked);
}

// spec_setup (pipelined) through its AXI4-Stream ports with random stalls on both sides.
TEST(LongSetup, StreamAgainstModel) {
    const SetupModel sm;
    std::mt19937_64 rng(kSeed * 1000 + 12);
    SetupStreamDriver<Vspec_setup> d;
    const double modes[][2] = {{1.0, 1.0}, {0.7, 0.3}, {0.3, 0.9}, {0.97, 0.97}};
    uint64_t done = 0;
    for (size_t batch = 0; done < kSpans / 10; ++batch) {
        std::vector<SetupInput> in;
        for (int i = 0; i < 2000; ++i) in.push_back(long_input(rng, sm.format(), 1023));
        const auto& m = modes[batch % 4];
        const std::vector<SetupOut> out = d.run(in, m[0], m[1], rng);
        ASSERT_EQ(out.size(), in.size());
        for (size_t i = 0; i < in.size(); ++i) {
            ASSERT_TRUE(same(out[i], sm.run(in[i]))) << "span " << done + i;
            ASSERT_TRUE(out[i].reserved_zero) << "span " << done + i << ": reserved descriptor bits";
        }
        done += in.size();
    }
    std::printf("spec_setup: %llu spans through AXI4-Stream with stalls, bit for bit the model (%llu clocks)\n",
                (unsigned long long)done, (unsigned long long)d.cycle());
}

TEST(LongSetup, ShaderPipelinedAgainstModels) {
    shader_run<Vspec_shader>("spec_shader (pipelined)", Model(), kSpans / 10, 24, kSeed * 1000 + 13);
}

TEST(LongSetup, ShaderSmallAgainstModels) {
    shader_run<Vspec_shader_small>("spec_shader (small)", Model(config_format("up5k")), std::max<uint64_t>(100, kSpans / 1000),
                                   24, kSeed * 1000 + 14);
}
