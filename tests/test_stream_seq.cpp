// spec_stream_seq, the compact back end (one span at a time, docs/stream.md): bit for bit the model's pixels
// (every n, l = 0 and the longest l, angles that run off the format's ends) under random stalls, in the
// default, up5k and tuned configurations; the AXI4-Stream rules under backpressure; reset in the middle of a
// span; its latency, one pixel per clock within a span and the clocks between spans back to back.
#include <gtest/gtest.h>

#include <random>

#include "Vspec_stream_seq.h"
#include "Vspec_stream_seq_tuned.h"
#include "Vspec_stream_seq_up5k.h"
#include "common.h"
#include "spec_model.h"
#include "stream_driver.h"

using namespace spec;
using namespace spec::test;

namespace {

void expect_pixels(const Model& m, const std::vector<SpanRegs>& spans, const std::vector<StreamPixel>& px) {
    size_t k = 0;
    for (size_t s = 0; s < spans.size(); ++s) {
        const auto want = m.span(spans[s]);
        for (size_t i = 0; i < want.size(); ++i, ++k) {
            ASSERT_LT(k, px.size());
            ASSERT_EQ(px[k].value, want[i]) << "span " << s << " pixel " << i << " n=" << spans[s].n
                                            << " zeta0=" << spans[s].zeta0 << " dzeta=" << spans[s].dzeta;
            ASSERT_EQ(px[k].last, i + 1 == want.size()) << "tlast, span " << s << " pixel " << i;
        }
    }
    ASSERT_EQ(k, px.size()) << "extra pixels";
}

// Spans whose angle runs off an end of the format and stays there (saturation), among them ones where a
// wrapping adder would come back into range and light pixels up again; and steps of every size.
std::vector<SpanRegs> saturating_spans(const Model& m, std::mt19937_64& rng) {
    std::vector<SpanRegs> v;
    const int64_t hi = m.angle_max(), lo = m.angle_min();
    const int64_t half = m.quantize_angle(0.5);
    for (unsigned n : {0u, 1u, 2u, 5u, 40u, 1023u}) {
        v.push_back(SpanRegs{0xffff, half, hi - half / 2, n, 40});        // up past the top, would wrap to the bottom
        v.push_back(SpanRegs{0xffff, -half, lo + half / 2, n, 40});       // down past the bottom
        v.push_back(SpanRegs{0x8001, hi, 0, n, 3});                      // the largest steps
        v.push_back(SpanRegs{0x7fff, lo, hi, n, 3});
        v.push_back(SpanRegs{0x1234, 1, hi - 3, n, 9});                   // reaches the top exactly, then holds
        v.push_back(SpanRegs{0x4321, -1, lo + 3, n, 9});
    }
    for (int i = 0; i < 200; ++i) {   // raw register contents: any start, steps of any size
        SpanRegs r;
        r.n = static_cast<uint32_t>(rng() % 1024);
        r.c = static_cast<uint32_t>(rng() & 0xffff);
        r.len = static_cast<uint32_t>(rng() % 300);
        r.zeta0 = static_cast<int32_t>(rng());
        r.dzeta = static_cast<int32_t>(rng()) >> (rng() % 32);
        v.push_back(r);
    }
    return v;
}

template <class V>
void random_spans_under_stalls(const Model& m, uint64_t seed, int rounds, uint32_t max_len) {
    StreamDriver<V> d;
    std::mt19937_64 rng(seed);
    const Stalls modes[] = {{1.0, 1.0}, {0.9, 0.9}, {0.5, 1.0}, {1.0, 0.5}, {0.3, 0.3}, {1.0, 0.1}, {0.1, 1.0}};
    size_t pixels = 0;
    for (int round = 0; round < rounds; ++round) {
        for (const Stalls& st : modes) {
            auto spans = random_spans(rng, m, 150, max_len);
            auto px = d.run(spans, st, rng);
            expect_pixels(m, spans, px);
            pixels += px.size();
        }
    }
    // every n, each with a span of its own
    std::vector<SpanRegs> sweep;
    for (unsigned n = 0; n < 1024; ++n) sweep.push_back(random_span(rng, m, n, rng() % 4 ? 3 : 40).regs);
    expect_pixels(m, sweep, d.run(sweep, Stalls{0.8, 0.7}, rng));
    // angles off the ends of the format
    const auto sat = saturating_spans(m, rng);
    expect_pixels(m, sat, d.run(sat, Stalls{0.9, 0.6}, rng));
    ::testing::Test::RecordProperty("pixels", std::to_string(pixels));
    EXPECT_GT(pixels, size_t(rounds) * 7 * 150 * max_len / 8) << "the spans are shorter than they should be";
}

}  // namespace

TEST(StreamSeq, EqualsModelUnderRandomStalls) { random_spans_under_stalls<Vspec_stream_seq>(Model(), 121, 3, 300); }

TEST(StreamSeq, Up5kEqualsModelUnderRandomStalls) {
    random_spans_under_stalls<Vspec_stream_seq_up5k>(Model(config_format("up5k")), 122, 2, 200);
}

TEST(StreamSeq, TunedEqualsModelUnderRandomStalls) {
    Format f;
    f.mode = Mode::tuned;
    random_spans_under_stalls<Vspec_stream_seq_tuned>(Model(f), 123, 1, 100);
}

// A saturating accumulator is what the model does: a span that runs past the top of the angle range stays
// there (dark for n > 0) where a wrapping one would come back from the bottom and light up again.
TEST(StreamSeq, AnglesSaturateAtTheEnds) {
    const Model m;
    StreamDriver<Vspec_stream_seq> d;
    std::mt19937_64 rng(124);
    const int64_t half = m.quantize_angle(0.5);
    const SpanRegs up{0xffff, half, m.angle_max() - half / 2, 1, 40};
    const auto want = m.span(up);
    EXPECT_EQ(want.back(), 0u) << "the model saturates: the span stays past the end";
    const auto px = d.run({up}, Stalls{}, rng);
    ASSERT_EQ(px.size(), want.size());
    for (size_t i = 0; i < want.size(); ++i) ASSERT_EQ(px[i].value, want[i]) << "pixel " << i;
}

// The longest span (l = 2^L_W - 1, every bit of the length field), one-pixel spans, and the bits between the
// fields all ones.
TEST(StreamSeq, LongestSpansAndIgnoredDescriptorBits) {
    const Model m;
    StreamDriver<Vspec_stream_seq> d;
    d.set_ignored_bits(true);
    std::mt19937_64 rng(125);
    std::vector<SpanRegs> spans;
    spans.push_back(SpanRegs{0xffff, m.quantize_angle(3.0 / 65535), m.quantize_angle(-1.5), 1023, 65535});
    spans.push_back(SpanRegs{0x8000, m.quantize_angle(-1e-6), m.quantize_angle(0.2), 7, 0});
    spans.push_back(SpanRegs{0x1234, m.quantize_angle(-1.0 / 40000), m.quantize_angle(0.5), 100, 65535});
    spans.push_back(SpanRegs{0x0001, 0, 0, 0, 0});
    const auto more = random_spans(rng, m, 50, 30);
    spans.insert(spans.end(), more.begin(), more.end());
    expect_pixels(m, spans, d.run(spans, Stalls{0.9, 0.7}, rng));
}

TEST(StreamSeq, AxiRulesHoldUnderBackpressure) {
    const Model m;
    StreamDriver<Vspec_stream_seq> d;
    std::mt19937_64 rng(126);
    bool prev_stalled = false, prev_last = false, prev_in = false;
    uint32_t prev_data = 0;
    size_t checked = 0;
    auto probe = [&](Vspec_stream_seq& t) {
        if (prev_stalled) {
            ASSERT_TRUE(t.m_axis_tvalid) << "valid dropped before ready";
            ASSERT_EQ(t.m_axis_tdata, prev_data) << "data changed while stalled";
            ASSERT_EQ(t.m_axis_tlast != 0, prev_last) << "tlast changed while stalled";
            ++checked;
        }
        if (t.m_axis_tvalid) ASSERT_TRUE(t.m_axis_tkeep) << "tkeep is 1 with every pixel";
        ASSERT_FALSE(prev_in && t.s_axis_tready) << "ready again right after a descriptor was taken";
        prev_stalled = t.m_axis_tvalid && !t.m_axis_tready;
        prev_data = t.m_axis_tdata;
        prev_last = t.m_axis_tlast != 0;
        prev_in = t.s_axis_tvalid && t.s_axis_tready;
    };
    auto spans = random_spans(rng, m, 800, 40);
    auto px = d.run(spans, Stalls{0.6, 0.4}, rng, 0, probe);
    expect_pixels(m, spans, px);
    EXPECT_GT(checked, 5000u);
}

TEST(StreamSeq, ResetInTheMiddleOfASpan) {
    const Model m;
    StreamDriver<Vspec_stream_seq> d;
    std::mt19937_64 rng(127);
    for (int cut = 1; cut < 80; cut += 3) {
        // start a long span (and offer a second), reset after `cut` cycles, the sink sometimes stalled
        SpanRegs r{0xffff, m.quantize_angle(0.001), m.quantize_angle(-0.05), 50, 100};
        uint32_t w[kDescWords];
        pack_descriptor(r, w);
        auto& t = d.top();
        int accepted = 0;
        for (int c = 0; c < cut; ++c) {
            t.m_axis_tready = (cut % 2) ? 1 : (rng() % 2);
            t.s_axis_tvalid = accepted < 2;
            for (int i = 0; i < kDescWords; ++i) t.s_axis_tdata[i] = w[i];
            t.eval();
            if (t.s_axis_tvalid && t.s_axis_tready) ++accepted;
            d.step();
        }
        t.m_axis_tready = 1;
        t.s_axis_tvalid = 1;   // a descriptor offered during the reset is dropped
        t.rst_n = 0;
        d.step();
        t.s_axis_tvalid = 0;
        t.rst_n = 1;
        t.eval();
        EXPECT_FALSE(t.m_axis_tvalid) << cut;
        EXPECT_FALSE(t.m_axis_tlast) << cut;
        EXPECT_EQ(t.m_axis_tdata, 0u) << cut;
        EXPECT_FALSE(t.s_axis_tready) << "not ready in the cycle after reset, cut " << cut;
        d.step();
        t.eval();
        EXPECT_TRUE(t.s_axis_tready) << cut;
        for (int c = 0; c < 60; ++c) {
            t.eval();
            ASSERT_FALSE(t.m_axis_tvalid) << "pixel after reset, cut " << cut;
            d.step();
        }
        // and it works normally afterwards
        auto spans = random_spans(rng, m, 20, 30);
        expect_pixels(m, spans, d.run(spans, Stalls{0.8, 0.8}, rng));
    }
}

// No stalls, descriptors always offered: the first pixel Format::stream_seq_latency() clocks after its
// descriptor is taken, then one pixel per clock to the span's end, then stream_seq_gap() clocks without a
// pixel before the next span's first (also for l = 0 spans back to back).
template <class V>
void back_to_back(const Model& m, uint64_t seed) {
    StreamDriver<V> d;
    std::mt19937_64 rng(seed);
    const int lat = m.format().stream_seq_latency(), gap = m.format().stream_seq_gap();
    for (uint32_t max_len : {0u, 1u, 7u, 300u}) {
        auto spans = random_spans(rng, m, 200, max_len);
        if (max_len == 0)
            for (auto& r : spans) r.len = 0;
        std::vector<uint64_t> taken, out;   // cycles of accepted descriptors, of pixels
        auto probe = [&](V& t) {
            if (t.s_axis_tvalid && t.s_axis_tready) taken.push_back(d.cycle());
            if (t.m_axis_tvalid && t.m_axis_tready) out.push_back(d.cycle());
        };
        expect_pixels(m, spans, d.run(spans, Stalls{}, rng, 0, probe));
        ASSERT_EQ(taken.size(), spans.size());
        size_t k = 0;
        for (size_t s = 0; s < spans.size(); ++s) {
            ASSERT_EQ(out[k], taken[s] + lat) << "first pixel of span " << s << ", max_len " << max_len;
            for (uint32_t i = 1; i <= spans[s].len; ++i) ASSERT_EQ(out[k + i], out[k] + i) << "span " << s;
            k += spans[s].len + 1;
            if (s + 1 < spans.size()) {
                ASSERT_EQ(out[k], out[k - 1] + gap + 1) << "clocks between spans " << s << " and " << s + 1;
            }
        }
    }
}

TEST(StreamSeq, LatencyAndSpansBackToBack) { back_to_back<Vspec_stream_seq>(Model(), 128); }
TEST(StreamSeq, Up5kLatencyAndSpansBackToBack) {
    back_to_back<Vspec_stream_seq_up5k>(Model(config_format("up5k")), 129);
}
