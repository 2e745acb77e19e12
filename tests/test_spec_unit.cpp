// spec_unit through its ports: equal to the bit-exact model, within the double-precision bounds of
// Fig. 8/10, and every behaviour of the interface contract.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "Vspec_unit.h"
#include "analysis.h"
#include "spec_model.h"
#include "spec_params.h"
#include "unit_driver.h"

using namespace spec;

namespace {
double scale_of(unsigned n) { return std::sqrt(double(n) / k_of_n(n)); }

struct RandomSpan {
    SpanRegs regs;
    double c, zeta0, dzeta;  // the decimal values given (before quantization)
};

// A span around the highlight of n: angles inside [-pi, pi], mostly within a few epicentres.
RandomSpan random_span(std::mt19937_64& rng, const Model& m, unsigned n, uint32_t max_len) {
    RandomSpan s;
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    s.c = u01(rng) * 0.999999;
    // half of the spans stay near the epicentre, half reach well past the table's pi/2
    const double reach = std::min(M_PI, (rng() % 2 ? 3.0 : 9.0) * epicentre_end(n) + 0.05 * u01(rng));
    std::uniform_real_distribution<double> ang(-reach, reach);
    const uint32_t len = static_cast<uint32_t>(rng() % (max_len + 1));
    s.zeta0 = ang(rng);
    const double end = ang(rng);
    s.dzeta = len ? (end - s.zeta0) / len : 0.0;
    s.regs = SpanRegs{m.quantize_c(s.c), m.quantize_angle(s.dzeta), m.quantize_angle(s.zeta0), n, len};
    return s;
}
}  // namespace

TEST(SpecUnit, EqualsBitExactModelOnRandomSpans) {
    const Model m;
    UnitDriver d;
    std::mt19937_64 rng(11);
    size_t pixels = 0, spans = 0;
    for (int round = 0; round < 3; ++round) {
        for (unsigned n = 0; n < 1024; ++n) {  // every n visited, three times
            RandomSpan s = random_span(rng, m, n, round == 2 ? 200 : 24);
            auto px = d.span(s.regs);
            ASSERT_EQ(px, m.span(s.regs)) << "n=" << n << " len=" << s.regs.len;
            pixels += px.size();
            ++spans;
        }
    }
    // raw random register contents, including angles that saturate the accumulator
    for (int i = 0; i < 500; ++i) {
        SpanRegs r{static_cast<uint32_t>(rng() & 0xffff), static_cast<int32_t>(rng()) >> (rng() % 32),
                   static_cast<int32_t>(rng()), static_cast<uint32_t>(rng() % 1024),
                   static_cast<uint32_t>(rng() % 40)};
        ASSERT_EQ(d.span(r), m.span(r)) << i;
        ++spans;
    }
    RecordProperty("spans", std::to_string(spans));
    EXPECT_GT(pixels, 30000u);
}

TEST(SpecUnit, WithinDoublePrecisionBoundsForEveryN) {
    const Model m;
    const ErrorTable& e = fig10_errors();
    UnitDriver d;
    std::mt19937_64 rng(12);
    const double lsb14 = std::ldexp(1.0, -14), lsb13 = std::ldexp(1.0, -13);
    size_t inside = 0, outside = 0, zeros = 0;
    double worst_margin = 0;  // largest |err| / bound seen
    for (int round = 0; round < 2; ++round) {
        for (unsigned n = 0; n < 1024; ++n) {
            RandomSpan s = random_span(rng, m, n, 64);
            auto px = d.span(s.regs);
            ASSERT_EQ(px.size(), s.regs.len + 1u);
            for (size_t i = 0; i < px.size(); ++i) {
                const double ang = s.zeta0 + double(i) * s.dzeta;
                const double ref = s.c * std::pow(std::max(0.0, std::cos(ang)), double(n));
                const double out = m.out_value(px[i]);
                const double err = std::fabs(out - ref);
                double bound;
                if (std::fabs(ang) <= epicentre_end(n)) {
                    bound = ref * (e.q[n] + 0.002) + lsb14;
                    ++inside;
                } else {
                    bound = s.c * (e.a[n] + 0.002) + lsb13;
                    ++outside;
                }
                worst_margin = std::max(worst_margin, err / bound);
                ASSERT_LE(err, bound) << "n=" << n << " angle=" << ang << " out=" << out << " ref=" << ref;
                if (n > 0 && scale_of(n) * std::fabs(ang) >= M_PI / 2) {
                    ASSERT_EQ(px[i], 0u) << "past pi/2: n=" << n << " angle=" << ang;
                    ++zeros;
                }
            }
        }
    }
    EXPECT_GT(inside, 10000u);
    EXPECT_GT(outside, 10000u);
    EXPECT_GT(zeros, 1000u);
    RecordProperty("worst_error_over_bound", std::to_string(worst_margin));
}

TEST(SpecUnit, Fig11And12Run) {
    const Model m;
    UnitDriver d;
    // l = 3: the span of Fig. 12, three intervals between four pixels
    SpanRegs r{m.quantize_c(0.75), m.quantize_angle(0.1), m.quantize_angle(-0.15), 10, 3};
    d.write(r);
    std::string s28, s37, s36, s34, s35, busy, valid;
    d.observer = [&](uint64_t, const CtrlSignals& c) {
        s28 += c.s28 ? '1' : '0';
        s37 += c.s37 ? '1' : '0';
        s36 += c.s36 ? '1' : '0';
        s34 += c.s34 ? '1' : '0';
        s35 += c.s35_n ? '1' : '0';
        busy += c.busy ? '1' : '0';
        valid += c.valid ? '1' : '0';
    };
    d.top().start = 1;
    d.steps(24);
    // index 0 = the cycle after Start
    EXPECT_EQ(s37, "010101010000000000000000") << "four strobes on 37";
    EXPECT_EQ(s36, "001111111000000000000000") << "select 36 low for the first strobe, high for the rest";
    EXPECT_EQ(s34, "001010101000000000000000") << "a count pulse on 34 after each strobe";
    EXPECT_EQ(s35, "111111110111111111111111") << "borrow 35 on the fourth count pulse";
    EXPECT_EQ(s28, "111111111000000000000000") << "flip-flop 39 (28) until the borrow";
    EXPECT_EQ(valid, "000000000000001010101000") << "data valid 29: 37 delayed by the pipeline";
    EXPECT_EQ(busy, "111111111111111111111000") << "busy_o until the last pixel is out";
    // the decoder's one-hot output for n = 10 is 33 (cos^16)
    const CtrlSignals c = d.signals();
    EXPECT_TRUE(c.d33 && !c.d30 && !c.d31 && !c.d32);
}

TEST(SpecUnit, PixelTimingAndOnePulsePerPixel) {
    const Model m;
    UnitDriver d;
    for (uint32_t len : {0u, 1u, 2u, 7u, 100u}) {
        SpanRegs r{0x9000, m.quantize_angle(0.001), m.quantize_angle(-0.05), 100, len};
        d.write(r);
        d.top().start = 1;
        d.step();
        ASSERT_TRUE(d.top().busy_o) << "busy from the cycle after start";
        std::vector<uint32_t> px;
        std::vector<uint64_t> at;
        const uint64_t t0 = d.cycle() - 1;  // the start cycle
        bool prev_valid = false;
        while (d.top().busy_o) {
            ASSERT_FALSE(prev_valid && d.top().valid_o) << "valid_o pulses are one clock each";
            prev_valid = d.top().valid_o;
            if (d.top().valid_o) {
                px.push_back(d.top().intensity_o);
                at.push_back(d.cycle() - t0);
            }
            d.step();
            ASSERT_LT(d.cycle() - t0, 4u * len + 100);
        }
        ASSERT_EQ(px, m.span(r));
        // the latency the generator writes into rom/spec_params.h (and README, docs/interface.md) is the RTL's
        const uint64_t first = spec_params::UNIT_FIRST_PIXEL;
        for (size_t i = 0; i < at.size(); ++i) EXPECT_EQ(at[i], first + 2 * i) << "pixel " << i;
        EXPECT_EQ(d.cycle() - t0, first + 2 * len + 1) << "busy falls the cycle after the last pixel";
        EXPECT_FALSE(d.top().valid_o);
        // intensity_o holds the last pixel while idle
        d.steps(5);
        EXPECT_EQ(d.top().intensity_o, px.back());
        EXPECT_FALSE(d.top().busy_o);
    }
}

TEST(SpecUnit, StartWritesAndLoadsWhileBusyAreIgnored) {
    const Model m;
    UnitDriver d;
    std::mt19937_64 rng(13);
    for (int i = 0; i < 200; ++i) {
        SpanRegs r{static_cast<uint32_t>(rng() & 0xffff), m.quantize_angle(0.01 * (int(rng() % 21) - 10)),
                   m.quantize_angle(-0.5), static_cast<uint32_t>(rng() % 1024), static_cast<uint32_t>(rng() % 20)};
        d.write(r);
        d.top().start = 1;
        d.step();
        std::vector<uint32_t> px;
        while (d.top().busy_o) {
            if (d.top().valid_o) px.push_back(d.top().intensity_o);
            // hammer every input while busy
            Vspec_unit& t = d.top();
            t.start = rng() & 1;
            t.c_i = rng() & 0xffff; t.c_we = rng() & 1;
            t.dzeta_i = static_cast<uint32_t>(rng()); t.dzeta_we = rng() & 1;
            t.zeta0_i = static_cast<uint32_t>(rng()); t.zeta0_we = rng() & 1;
            t.n_i = rng() & 0x3ff; t.n_we = rng() & 1;
            t.len_i = rng() & 0xffff; t.len_load_n = rng() & 1;
            d.step();
        }
        ASSERT_EQ(px, m.span(r)) << i;
        // the registers still hold the span: a reload of the counter alone repeats it exactly
        d.top().len_i = r.len;
        d.top().len_load_n = 0;
        d.step();
        ASSERT_EQ(d.run(), m.span(r)) << "registers changed while busy, span " << i;
    }
}

TEST(SpecUnit, InitNReturnsToIdleAtOnce) {
    const Model m;
    UnitDriver d;
    for (int cut = 0; cut < 30; ++cut) {
        SpanRegs r{0xc000, m.quantize_angle(0.02), m.quantize_angle(-0.2), 7, 10};
        d.write(r);
        d.top().start = 1;
        d.step();
        d.steps(cut);
        d.top().init_n = 0;
        d.step();
        EXPECT_FALSE(d.top().busy_o) << cut;
        EXPECT_FALSE(d.top().valid_o) << cut;
        EXPECT_EQ(d.top().intensity_o, 0u);
        for (int i = 0; i < 40; ++i) {
            d.step();
            ASSERT_FALSE(d.top().valid_o) << "no valid_o after init_n, cut " << cut;
            ASSERT_FALSE(d.top().busy_o);
        }
        // registers cleared: a start now gives one pixel (l = 0) of C = 0
        ASSERT_EQ(d.run(), std::vector<uint32_t>{0u});
    }
}

TEST(SpecUnit, NZeroGivesCExactlyAndHighNUseK16) {
    const Model m;
    UnitDriver d;
    std::mt19937_64 rng(14);
    for (int i = 0; i < 50; ++i) {
        const uint32_t c = rng() & 0xffff;
        SpanRegs r{c, static_cast<int32_t>(rng()) >> 6, static_cast<int32_t>(rng()) >> 2, 0, 20};
        for (uint32_t p : d.span(r)) ASSERT_EQ(p, c);
    }
    // n = 1001..1023: the decoder selects cos^16, like 7..1000, and the error stays bounded
    for (unsigned n = 1001; n < 1024; ++n) {
        SpanRegs r{0xffff, m.quantize_angle(0.002), m.quantize_angle(-0.03), n, 30};
        d.write(r);
        EXPECT_TRUE(d.signals().d33) << n;
        auto px = d.run();
        for (size_t i = 0; i < px.size(); ++i) {
            const double ang = -0.03 + 0.002 * i;
            const double ref = m.out_value(0xffff) * std::pow(std::cos(ang), n);
            EXPECT_NEAR(m.out_value(px[i]), ref, 0.01) << n;
        }
    }
}

TEST(SpecUnit, AnglesOfEitherSign) {
    const Model m;
    UnitDriver d;
    for (unsigned n : {1u, 2u, 3u, 6u, 7u, 50u, 1000u}) {
        SpanRegs pos{0xffff, m.quantize_angle(0.01), m.quantize_angle(0.0), n, 150};
        SpanRegs neg{0xffff, m.quantize_angle(-0.01), m.quantize_angle(0.0), n, 150};
        EXPECT_EQ(d.span(pos), d.span(neg)) << n;
    }
}

TEST(SpecUnit, WritesInTheStartCycleLand) {
    const Model m;
    UnitDriver d;
    SpanRegs r{0x7000, m.quantize_angle(0.05), m.quantize_angle(-0.1), 20, 5};
    Vspec_unit& t = d.top();
    t.c_i = r.c; t.c_we = 1;
    t.dzeta_i = static_cast<uint32_t>(r.dzeta); t.dzeta_we = 1;
    t.zeta0_i = static_cast<uint32_t>(r.zeta0); t.zeta0_we = 1;
    t.n_i = r.n; t.n_we = 1;
    t.len_i = r.len; t.len_load_n = 0;
    t.start = 1;
    d.step();
    std::vector<uint32_t> px;
    while (t.busy_o) {
        if (t.valid_o) px.push_back(t.intensity_o);
        d.step();
    }
    EXPECT_EQ(px, m.span(r));
}
