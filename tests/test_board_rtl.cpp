// The reference designs' shared RTL (boards/common/) against the C++ model (sim/board/), module by module:
// the span finder, the TMDS encoder and serializer.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <random>

#include "Vsphere_spans_fast.h"
#include "Vsphere_spans_serial.h"
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
    bool stalled = false;                // m_valid without m_ready last clock: the beat must not change
    std::array<uint64_t, 5> held{};
    while (d->busy) {
        d->m_ready = ready(rng);
        d->eval();
        const std::array<uint64_t, 5> beat{d->m_obj, d->m_x0, d->m_l, d->m_n1, d->m_n2};
        if (d->m_valid && stalled && beat != held)
            throw std::runtime_error("sphere_spans: the beat changed while stalled");
        stalled = d->m_valid && !d->m_ready;
        held = beat;
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
    ::testing::Test::RecordProperty("busiest_line_clocks", int(worst));
    if (max_cycles_allowed) EXPECT_LE(worst, max_cycles_allowed) << "clocks for the busiest line";
}

}  // namespace

// Every line of the 640 x 480 scene (16 split points per chord, the iCE40's arithmetic speed) equals the model
// sub-span for sub-span, with and without a sink that stalls; the busiest line fits the iCEBreaker's 1600 clocks
// with room for the shader (one bit per clock in the multiplier and the square root).
TEST(SphereSpans, SmallMatchesModelEveryLine) {
    const BoardScene s = make_board_scene("640x480", 16);
    check_scene<Vsphere_spans_small>(s, 1.0, 1200);
    check_scene<Vsphere_spans_small>(s, 0.3, 0);
}

// SERIAL = 1 (the iCEBreaker's: one token in the stages at a time, the stages read x0, DY, p, DX and W2 from stage
// A1's registers): the same sub-spans on every line, with and without a stalling sink. Slower than the
// overlapped stages (2312 clocks for the busiest line here, 1200 overlapped); the frame buffer designs do not race
// the beam, and their shader takes a few thousand clocks for each sub-span.
TEST(SphereSpans, SerialMatchesModelEveryLine) {
    const BoardScene s = make_board_scene("640x480", 16);
    check_scene<Vsphere_spans_serial>(s, 1.0, 2400);
    check_scene<Vsphere_spans_serial>(s, 0.3, 0);
}

// The same for 1280 x 720 with 32 split points and the ECP5's 720p arithmetic (single-cycle products, two root
// bits per clock): the busiest line within 1200 of the 1650 clocks.
TEST(SphereSpans, FastMatchesModelEveryLine) {
    const BoardScene s = make_board_scene("1280x720", 32);
    check_scene<Vsphere_spans_fast>(s, 1.0, 1200);
    check_scene<Vsphere_spans_fast>(s, 0.5, 0);
}

// tmds_encoder.v against the C++ encoder on a long random sequence of data and control periods (every byte
// at every reachable disparity), and the decoder inverts it; the running disparity of the characters stays
// within [-8, 8] (the DVI 1.0 encoder's bound) and the encoder starts from it again after control periods.
TEST(TmdsEncoder, MatchesModelAndDecodes) {
    BoardDut<Vtmds_encoder> d;
    d->rst_n = 0;
    d->ce = 1;
    d.tick();
    d->rst_n = 1;
    TmdsEncoder model;
    std::mt19937 rng(3);
    int disparity = 0, worst = 0;
    uint64_t data_chars = 0;
    for (int i = 0; i < 200000; ++i) {
        const bool de = (i % 1000) < 900;    // data periods with control periods between
        const unsigned c = rng() & 3u;
        const uint8_t v = (i < 256 * 17) ? uint8_t(i) : uint8_t(rng());
        d->de = de;
        d->c = c;
        d->d = v;
        d.tick();
        const uint32_t want = model.encode(de, c, v);
        ASSERT_EQ(d->q, want) << "character " << i;
        const TmdsChar back = tmds_decode(want);
        ASSERT_TRUE(back.valid) << i;
        if (de) {
            ASSERT_FALSE(back.is_control) << i;
            ASSERT_EQ(back.d, v) << i;
            disparity += 2 * __builtin_popcount(want) - 10;
            worst = std::max(worst, std::abs(disparity));
            ASSERT_EQ(disparity, model.disparity()) << i;
            ++data_chars;
        } else {
            ASSERT_TRUE(back.is_control) << i;
            ASSERT_EQ(back.c, c) << i;
            disparity = 0;
        }
    }
    EXPECT_LE(worst, 8);
    EXPECT_GE(worst, 6);
    EXPECT_GT(data_chars, 150000u);
}

// A character that is neither a control character nor any byte's encoding is reported invalid.
TEST(TmdsDecode, RejectsWhatNoEncoderMakes) {
    int invalid = 0;
    for (uint32_t q = 0; q < 1024; ++q) invalid += !tmds_decode(q).valid;
    EXPECT_GT(invalid, 0);
    EXPECT_LT(invalid, 1024 - 256);
}

namespace {
// tmds_serializer with the pixel domain driven from here, locked 1:5 as the PLL makes them: chars change with
// a toggle every 5 bit clocks (on the bit clock edge `phase`), the pairs read back into characters.
struct SerRun {
    std::vector<uint32_t> sent[3], got[3];
    bool out_of_step = false;
};
SerRun run_serializer(int phase, int pixels, int skip_at) {
    BoardDut<Vtmds_serializer> d;
    d->rst_n = 0;
    d.tick();
    d.tick();
    d->rst_n = 1;
    std::mt19937 rng(11);
    SerRun r;
    bool tgl = false;
    std::vector<uint8_t> bits[4];
    for (int c = 0; c < pixels * 5; ++c) {
        if (c % 5 == phase && c / 5 != skip_at) {
            uint32_t ch[3];
            for (int k = 0; k < 3; ++k) ch[k] = rng() & 0x3ffu;
            d->chars = ch[0] | (ch[1] << 10) | (uint32_t(ch[2]) << 20);
            tgl = !tgl;
            d->load_tgl = tgl;
            for (int k = 0; k < 3; ++k) r.sent[k].push_back(ch[k]);
        }
        d.tick();
        for (int k = 0; k < 4; ++k) {
            bits[k].push_back((d->pairs >> (2 * k)) & 1u);
            bits[k].push_back((d->pairs >> (2 * k + 1)) & 1u);
        }
    }
    r.out_of_step = d->out_of_step;
    // characters start where the clock lane's ones start (0000011111: five ones first)
    size_t start = 1;
    while (start < bits[3].size() && !(bits[3][start] && !bits[3][start - 1])) ++start;
    for (int k = 0; k < 3; ++k) {
        std::vector<uint8_t> b(bits[k].begin() + long(start), bits[k].end());
        r.got[k] = to_chars(b, 0);
    }
    return r;
}
}  // namespace

// Every character arrives, in order, whatever the phase of the pixel clock against the bit clock; the clock
// lane sends 0000011111 per pixel; a toggle that does not come when due raises out_of_step.
TEST(TmdsSerializer, SendsEveryCharacterInOrderAtAnyPhase) {
    for (int phase = 0; phase < 5; ++phase) {
        const SerRun r = run_serializer(phase, 400, -1);
        EXPECT_FALSE(r.out_of_step) << phase;
        for (int k = 0; k < 3; ++k) {
            ASSERT_GE(r.got[k].size(), size_t(390)) << phase;
            // the first characters sent before the serializer found its phase may be lost; then every one
            const auto it = std::search(r.sent[k].begin(), r.sent[k].end(), r.got[k].begin(), r.got[k].begin() + 300);
            EXPECT_TRUE(it != r.sent[k].end()) << "lane " << k << " phase " << phase;
            EXPECT_LE(it - r.sent[k].begin(), 2) << "lane " << k << " phase " << phase;
        }
    }
    EXPECT_TRUE(run_serializer(2, 400, 200).out_of_step);
}
