// spec_shader in both configurations - ecp5 (spec_setup -> spec_stream) and up5k (spec_setup_small ->
// spec_stream_seq, the iCEBreaker's) - span ends in, pixels out, against the bit-exact models (the configuration's
// setup model, then the core's model) under random stalls, with tlast per span and the span's flags on tuser; the
// AXI4-Stream rules under backpressure; the sustained rate; reset in the middle of a run.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <random>

#include "Vspec_shader.h"
#include "Vspec_shader_up5k.h"
#include "setup_config.h"
#include "setup_driver.h"
#include "setup_eval.h"

using namespace spec;

namespace {
std::vector<SetupInput> shader_inputs(std::mt19937_64& rng, const SetupFormat& sf, size_t count, uint32_t max_len) {
    std::vector<SetupInput> v;
    for (size_t i = 0; i < count; ++i) {
        SetupInput in = (i % 5 == 4) ? random_raw(rng, sf)
                                     : random_case(rng, sf, SpanKind(rng() % unsigned(SpanKind::count)),
                                                   static_cast<unsigned>(rng() % 1024), max_len);
        in.l = in.l % (max_len + 1);
        v.push_back(in);
    }
    return v;
}

// The pixels the models give for the spans: the setup model's registers through the core's model.
void expect_pixels(const ConfigSetupModel& sm, const Model& core, const std::vector<SetupInput>& in,
                   const std::vector<ShaderPixel>& px) {
    size_t k = 0;
    for (size_t s = 0; s < in.size(); ++s) {
        const SetupResult r = sm.run(in[s]);
        const std::vector<uint32_t> want = core.span(r.regs);
        for (size_t i = 0; i < want.size(); ++i, ++k) {
            ASSERT_LT(k, px.size()) << "missing pixels";
            ASSERT_EQ(px[k].value, want[i]) << "span " << s << " pixel " << i;
            ASSERT_EQ(px[k].last, i + 1 == want.size()) << "tlast, span " << s << " pixel " << i;
            ASSERT_EQ(px[k].flags, r.flags) << "tuser, span " << s << " pixel " << i;
        }
    }
    ASSERT_EQ(k, px.size()) << "extra pixels";
}

// The AXI4-Stream rule at the shader's output, checked every cycle (a ShaderDriver::run on_cycle, through
// std::ref): a pixel offered without m_axis_tready is offered again unchanged, with its tlast and tuser.
// `held` counts the cycles in which that was checked.
struct OutputHolds {
    bool stalled = false;
    uint32_t data = 0;
    unsigned last = 0, user = 0;
    size_t held = 0;
    template <class V>
    void operator()(V& t) {
        if (stalled) {
            ASSERT_TRUE(t.m_axis_tvalid) << "tvalid dropped before tready";
            ASSERT_EQ(t.m_axis_tdata, data);
            ASSERT_EQ(t.m_axis_tlast, last);
            ASSERT_EQ(t.m_axis_tuser, user);
            ++held;
        }
        stalled = t.m_axis_tvalid && !t.m_axis_tready;
        data = t.m_axis_tdata;
        last = t.m_axis_tlast;
        user = t.m_axis_tuser;
    }
};
}  // namespace

TEST(Shader, Ecp5EqualsModelsUnderStalls) {
    const ConfigSetupModel sm(SetupConfig::ecp5);
    const Model core;
    std::mt19937_64 rng(51);
    ShaderDriver<Vspec_shader> d;
    const double modes[][2] = {{1.0, 1.0}, {0.9, 0.9}, {0.5, 1.0}, {1.0, 0.5}, {0.3, 0.3}, {1.0, 0.1}};
    size_t pixels = 0;
    for (const auto& m : modes) {
        const auto in = shader_inputs(rng, sm.format(), 400, 12);
        const auto px = d.run(in, m[0], m[1], rng);
        expect_pixels(sm, core, in, px);
        pixels += px.size();
    }
    RecordProperty("pixels", std::to_string(pixels));
}

TEST(Shader, AxiRulesHoldUnderBackpressure) {
    const ConfigSetupModel sm(SetupConfig::ecp5);
    std::mt19937_64 rng(53);
    ShaderDriver<Vspec_shader> d;
    OutputHolds hold;
    const auto in = shader_inputs(rng, sm.format(), 800, 6);
    const auto px = d.run(in, 0.8, 0.4, rng, 0, std::ref(hold));
    expect_pixels(sm, Model(), in, px);
    EXPECT_GT(hold.held, 1000u);
}

// The ecp5 shader keeps up with the slower of its two rates: a span every II clocks (the setup) and a pixel every
// clock (spec_stream), after the two latencies.
TEST(Shader, Ecp5SustainsASpanEveryIIClocksAndAPixelEveryClock) {
    const ConfigSetupModel sm(SetupConfig::ecp5);
    std::mt19937_64 rng(54);
    ShaderDriver<Vspec_shader> d;
    for (uint32_t max_len : {0u, 1u, 4u, 40u}) {
        auto in = shader_inputs(rng, sm.format(), 2000, max_len);
        size_t expect = 0;
        for (const auto& s : in) expect += s.l + 1;
        const uint64_t c0 = d.cycle();
        const auto px = d.run(in, 1.0, 1.0, rng);
        const uint64_t cycles = d.cycle() - c0;
        expect_pixels(sm, Model(), in, px);
        uint64_t bound = 0;   // the slower rate span by span
        for (const auto& sp : in) bound += std::max<uint64_t>(setup_params::II, sp.l + 1);
        EXPECT_LE(cycles, bound + setup_params::LATENCY + 300) << "max_len " << max_len;
    }
}

TEST(Shader, ResetDropsSpansInFlight) {
    const ConfigSetupModel sm(SetupConfig::ecp5);
    std::mt19937_64 rng(55);
    ShaderDriver<Vspec_shader> d;
    auto in = shader_inputs(rng, sm.format(), 50, 20);
    // half a run, then reset: nothing of it may come out afterwards
    d.top().m_axis_tready = 0;
    for (int i = 0; i < 30; ++i) {
        uint32_t w[setup_params::BEAT_W / 32];
        pack_setup_beat(in[i], w);
        for (int j = 0; j < setup_params::BEAT_W / 32; ++j) d.top().s_axis_tdata[j] = w[j];
        d.top().s_axis_tvalid = 1;
        d.step();
    }
    d.top().s_axis_tvalid = 0;
    d.reset();
    d.step();
    EXPECT_FALSE(d.top().m_axis_tvalid);
    const auto fresh = shader_inputs(rng, sm.format(), 100, 10);
    expect_pixels(sm, Model(), fresh, d.run(fresh, 1.0, 0.7, rng));
}

// The flags FIFO's corner: a descriptor reaches spec_stream in the very clock in which the only span in it
// hands over its last pixel. The new span's flags must come from its descriptor, not from the FIFO's memory
// (written at that same edge). The setup hands out descriptors II clocks apart, so the first span's length is
// swept (one more pixel, one clock later) until its last pixel leaves as the second descriptor arrives: then the
// second span's pixel follows the first span's last by spec_stream's latency.
TEST(Shader, FlagsWhenTheOnlySpanLeavesAsTheNextArrives) {
    const ConfigSetupModel sm(SetupConfig::ecp5);
    std::mt19937_64 rng(56);
    ShaderDriver<Vspec_shader> d;
    int met = 0;
    for (unsigned len = 0; len < 2 * setup_params::II + 8; ++len) {
        SetupInput a = random_case(rng, sm.format(), SpanKind::random, static_cast<unsigned>(rng() % 1024), 8);
        a.l = len;
        SetupInput b;
        do {
            b = random_case(rng, sm.format(), SpanKind(rng() % unsigned(SpanKind::count)),
                            static_cast<unsigned>(rng() % 1024), 8);
            b.l = 0;
        } while (sm.run(b).flags == sm.run(a).flags);
        std::vector<ShaderPixel> px;
        std::vector<uint64_t> when;
        auto clock = [&](const SetupInput* s) {   // one clock, the sink ready; true when s was taken
            const size_t had = px.size();
            const bool taken = d.clock(s, true, px);
            if (px.size() > had) when.push_back(d.cycle());
            return taken;
        };
        // first leave the first span's flags in both FIFO words the pair will use, so that a new span's flags
        // read from the memory instead of its descriptor differ from the right ones
        d.reset();
        while (!clock(&a)) {}
        while (!clock(&a)) {}
        const size_t na = size_t(len) + 1;
        for (int i = 0; i < 4000 && px.size() < 2 * na; ++i) clock(nullptr);
        ASSERT_EQ(px.size(), 2 * na);
        px.clear();
        when.clear();
        d.reset();
        while (!clock(&a)) {}
        while (!clock(&b)) {}
        for (int i = 0; i < 4000 && px.size() < na + 1; ++i) clock(nullptr);
        ASSERT_EQ(px.size(), na + 1) << "length " << len;
        expect_pixels(sm, Model(), {a, b}, px);
        if (HasFatalFailure()) {
            ADD_FAILURE() << "length " << len;
            return;
        }
        if (when[na] - when[na - 1] == uint64_t(spec_params::STREAM_LATENCY)) ++met;
    }
    EXPECT_GE(met, 1) << "the sweep of lengths must meet the corner";
}

// The up5k configuration (the small setup, spec_stream_seq; the iCEBreaker's shader): the same pixels and flags as
// the models under random stalls, the AXI4-Stream rules under backpressure, reset.
TEST(Shader, Up5kEqualsModelsUnderStalls) {
    const ConfigSetupModel sm(SetupConfig::up5k);
    const Model core(config_format("up5k"));
    std::mt19937_64 rng(57);
    ShaderDriver<Vspec_shader_up5k> d;
    OutputHolds hold;
    const double modes[][2] = {{1.0, 1.0}, {0.5, 0.5}, {1.0, 0.2}, {0.2, 0.05}};
    for (const auto& m : modes) {
        const auto in = shader_inputs(rng, sm.format(), 80, 40);
        expect_pixels(sm, core, in, d.run(in, m[0], m[1], rng, 0, std::ref(hold)));
    }
    EXPECT_GT(hold.held, 1000u);
    // reset with spans in flight: nothing of them comes out afterwards
    auto in = shader_inputs(rng, sm.format(), 6, 20);
    std::vector<ShaderPixel> px;
    for (int i = 0, sent = 0; i < 6000; ++i) {
        if (d.clock(sent < 6 ? &in[size_t(sent)] : nullptr, i % 3 == 0, px)) ++sent;
    }
    ASSERT_FALSE(px.empty());
    d.reset();
    d.step();
    EXPECT_FALSE(d.top().m_axis_tvalid);
    const auto fresh = shader_inputs(rng, sm.format(), 20, 10);
    expect_pixels(sm, core, fresh, d.run(fresh, 1.0, 0.7, rng));
}

// spec_stream_seq takes the next descriptor as soon as the last span's pixels have left its datapath, while
// the span's last pixel may still wait for the sink: the flags FIFO's push (the new span) and pop (the old
// span's last pixel) can meet in one clock. The sink holds the first span's last pixel until a release cycle
// swept around the clock at which the second span's descriptor arrives: the flags must stay each span's own.
TEST(Shader, Up5kFlagsWhenTheNextSpanArrivesAsTheLastPixelLeaves) {
    const ConfigSetupModel sm(SetupConfig::up5k);
    const Model core(config_format("up5k"));
    std::mt19937_64 rng(58);
    ShaderDriver<Vspec_shader_up5k> d;
    const int lat = config_format("up5k").stream_seq_latency();
    for (int trial = 0; trial < 4; ++trial) {
        SetupInput a = random_case(rng, sm.format(), SpanKind::random, static_cast<unsigned>(rng() % 1024), 8);
        a.l = 3;
        SetupInput b;
        do {
            b = random_case(rng, sm.format(), SpanKind(rng() % unsigned(SpanKind::count)),
                            static_cast<unsigned>(rng() % 1024), 8);
            b.l = 0;
        } while (sm.run(b).flags == sm.run(a).flags);
        // hold = 0: the sink always ready; else it holds a's last pixel until `hold` clocks after the start
        auto run = [&](uint64_t hold, std::vector<ShaderPixel>& px, std::vector<uint64_t>& when) {
            d.reset();
            const uint64_t c0 = d.cycle();
            int sent = 0;
            for (int i = 0; i < 20000 && px.size() < 5; ++i) {
                const bool ready = !(hold && px.size() == 3 && d.cycle() - c0 < hold);
                const size_t had = px.size();
                if (d.clock(sent == 0 ? &a : sent == 1 ? &b : nullptr, ready, px)) ++sent;
                if (px.size() > had) when.push_back(d.cycle() - c0);
            }
        };
        std::vector<ShaderPixel> px;
        std::vector<uint64_t> when;
        run(0, px, when);
        ASSERT_EQ(px.size(), 5u);
        expect_pixels(sm, core, {a, b}, px);
        const uint64_t arrive = when[4] - uint64_t(lat);   // b's descriptor reaches spec_stream_seq about here
        ASSERT_GT(arrive, when[3] + 4) << "b arrives after a has left: the test would not meet the corner";
        for (uint64_t hold = arrive - 4; hold <= arrive + 4; ++hold) {
            px.clear();
            when.clear();
            run(hold, px, when);
            ASSERT_EQ(px.size(), 5u) << "hold " << hold;
            expect_pixels(sm, core, {a, b}, px);
            if (HasFatalFailure()) {
                ADD_FAILURE() << "trial " << trial << ", a's last pixel held until " << hold;
                return;
            }
        }
    }
}
