// The Verilated-harness template (sim/rtl/harness.h) and the stream driver's end-of-stream checks, on a
// Verilated block and on a C++ stand-in for spec_stream that breaks the stream's contract on purpose.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "Vspec_counter.h"
#include "Vspec_unit.h"
#include "harness.h"
#include "spec_model.h"
#include "stream_driver.h"
#include "unit_driver.h"

using namespace spec;

TEST(Harness, TickCountsClocksAndResetUsesThePortAndLevel) {
    Harness<Vspec_counter> c(active_high<Vspec_counter>([](Vspec_counter& v) -> CData& { return v.rst; }));
    EXPECT_EQ(c.cycle(), 0u);
    c->load_n = 0;
    c->d = 7;
    c->count = 0;
    c.tick();
    EXPECT_EQ(c->q, 7);
    EXPECT_EQ(c.cycle(), 1u);
    c->load_n = 1;
    c.reset(3);
    EXPECT_EQ(c->q, 0) << "reset() drives rst high for the clocks";
    EXPECT_EQ(c->rst, 0) << "and leaves it inactive";
    EXPECT_EQ(c.cycle(), 4u);
    Harness<Vspec_counter> none;
    EXPECT_THROW(none.reset(), std::logic_error) << "no reset port given";
}

TEST(Harness, OpentraceWritesEveryEdgeAndRefusesAnUntracedModel) {
    const std::string vcd = ::testing::TempDir() + "/harness_" + std::to_string(::getpid()) + ".vcd";
    {
        UnitDriver d;
        d.steps(3);
        d.opentrace(vcd);   // opened after construction: from here on
        d.span(SpanRegs{0x8000, 0, 0, 1, 2});
    }
    std::ifstream in(vcd);
    ASSERT_TRUE(in.good());
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string text = ss.str();
    EXPECT_NE(text.find("$var"), std::string::npos);
    EXPECT_NE(text.find("busy_o"), std::string::npos);
    size_t stamps = 0;
    for (size_t p = 0; (p = text.find("\n#", p)) != std::string::npos; ++p) ++stamps;
    EXPECT_GT(stamps, 30u) << "two timestamps per clock of the span";
    std::remove(vcd.c_str());

    Harness<Vspec_counter> c;
    EXPECT_THROW(c.opentrace(vcd), std::logic_error) << "Vspec_counter is Verilated without TRACE";
    UnitDriver d;
    EXPECT_THROW(d.opentrace("/nonexistent-dir/x.vcd"), std::runtime_error);
}

namespace {
// A C++ stand-in with spec_stream's ports: every descriptor gives l + 1 pixels (value = pixel index) with
// tlast on the last, one per clock, and then `extra` more pixels, or tlast on the wrong pixel.
struct FakeStream {
    FakeStream(VerilatedContext*, const char*) {}
    CData clk = 0, rst_n = 1, s_axis_tvalid = 0, s_axis_tready = 1, m_axis_tvalid = 0, m_axis_tready = 0,
          m_axis_tlast = 0, m_axis_tkeep = 1;   // one lane: tkeep always 1
    VlWide<4> s_axis_tdata;
    SData m_axis_tdata = 0;
    static int extra, bad_last_at;
    void eval() {
        if (clk && !prev_clk_) {   // rising edge
            if (m_axis_tvalid && m_axis_tready) m_axis_tvalid = 0;
            if (s_axis_tvalid && s_axis_tready) {
                left_ = int(s_axis_tdata[1] & 0xffff) + 1 + extra;
                extra_left_ = extra;
                index_ = 0;
            }
            if (!m_axis_tvalid && left_ > 0) {
                m_axis_tvalid = 1;
                m_axis_tdata = SData(index_);
                --left_;
                m_axis_tlast = (left_ == extra_left_) || (index_ == bad_last_at);
                if (left_ < extra_left_) extra_left_ = left_;
                ++index_;
            }
            s_axis_tready = left_ == 0;
        }
        prev_clk_ = clk;
    }
    void final() {}

private:
    CData prev_clk_ = 0;
    int left_ = 0, extra_left_ = 0, index_ = 0;
};
int FakeStream::extra = 0;
int FakeStream::bad_last_at = -1;
}  // namespace

TEST(StreamDriver, FailsOnTrailingPixelsAndMisplacedTlast) {
    std::mt19937_64 rng(1);
    const std::vector<SpanRegs> spans{SpanRegs{0, 0, 0, 0, 3}};
    FakeStream::extra = 0;
    FakeStream::bad_last_at = -1;
    {
        StreamDriver<FakeStream> d;
        const auto px = d.run(spans, Stalls{}, rng);
        ASSERT_EQ(px.size(), 4u) << "the stand-in itself is right";
        EXPECT_TRUE(px[3].last);
    }
    FakeStream::extra = 1;   // one pixel after the span's last
    {
        StreamDriver<FakeStream> d;
        EXPECT_THROW(d.run(spans, Stalls{}, rng), StreamError);
    }
    FakeStream::extra = 0;
    FakeStream::bad_last_at = 1;   // tlast in the middle of the span
    {
        StreamDriver<FakeStream> d;
        EXPECT_THROW(d.run(spans, Stalls{}, rng), StreamError);
    }
    FakeStream::bad_last_at = -1;
}
