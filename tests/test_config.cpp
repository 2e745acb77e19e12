// The configuration the generator describes is the RTL's: the latencies it writes into the headers
// (rom/spec_params.h, spec_format.h's formulas) are measured on the Verilated cores, and spec_unit in the up5k
// configuration (INTERP = 1; README publishes its synthesis figures) is held to its bit-exact model.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "Vspec_stream.h"
#include "Vspec_stream_up5k.h"
#include "Vspec_unit_up5k.h"
#include "analysis.h"
#include "spec_model.h"
#include "spec_params.h"
#include "stream_driver.h"
#include "unit_driver.h"

using namespace spec;

namespace {

// Cycles from a descriptor accepted by an idle spec_stream to its first pixel on m_axis.
template <class V>
int stream_first_pixel(StreamDriver<V>& d, const SpanRegs& r) {
    uint32_t w[kDescWords];
    pack_descriptor(r, w);
    V& t = d.top();
    for (int i = 0; i < kDescWords; ++i) t.s_axis_tdata[i] = w[i];
    t.m_axis_tready = 1;
    t.s_axis_tvalid = 0;
    t.eval();
    for (int i = 0; i < 4 && !t.s_axis_tready; ++i) d.step();  // tready rises the second cycle after a reset
    t.s_axis_tvalid = 1;
    t.eval();
    EXPECT_TRUE(t.s_axis_tready) << "an idle core takes a descriptor";
    d.step();  // accepted at this edge: cycle a
    t.s_axis_tvalid = 0;
    int at = 1;
    t.eval();
    while (!t.m_axis_tvalid && at < 200) {
        d.step();
        t.eval();
        ++at;
    }
    for (int i = 0; i < int(r.len) + 40; ++i) d.step();  // drain
    return at;
}

}  // namespace

TEST(ConfigLatency, StreamFirstPixelIsTheHeaders) {
    StreamDriver<Vspec_stream> d;
    for (uint32_t len : {0u, 5u}) {
        EXPECT_EQ(stream_first_pixel(d, SpanRegs{0x1234, 0, 0, 7, len}), spec_params::STREAM_LATENCY) << len;
        EXPECT_EQ(stream_first_pixel(d, SpanRegs{0x1234, 0, 0, 7, len}), Format().stream_latency()) << len;
    }
}

TEST(ConfigLatency, Up5kStreamFirstPixelIsTheFormats) {
    StreamDriver<Vspec_stream_up5k> d;
    EXPECT_EQ(stream_first_pixel(d, SpanRegs{0x1234, 0, 0, 7, 3}), config_format("up5k").stream_latency());
    EXPECT_NE(config_format("up5k").stream_latency(), Format().stream_latency()) << "INTERP adds two stages";
}

TEST(ConfigLatency, Up5kUnitFirstPixelIsTheFormats) {
    UnitDriverT<Vspec_unit_up5k> d;
    for (uint32_t len : {0u, 4u}) {
        d.write(SpanRegs{0x4000, 0, 0, 5, len});
        d.top().start = 1;
        d.step();
        int at = 1;
        std::vector<int> pulses;
        while (d.top().busy_o && at < 200) {
            if (d.top().valid_o) pulses.push_back(at);
            d.step();
            ++at;
        }
        ASSERT_EQ(pulses.size(), len + 1);
        for (size_t i = 0; i < pulses.size(); ++i) {
            EXPECT_EQ(pulses[i], config_format("up5k").unit_first_pixel() + 2 * int(i)) << "pixel " << i;
        }
    }
}

// spec_unit with INTERP = 1 equals the up5k model bit for bit on random spans, and keeps the per-n bound.
TEST(Up5kUnit, EqualsModelAndKeepsTheAccuracyBound) {
    const Model m(config_format("up5k"));
    UnitDriverT<Vspec_unit_up5k> d;
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 600; ++i) {
        SpanRegs r;
        r.n = static_cast<uint32_t>(rng() % 1024);
        r.c = static_cast<uint32_t>(rng() & 0xffff);
        r.len = static_cast<uint32_t>(rng() % 24);
        const double reach = std::min(M_PI, 6.0 * epicentre_end(r.n));
        r.zeta0 = m.quantize_angle(reach * u(rng));
        r.dzeta = m.quantize_angle(r.len ? (reach * u(rng) - m.angle_value(r.zeta0)) / r.len : 0.0);
        if (i % 16 == 0) {  // raw register contents, saturating angles included
            r.zeta0 = static_cast<int32_t>(rng());
            r.dzeta = static_cast<int32_t>(rng()) >> (rng() % 32);
        }
        ASSERT_EQ(d.span(r), m.span(r)) << "span " << i << " n=" << r.n << " l=" << r.len;
    }
    const ErrorTable& e = fig10_errors();
    const double lsb14 = std::ldexp(1.0, -14), lsb13 = std::ldexp(1.0, -13);
    for (unsigned n = 0; n < 1024; n += 3) {
        const double end = std::min(M_PI, 8.0 * epicentre_end(n));
        const SpanRegs r{0xffff, m.quantize_angle(end / 60), 0, n, 60};
        const auto out = d.span(r);
        ASSERT_EQ(out, m.span(r));
        const double c = m.out_value(r.c);
        size_t k = 0;
        for (int64_t a : m.angles(r)) {
            const double ang = m.angle_value(a);
            const double ref = c * std::pow(std::max(0.0, std::cos(ang)), double(n));
            const double err = std::fabs(m.out_value(out[k++]) - ref);
            if (ang <= epicentre_end(n)) ASSERT_LE(err, ref * (e.q[n] + 0.002) + lsb14) << n << " " << ang;
            else ASSERT_LE(err, c * (e.a[n] + 0.002) + lsb13) << n << " " << ang;
        }
    }
}
