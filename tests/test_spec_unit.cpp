// spec_unit through its ports: equal to the bit-exact model, within the double-precision bounds of
// Fig. 8/10, and every behaviour of the interface contract.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "Vspec_unit.h"
#include "analysis.h"
#include "common.h"
#include "spec_model.h"
#include "spec_params.h"
#include "unit_driver.h"

using namespace spec;
using namespace spec::test;

namespace {
double scale_of(unsigned n) { return std::sqrt(double(n) / k_of_n(n)); }

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

namespace {
// Every n twice, random spans around the highlight (seed 12) through `core`, each pixel against the double-precision
// bound of Fig. 8/10 (inside the epicentre C cos^n (q(n) + 0.2 %) + 2^-14, outside C (a(n) + 0.2 %) + 2^-13),
// and 0 exactly once the scaled angle reaches pi/2.
struct BoundSweep {
    BoundRatios worst;   // tests/common.h
    size_t inside = 0, outside = 0, zeros = 0;
    size_t over_bound = 0, nonzero_past = 0, wrong_count = 0;
    std::string first;   // the first violation
};
BoundSweep sweep_bounds(SpanCore& core) {
    const Model m;
    const ErrorTable& e = fig10_errors();
    std::mt19937_64 rng(12);
    const double lsb14 = std::ldexp(1.0, -14), lsb13 = std::ldexp(1.0, -13);
    BoundSweep r;
    for (int round = 0; round < 2; ++round) {
        for (unsigned n = 0; n < 1024; ++n) {
            RandomSpan s = random_span(rng, m, n, 64);
            auto px = core.span(s.regs);
            if (px.size() != s.regs.len + 1u) {
                ++r.wrong_count;
                continue;
            }
            const auto reg8 = m.angles(s.regs);
            for (size_t i = 0; i < px.size(); ++i) {
                const double ang = s.zeta0 + double(i) * s.dzeta;
                const double ref = s.c * std::pow(std::max(0.0, std::cos(ang)), double(n));
                const double out = m.out_value(px[i]);
                const double err = std::fabs(out - ref);
                const bool in = std::fabs(ang) <= epicentre_end(n);
                const double bound = in ? ref * (e.q[n] + 0.002) + lsb14 : s.c * (e.a[n] + 0.002) + lsb13;
                (in ? r.inside : r.outside) += 1;
                r.worst.add(m, s.regs, reg8[i], px[i], ref, bound, s.c, ang);
                if (err > bound && r.over_bound++ == 0) {
                    r.first = "n=" + std::to_string(n) + " angle=" + std::to_string(ang) + " out=" + std::to_string(out) +
                              " ref=" + std::to_string(ref);
                }
                if (n > 0 && scale_of(n) * std::fabs(ang) >= M_PI / 2) {
                    ++r.zeros;
                    if (px[i] != 0) ++r.nonzero_past;
                }
            }
        }
    }
    return r;
}
constexpr double kUnitErrorLimit = 0.95, kUnitFixedLimit = 0.45;   // docs/verification.md
}  // namespace

TEST(SpecUnit, WithinDoublePrecisionBoundsForEveryN) {
    UnitDriver d;
    const BoundSweep r = sweep_bounds(d);
    ASSERT_EQ(r.wrong_count, 0u);
    ASSERT_EQ(r.over_bound, 0u) << "first: " << r.first;
    ASSERT_EQ(r.nonzero_past, 0u) << "past pi/2 the core outputs 0";
    EXPECT_GT(r.inside, 10000u);
    EXPECT_GT(r.outside, 10000u);
    EXPECT_GT(r.zeros, 1000u);
    const BoundRatios& worst = r.worst;
    RecordProperty("worst_error_over_bound", std::to_string(worst.error_over_bound));
    RecordProperty("worst_fixed_point_over_slack", std::to_string(worst.fixed_over_slack));
    // asserted with the margins of tests/common.h; the measured values are docs/verification.md's
    EXPECT_LE(worst.error_over_bound, kUnitErrorLimit);
    EXPECT_LE(worst.fixed_over_slack, kUnitFixedLimit) << "fixed-point error grew (worst at n = " << worst.fixed_n << ")";
    EXPECT_GE(worst.fixed_over_slack, 0.25) << "the measurement itself changed: re-measure and document";
    expect_documented_ratios("SpecUnit.WithinDoublePrecisionBoundsForEveryN", worst, kUnitErrorLimit, kUnitFixedLimit);
}

// Why the fixed-point ratio is asserted: the bit-exact model with a ROM 12 of half the positions (2^11 per table),
// twice today's fixed-point error, stays inside every pixel's bound - the old test's only assertion - but fails
// the fixed-point ratio's limit. Its numbers are docs/verification.md's row "ROM 12 of 2048 positions".
TEST(SpecUnit, TwiceTheFixedPointErrorPassesTheBoundButNotTheRatio) {
    Format coarse;
    coarse.tbl_aw = 11;
    const Model m(coarse);
    ModelCore core(m);
    const BoundSweep r = sweep_bounds(core);
    EXPECT_EQ(r.over_bound, 0u) << "the per-pixel bound lets it through: " << r.first;
    EXPECT_GT(r.worst.fixed_over_slack, 1.8 * 0.362) << "about twice today's fixed-point error";
    EXPECT_GT(r.worst.fixed_over_slack, kUnitFixedLimit) << "the asserted ratio catches it";
    expect_documented_ratios("model with a ROM 12 of 2048 positions", r.worst, kUnitErrorLimit, kUnitFixedLimit);
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

// init_n clears every register the interface loads (docs/interface.md), seen through the pixels: registers 1-4
// and counter 5 (with its length) get non-zero values, init_n pulses, then every one but the register under test
// is written again and Start runs a span: its pixels must be those of a span with that register 0. Each choice
// of values makes the output depend on the register under test (C = 0 gives zeros whatever else holds; a step,
// a start angle or an exponent left over changes the pixels; a length left over changes their number).
TEST(SpecUnit, InitNClearsEveryRegisterSeenThroughThePixels) {
    const Model m;
    UnitDriver d;
    const SpanRegs full{m.quantize_c(0.9), m.quantize_angle(0.031), m.quantize_angle(-0.4), 10, 9};
    enum Reg { kC, kDzeta, kZeta0, kN, kLen };
    const char* names[] = {"C (register 1)", "dzeta (register 2)", "zeta0 (register 3)", "n (register 4)",
                           "l (counter 5 / length)"};
    for (int reg = kC; reg <= kLen; ++reg) {
        for (int cut : {-1, 0, 3, 12}) {   // init_n when idle (-1) or `cut` cycles into a span
            d.write(full);
            if (cut >= 0) {
                d.top().start = 1;
                d.step();
                d.steps(cut);
            } else {
                ASSERT_EQ(d.run(), m.span(full)) << "the values are loaded";
            }
            d.init();
            ASSERT_FALSE(d.top().busy_o);
            // write all but `reg`; the counter is loaded unless it is the one under test
            Vspec_unit& t = d.top();
            t.c_i = full.c;
            t.c_we = reg != kC;
            t.dzeta_i = static_cast<uint32_t>(full.dzeta);
            t.dzeta_we = reg != kDzeta;
            t.zeta0_i = static_cast<uint32_t>(full.zeta0);
            t.zeta0_we = reg != kZeta0;
            t.n_i = full.n;
            t.n_we = reg != kN;
            t.len_i = full.len;
            t.len_load_n = reg == kLen;
            d.step();
            SpanRegs cleared = full;
            if (reg == kC) cleared.c = 0;
            if (reg == kDzeta) cleared.dzeta = 0;
            if (reg == kZeta0) cleared.zeta0 = 0;
            if (reg == kN) cleared.n = 0;
            if (reg == kLen) cleared.len = 0;
            const auto want = m.span(cleared);
            ASSERT_NE(want, m.span(full)) << names[reg] << ": the choice of values shows nothing";
            ASSERT_EQ(d.run(4 * 65536), want) << names[reg] << " not cleared by init_n (cut " << cut << ")";
        }
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
