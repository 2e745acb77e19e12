// Start (input 26) as in the patent: a span begins on Start's rising edge, and a Start without a new load
// of counter 5 runs the last loaded l again (docs/decisions.md, "Start and counter 5").
#include <gtest/gtest.h>

#include <vector>

#include "Vspec_unit.h"
#include "spec_model.h"
#include "spec_params.h"
#include "unit_driver.h"

using namespace spec;

namespace {

// Runs `cycles` clocks with Start held at `level` (the driver drops every input after each clock), collecting
// the valid_o pixels.
std::vector<uint32_t> hold_start(UnitDriver& d, bool level, int cycles) {
    std::vector<uint32_t> px;
    for (int i = 0; i < cycles; ++i) {
        d.top().start = level;
        d.top().eval();
        if (d.top().valid_o) px.push_back(d.top().intensity_o);
        d.step();
    }
    return px;
}

// A one-clock Start pulse, then the span's pixels until busy_o falls.
std::vector<uint32_t> pulse(UnitDriver& d) { return d.run(200000); }

}  // namespace

// The trap: l = 2 loaded, Start held high for 400 cycles gave 211 pixels when Start was a level.
TEST(SpecUnitStart, HeldHighBeginsExactlyOneSpan) {
    const Model m;
    UnitDriver d;
    const SpanRegs r{0xc000, m.quantize_angle(0.02), m.quantize_angle(-0.03), 10, 2};
    d.write(r);
    const auto px = hold_start(d, true, 400);
    EXPECT_EQ(px, m.span(r)) << "one span of l + 1 = 3 pixels, not one per level-high stretch";
    EXPECT_FALSE(d.top().busy_o);
    // lowering Start begins nothing; raising it again begins the next span (the same registers: the same pixels)
    EXPECT_TRUE(hold_start(d, false, 50).empty());
    EXPECT_EQ(hold_start(d, true, 100), m.span(r));
}

// After a span the patent's counter 5 sits at its maximum; a Start without a new load must not turn that into a
// span of 2^L_W pixels. The length register keeps the last loaded l, and every register keeps its value, so a
// bare Start repeats the last span exactly.
TEST(SpecUnitStart, WithoutANewLoadRepeatsTheLastLength) {
    const Model m;
    UnitDriver d;
    const SpanRegs r{0x8000, m.quantize_angle(0.01), m.quantize_angle(-0.02), 3, 2};
    ASSERT_EQ(d.span(r), m.span(r));
    EXPECT_EQ(pulse(d), m.span(r)) << "a Start without a load runs l = 2 again";
    EXPECT_EQ(pulse(d), m.span(r));
    // a new length alone (registers 1-4 keep theirs)
    d.top().len_i = 7;
    d.top().len_load_n = 0;
    d.step();
    SpanRegs r7 = r;
    r7.len = 7;
    EXPECT_EQ(pulse(d), m.span(r7));
    // after init_n every register is 0: l = 0, C = 0 -> one pixel of 0
    d.init();
    EXPECT_EQ(pulse(d), std::vector<uint32_t>{0u});
}

// Start held high across init_n does not begin a span: after reset Start must rise again.
TEST(SpecUnitStart, HeldAcrossInitNBeginsNothing) {
    const Model m;
    UnitDriver d;
    const SpanRegs r{0x9000, 0, 0, 1, 4};
    d.write(r);
    d.top().start = 1;
    d.top().init_n = 0;
    d.step();
    EXPECT_TRUE(hold_start(d, true, 100).empty());
    EXPECT_FALSE(d.top().busy_o);
    d.write(r);
    EXPECT_EQ(hold_start(d, false, 3).size(), 0u);
    EXPECT_EQ(hold_start(d, true, 100), m.span(r));
}

// A rising edge while busy is ignored, even if Start then stays high until the core is idle.
TEST(SpecUnitStart, RisingWhileBusyIsIgnored) {
    const Model m;
    UnitDriver d;
    const SpanRegs r{0x7000, m.quantize_angle(0.001), 0, 100, 5};
    d.write(r);
    d.top().start = 1;
    d.step();                                    // the span begins
    EXPECT_TRUE(hold_start(d, false, 4).empty());
    const auto px = hold_start(d, true, 300);    // rises at cycle 5 of the span, held long after it
    EXPECT_EQ(px, m.span(r)) << "the first span's pixels only";
    EXPECT_FALSE(d.top().busy_o);
}

// The latency the generator writes into the headers (spec_params::UNIT_FIRST_PIXEL) is the RTL's, for every l.
TEST(SpecUnitStart, FirstPixelLatencyIsTheHeaders) {
    const Model m;
    UnitDriver d;
    for (uint32_t len : {0u, 3u}) {
        d.write(SpanRegs{0x4000, 0, 0, 5, len});
        d.top().start = 1;
        d.step();
        int at = 1;
        while (!d.top().valid_o && at < 100) {
            d.step();
            ++at;
        }
        EXPECT_EQ(at, spec_params::UNIT_FIRST_PIXEL) << "l = " << len;
        while (d.top().busy_o) d.step();
    }
}
