// spec_stream with LANES = 2 and 4 pixels per beat (issue 14, docs/stream.md): the pixels of LANES = 1, bit
// for bit and in the same order, under random stalls on both sides; the beats' m_axis_tkeep and m_axis_tlast
// (checked beat by beat by StreamDriver::run); one beat per clock (the beat count of a run without stalls is
// what the slot rules give, plus the pipeline's latency); AXI4-Stream rules; reset in the middle of a span.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "Vspec_stream.h"
#include "Vspec_stream_l2.h"
#include "Vspec_stream_l2p.h"
#include "Vspec_stream_l2p_up5k.h"
#include "Vspec_stream_l4.h"
#include "Vspec_stream_l4p.h"
#include "analysis.h"
#include "cmd_bench.h"
#include "cmd_span.h"
#include "cli.h"
#include "spec_model.h"
#include "spec_params.h"
#include "stream_driver.h"

using namespace spec;

namespace {
// Random spans: one-pixel and short spans often (where slots are left empty and spans meet inside a beat),
// some long, one in sixteen with raw register contents (saturating angles, any step).
std::vector<SpanRegs> lane_spans(std::mt19937_64& rng, const Model& m, size_t count, uint32_t max_len) {
    std::vector<SpanRegs> v;
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (size_t i = 0; i < count; ++i) {
        SpanRegs r;
        r.n = static_cast<uint32_t>(rng() % 1024);
        r.c = static_cast<uint32_t>(rng() & 0xffff);
        const int kind = static_cast<int>(rng() % 5);
        r.len = kind == 0 ? 0 : kind <= 2 ? static_cast<uint32_t>(rng() % 9) : static_cast<uint32_t>(rng() % (max_len + 1));
        const double reach = std::min(M_PI, 6.0 * epicentre_end(r.n));
        r.zeta0 = m.quantize_angle(reach * u(rng));
        r.dzeta = m.quantize_angle(r.len ? (reach * u(rng) - m.angle_value(r.zeta0)) / r.len : 0.0);
        if (rng() % 16 == 0) {
            r.zeta0 = static_cast<int32_t>(rng());
            r.dzeta = static_cast<int32_t>(rng()) >> (rng() % 32);
        }
        v.push_back(r);
    }
    return v;
}

void expect_model(const Model& m, const std::vector<SpanRegs>& spans, const std::vector<StreamPixel>& px) {
    size_t k = 0;
    for (size_t s = 0; s < spans.size(); ++s) {
        const auto want = m.span(spans[s]);
        for (size_t i = 0; i < want.size(); ++i, ++k) {
            ASSERT_LT(k, px.size());
            ASSERT_EQ(px[k].value, want[i]) << "span " << s << " pixel " << i << " n=" << spans[s].n;
            ASSERT_EQ(px[k].last, i + 1 == want.size()) << "last, span " << s << " pixel " << i;
        }
    }
    ASSERT_EQ(k, px.size()) << "extra pixels";
}

// Beats of a run without stalls, from the slot rules alone: PACK = 0, ceil((l + 1) / LANES) per span; PACK = 1,
// spans packed one after another with at most one span starting in a beat.
uint64_t ideal_beats(const std::vector<SpanRegs>& spans, int lanes, bool pack) {
    uint64_t beats = 0;
    if (!pack) {
        for (const auto& s : spans) beats += (uint64_t(s.len) + lanes) / lanes;
        return beats;
    }
    uint64_t rem = 0;
    size_t i = 0;
    while (i < spans.size() || rem > 0) {
        uint64_t free = lanes;
        const uint64_t t = std::min<uint64_t>(rem, free);
        rem -= t;
        free -= t;
        if (free > 0 && rem == 0 && i < spans.size()) {
            const uint64_t p = uint64_t(spans[i++].len) + 1;
            rem = p - std::min(p, free);
        }
        ++beats;
    }
    return beats;
}

template <class V, int L, bool P>
void random_stalls(const Format& f, uint64_t seed, int rounds) {
    const Model m(f);
    StreamDriver<V, L, P> d;
    std::mt19937_64 rng(seed);
    const Stalls modes[] = {{1.0, 1.0}, {0.9, 0.9}, {0.5, 1.0}, {1.0, 0.5}, {0.3, 0.3}, {1.0, 0.1}, {0.1, 1.0}};
    size_t pixels = 0;
    for (int round = 0; round < rounds; ++round) {
        for (const Stalls& st : modes) {
            const auto spans = lane_spans(rng, m, 300, 80);
            const auto px = d.run(spans, st, rng);
            expect_model(m, spans, px);
            pixels += px.size();
        }
    }
    ::testing::Test::RecordProperty("pixels", std::to_string(pixels));
    EXPECT_GT(pixels, 50000u);
}

template <class V, int L, bool P>
void one_beat_per_clock(uint64_t seed) {
    const Model m;
    StreamDriver<V, L, P> d;
    std::mt19937_64 rng(seed);
    for (uint32_t max_len : {0u, 1u, 3u, 9u, 200u}) {
        auto spans = lane_spans(rng, m, 1500, max_len);
        if (max_len == 0)
            for (auto& r : spans) r.len = 0;   // one-pixel spans back to back: one span starts every beat
        const uint64_t c0 = d.cycle(), b0 = d.beats();
        const auto px = d.run(spans, Stalls{}, rng);
        expect_model(m, spans, px);
        const uint64_t want = ideal_beats(spans, L, P);
        EXPECT_EQ(d.beats() - b0, want) << "max_len " << max_len;
        // run() keeps the sink ready kDrainCycles after the last pixel (watching for extra ones)
        const uint64_t drain = StreamDriver<V, L, P>::kDrainCycles;
        EXPECT_LE(d.cycle() - c0 - drain, want + spec_params::STREAM_LATENCY + 4)
            << "max_len " << max_len;
    }
}
}  // namespace

TEST(Lanes, TwoLanesEqualModelUnderRandomStalls) { random_stalls<Vspec_stream_l2, 2, false>(Format(), 41, 3); }
TEST(Lanes, FourLanesEqualModelUnderRandomStalls) { random_stalls<Vspec_stream_l4, 4, false>(Format(), 42, 3); }
TEST(Lanes, FourLanesPackedEqualModelUnderRandomStalls) {
    random_stalls<Vspec_stream_l4p, 4, true>(Format(), 43, 3);
}
TEST(Lanes, TwoLanesPackedEqualModelUnderRandomStalls) {
    random_stalls<Vspec_stream_l2p, 2, true>(Format(), 45, 3);
}
TEST(Lanes, TwoLanesPackedUp5kEqualModelUnderRandomStalls) {
    random_stalls<Vspec_stream_l2p_up5k, 2, true>(config_format("up5k"), 44, 3);
}

TEST(Lanes, OneBeatPerClock) {
    one_beat_per_clock<Vspec_stream_l2, 2, false>(51);
    one_beat_per_clock<Vspec_stream_l4, 4, false>(52);
    one_beat_per_clock<Vspec_stream_l2p, 2, true>(54);
    one_beat_per_clock<Vspec_stream_l4p, 4, true>(53);
}

// The same pixels as LANES = 1, in the same order (the model equality above implies it; this compares the cores
// directly).
TEST(Lanes, SamePixelsAsOneLane) {
    const Model m;
    std::mt19937_64 rng(54);
    const auto spans = lane_spans(rng, m, 800, 40);
    StreamDriver<Vspec_stream> one;
    StreamDriver<Vspec_stream_l4p, 4, true> four;
    const auto a = one.run(spans, Stalls{0.8, 0.7}, rng);
    const auto b = four.run(spans, Stalls{0.7, 0.8}, rng);
    ASSERT_EQ(a.size(), b.size());
    for (size_t k = 0; k < a.size(); ++k) ASSERT_EQ(a[k].value, b[k].value) << "pixel " << k;
}

// AXI4-Stream source rules with several lanes: valid held until ready, data, keep and last stable meanwhile.
TEST(Lanes, AxiRulesHoldUnderBackpressure) {
    const Model m;
    StreamDriver<Vspec_stream_l4p, 4, true> d;
    std::mt19937_64 rng(55);
    bool prev_stalled = false;
    uint64_t prev_data = 0;
    unsigned prev_keep = 0;
    bool prev_last = false;
    size_t checked = 0;
    auto probe = [&](Vspec_stream_l4p& t) {
        if (prev_stalled) {
            ASSERT_TRUE(t.m_axis_tvalid) << "valid dropped before ready";
            ASSERT_EQ(uint64_t(t.m_axis_tdata), prev_data) << "data changed while stalled";
            ASSERT_EQ(unsigned(t.m_axis_tkeep), prev_keep) << "keep changed while stalled";
            ASSERT_EQ(t.m_axis_tlast != 0, prev_last) << "last changed while stalled";
            ++checked;
        }
        prev_stalled = t.m_axis_tvalid && !t.m_axis_tready;
        prev_data = t.m_axis_tdata;
        prev_keep = t.m_axis_tkeep;
        prev_last = t.m_axis_tlast != 0;
    };
    const auto spans = lane_spans(rng, m, 1500, 30);
    expect_model(m, spans, d.run(spans, Stalls{0.6, 0.4}, rng, 0, probe));
    EXPECT_GT(checked, 3000u);
}

// A reset in the middle of a span: nothing of it appears afterwards, and the core works normally after.
TEST(Lanes, ResetInTheMiddleOfASpan) {
    const Model m;
    StreamDriver<Vspec_stream_l2, 2, false> d;
    std::mt19937_64 rng(56);
    for (int cut = 1; cut < 50; cut += 3) {
        SpanRegs r{0xffff, m.quantize_angle(0.001), m.quantize_angle(-0.05), 50, 100};
        uint32_t w[kDescWords];
        pack_descriptor(r, w);
        auto& t = d.top();
        t.m_axis_tready = 1;
        int accepted = 0;
        for (int c = 0; c < cut; ++c) {
            t.s_axis_tvalid = accepted < 2;
            for (int i = 0; i < kDescWords; ++i) t.s_axis_tdata[i] = w[i];
            t.eval();
            if (t.s_axis_tvalid && t.s_axis_tready) ++accepted;
            d.step();
        }
        t.s_axis_tvalid = 0;
        t.rst_n = 0;
        d.step();
        t.rst_n = 1;
        for (int c = 0; c < 60; ++c) {
            t.eval();
            ASSERT_FALSE(t.m_axis_tvalid) << "a beat after the reset, cut " << cut;
            d.step();
        }
        const auto spans = lane_spans(rng, m, 20, 30);
        expect_model(m, spans, d.run(spans, Stalls{0.8, 0.8}, rng));
    }
}

// specsim span --lanes / --pack: only with the stream model, in patent mode, LANES 1, 2, 4; --pack with 4.
TEST(Lanes, SpanOptionsRefuseWhatNoCoreRuns) {
    auto parse = [](std::vector<std::string> extra) {
        std::vector<std::string> v{"specsim", "span", "--n", "3", "--c", "0.5", "--zeta0", "0", "--dzeta", "0.1",
                                   "--len", "4"};
        v.insert(v.end(), extra.begin(), extra.end());
        std::vector<char*> argv;
        for (auto& x : v) argv.push_back(&x[0]);
        return parse_span(int(argv.size()), argv.data());
    };
    EXPECT_EQ(parse({"--model", "stream", "--lanes", "4", "--pack"}).lanes, 4);
    EXPECT_TRUE(parse({"--model", "stream", "--lanes", "4", "--pack"}).pack);
    EXPECT_THROW(parse({"--model", "stream", "--lanes", "3"}), UsageError);
    EXPECT_THROW(parse({"--model", "stream", "--lanes", "8"}), UsageError);
    EXPECT_THROW(parse({"--model", "rtl", "--lanes", "2"}), UsageError);
    EXPECT_THROW(parse({"--model", "stream", "--lanes", "2", "--pack"}), UsageError);
    EXPECT_THROW(parse({"--model", "stream", "--lanes", "2", "--mode", "tuned"}), UsageError);
}

// bench-lanes on a small frame of the default scene: every configuration gives all the pixels, the beats the
// slot rules give, one beat per clock after the latency, and packing never costs beats.
TEST(Lanes, BenchLanesOnSceneSpans) {
    const auto spans = scene_spans("default", 96, 64);
    ASSERT_GT(spans.size(), 20u);
    const LanesRow r = bench_lanes_row(spans, 96, 64);
    uint64_t px = 0;
    for (const auto& s : spans) px += uint64_t(s.len) + 1;
    EXPECT_EQ(r.pixels, px);
    ASSERT_EQ(r.figures.size(), 5u);
    for (const auto& f : r.figures) {
        EXPECT_EQ(f.beats, ideal_beats(spans, f.lanes, f.pack)) << f.name;
        EXPECT_LE(f.cycles, f.beats + spec_params::STREAM_LATENCY + 4) << f.name;
        EXPECT_NEAR(f.ppc, double(px) / double(f.cycles), 1e-9) << f.name;
    }
    EXPECT_LE(r.figures[2].beats, r.figures[1].beats);   // 2 packed <= 2
    EXPECT_LE(r.figures[4].beats, r.figures[3].beats);   // 4 packed <= 4
}
