// The reference designs' shared RTL (boards/common/) against the C++ model (sim/board/), module by module:
// the span finder, the TMDS encoder and serializer.
#include <gtest/gtest.h>

#include <random>

#include "Vsphere_spans_fast.h"
#include "Vsphere_spans_small.h"
#include "Vtmds_encoder.h"
#include "Vtmds_serializer.h"
#include "board_dut.h"
#include "board_model.h"
#include "board_scene.h"
#include "tmds.h"

using namespace spec::board;

namespace {

// Runs sphere_spans for line y with the sink ready with probability p_ready; returns the sub-spans.
template <class V>
std::vector<SubSpan> rtl_line(BoardDut<V>& d, int y, double p_ready, std::mt19937& rng, uint64_t* cycles) {
    std::bernoulli_distribution ready(p_ready);
    std::vector<SubSpan> out;
    d->start = 1;
    d->y = unsigned(y);
    d->m_ready = 0;
    d.tick();
    d->start = 0;
    uint64_t c = 1;
    while (d->busy) {
        d->m_ready = ready(rng);
        d->eval();
        if (d->m_valid && d->m_ready) {
            SubSpan s;
            s.obj = d->m_obj;
            s.x0 = int(d->m_x0);
            s.l = d->m_l;
            for (int k = 0; k < 3; ++k) {
                s.n1[size_t(k)] = int16_t(uint16_t(d->m_n1 >> (16 * k)));
                s.n2[size_t(k)] = int16_t(uint16_t(d->m_n2 >> (16 * k)));
            }
            out.push_back(s);
        }
        d.tick();
        if (++c > 100000) throw std::runtime_error("sphere_spans: no end of line");
    }
    if (cycles) *cycles = c;
    return out;
}

template <class V>
void check_scene(const BoardScene& s, double p_ready, uint64_t max_cycles_allowed) {
    BoardDut<V> d;
    d->rst_n = 0;
    d.tick();
    d->rst_n = 1;
    std::mt19937 rng(7);
    uint64_t worst = 0;
    size_t spans = 0;
    for (int y = 0; y < s.mode.v_active; ++y) {
        uint64_t c = 0;
        const std::vector<SubSpan> got = rtl_line(d, y, p_ready, rng, &c);
        const std::vector<SubSpan> want = line_spans(s, y);
        ASSERT_EQ(got.size(), want.size()) << "line " << y;
        for (size_t i = 0; i < got.size(); ++i) {
            EXPECT_EQ(got[i].obj, want[i].obj) << "line " << y << " span " << i;
            EXPECT_EQ(got[i].x0, want[i].x0) << "line " << y << " span " << i;
            EXPECT_EQ(got[i].l, want[i].l) << "line " << y << " span " << i;
            EXPECT_EQ(got[i].n1, want[i].n1) << "line " << y << " span " << i;
            EXPECT_EQ(got[i].n2, want[i].n2) << "line " << y << " span " << i;
        }
        worst = std::max(worst, c);
        spans += got.size();
    }
    EXPECT_GT(spans, size_t(1000));
    if (max_cycles_allowed) EXPECT_LE(worst, max_cycles_allowed) << "clocks for the busiest line";
}

}  // namespace

// Every line of the 640 x 480 scene (16 split points per chord, the iCE40's arithmetic speed) equals the model
// sub-span for sub-span, with and without a sink that stalls; the busiest line fits the iCEBreaker's 1600 clocks
// with room for the shader.
TEST(SphereSpans, SmallMatchesModelEveryLine) {
    const BoardScene s = make_board_scene("640x480", 16);
    check_scene<Vsphere_spans_small>(s, 1.0, 1200);
    check_scene<Vsphere_spans_small>(s, 0.3, 0);
}

// The same for 1280 x 720 with 32 split points and the ECP5's single-cycle arithmetic.
TEST(SphereSpans, FastMatchesModelEveryLine) {
    const BoardScene s = make_board_scene("1280x720", 32);
    check_scene<Vsphere_spans_fast>(s, 1.0, 1200);
    check_scene<Vsphere_spans_fast>(s, 0.5, 0);
}
