// The reference designs' small shared modules (boards/common/) against their definitions and the model:
// isqrt, seq_mul, video_timing, compose, compose_seq, sync_fifo, light_gen.
#include <gtest/gtest.h>

#include <deque>
#include <random>

#include "Vcompose.h"
#include "Vcompose_seq.h"
#include "Vcompose_seq_hold.h"
#include "Visqrt.h"
#include "Vlight_gen.h"
#include "Vseq_mul.h"
#include "Vsync_fifo.h"
#include "Vsync_fifo_q0.h"
#include "Vsync_fifo_q1.h"
#include "Vvideo_timing.h"
#include "board_dut.h"
#include "board_model.h"
#include "board_quant.h"
#include "board_scene.h"

using namespace spec::board;

// isqrt.v (28-bit radicand, 2 result bits per clock): floor(sqrt(x)) in 7 clocks, for the corners and 20 000
// random radicands.
TEST(BoardIsqrt, FloorOfTheRootInSevenClocks) {
    BoardDut<Visqrt> d;
    d->rst_n = 0;
    d.tick();
    d->rst_n = 1;
    std::mt19937 rng(5);
    std::vector<uint32_t> xs = {0, 1, 2, 3, 4, 15, 16, 17, (1u << 28) - 1, (1u << 27), 16383u * 16383u,
                                16383u * 16383u - 1};
    for (int i = 0; i < 20000; ++i) xs.push_back(rng() & ((1u << 28) - 1));
    for (uint32_t x : xs) {
        d->x = x;
        d->start = 1;
        d.tick();
        d->start = 0;
        int c = 0;
        while (!d->done) {
            d.tick();
            ASSERT_LT(++c, 20);
        }
        EXPECT_EQ(c, 7);
        ASSERT_EQ(d->root, isqrt(x)) << x;
    }
}

// seq_mul.v (9 x 9 bits, 3 bits per clock): the product, every pair of one operand's corners and random.
TEST(BoardSeqMul, Products) {
    BoardDut<Vseq_mul> d;
    d->rst_n = 0;
    d.tick();
    d->rst_n = 1;
    std::mt19937 rng(9);
    for (int i = 0; i < 20000; ++i) {
        const uint32_t a = (i < 512) ? uint32_t(i) : rng() & 511u, b = (i < 512) ? 511u - uint32_t(i) : rng() & 511u;
        d->a = a;
        d->b = b;
        d->start = 1;
        d.tick();
        d->start = 0;
        int c = 0;
        while (!d->done) {
            d.tick();
            ASSERT_LT(++c, 10);
        }
        ASSERT_EQ(d->p, a * b) << a << " * " << b;
    }
}

// video_timing.v with the VESA 640 x 480 figures and a pixel every other clock: two whole frames counted from
// the outputs (sync widths, porches, polarity, total), and vsync switching together with hsync's leading edge.
TEST(BoardVideoTiming, VesaFiguresCountedFromTheOutputs) {
    BoardDut<Vvideo_timing> d;
    d->rst_n = 0;
    d->ce = 1;
    d.tick();
    d->rst_n = 1;
    const VideoMode m = video_mode("640x480");
    // reset puts the raster at (0, V_ACTIVE): one frame minus the active lines before line 0
    int hs_edges = 0, vs_rises = 0, de_px = 0, hs_px = 0, vs_lines_at_hs = 0;
    bool hs_prev = true, vs_prev = true;
    const int cycles = 2 * 2 * m.h_total() * m.v_total();
    for (int c = 0; c < cycles; ++c) {
        d->ce = (c & 1) == 0;
        d.tick();
        if (!d->ce) continue;   // outputs change only after ce cycles
        const bool hs_act = !d->hsync, vs_act = !d->vsync;   // negative syncs
        if (d->de) {
            ++de_px;
            ASSERT_LT(d->h, m.h_active);
            ASSERT_LT(d->v, m.v_active);
        }
        if (hs_act) ++hs_px;
        if (hs_act && hs_prev) {
            ++hs_edges;
            EXPECT_EQ(d->h, m.h_active + m.h_fp);
            if (vs_act) ++vs_lines_at_hs;
        }
        if (vs_act && vs_prev) {
            ++vs_rises;
            EXPECT_EQ(d->h, m.h_active + m.h_fp) << "vsync starts with hsync";
            EXPECT_EQ(d->v, m.v_active + m.v_fp - 1);
        }
        if (!vs_act && !vs_prev) EXPECT_EQ(d->h, m.h_active + m.h_fp) << "vsync ends with hsync";
        hs_prev = !hs_act;
        vs_prev = !vs_act;
    }
    EXPECT_EQ(de_px, 2 * m.h_active * m.v_active);
    EXPECT_EQ(hs_px, 2 * m.h_sync * m.v_total());
    EXPECT_EQ(hs_edges, 2 * m.v_total());
    EXPECT_EQ(vs_rises, 2);
    EXPECT_EQ(vs_lines_at_hs, 2 * m.v_sync);
}

// compose.v (4 bits a channel, the 640 x 480 objects) against board_model's compose on random terms and
// the corners (zero, saturation); three clocks of latency, x and last carried.
TEST(BoardCompose, MatchesModel) {
    BoardDut<Vcompose> d;
    d->rst_n = 0;
    d.tick();
    d->rst_n = 1;
    const Quant q = quantize(make_board_scene("640x480", 16));
    std::mt19937 rng(13);
    struct In {
        unsigned obj, x, dif, spc;
        bool last;
    };
    std::deque<In> pending;
    int checked = 0;
    for (int i = 0; i < 30000; ++i) {
        In in{unsigned(rng() % q.obj.size()), rng() & 1023u, (i % 7 == 0) ? 65535u : rng() & 65535u,
              (i % 5 == 0) ? 0u : (i % 11 == 0) ? 65535u : rng() & 65535u, (rng() & 1u) != 0};
        const bool valid = (rng() % 4) != 0;
        d->in_valid = valid;
        d->in_obj = in.obj;
        d->in_x = in.x;
        d->in_dif = in.dif;
        d->in_spc = in.spc;
        d->in_last = in.last;
        d.tick();
        if (valid) pending.push_back(in);
        if (d->out_valid) {
            ASSERT_FALSE(pending.empty());
            const In w = pending.front();
            pending.pop_front();
            const auto rgb = compose(q.obj[w.obj], w.dif, w.spc, 4);
            ASSERT_EQ(d->out_rgb, (rgb[0] << 8) | (rgb[1] << 4) | rgb[2]) << i;
            ASSERT_EQ(d->out_x, w.x);
            ASSERT_EQ(d->out_last, w.last);
            ++checked;
        }
        ASSERT_LE(pending.size(), size_t(3)) << "latency above 3 clocks";
    }
    EXPECT_GT(checked, 20000);
}

// compose_seq.v (the iCEBreaker's colour, one channel at a time) against the same model on random terms and
// the corners, under random stalls on both sides: every item once, in order, tags kept, bypass items (the
// frame buffer's line clears) passed through with rgb 0; output held while not taken. hold: HOLD = 1, the item
// is read at the input and taken in the clock its result is taken (never before, never after).
namespace {
template <class V>
void check_compose_seq(bool hold) {
    BoardDut<V> d;
    d->rst_n = 0;
    d.tick();
    d->rst_n = 1;
    const Quant q = quantize(make_board_scene("640x480", 16));
    std::mt19937 rng(17);
    struct In {
        bool bypass;
        unsigned tag, obj, dif, spc;
    };
    auto make = [&](int i) {
        return In{(rng() % 9) == 0, unsigned(rng() & 0x1ffffu), unsigned(rng() % q.obj.size()),
                  (i % 7 == 0) ? 65535u : rng() & 65535u, (i % 5 == 0) ? 0u : (i % 11 == 0) ? 65535u : rng() & 65535u};
    };
    std::deque<In> sent;
    In cur = make(0);
    bool cur_valid = false;
    int checked = 0, bypassed = 0, next = 1;
    unsigned held_rgb = 0, held_tag = 0;
    bool was_stalled = false;
    for (int i = 0; i < 120000; ++i) {
        if (!cur_valid && (rng() % 3) != 0) {
            cur = make(next++);
            cur_valid = true;
        }
        d->s_valid = cur_valid;
        d->s_bypass = cur.bypass;
        d->s_tag = cur.tag;
        d->s_obj = cur.obj;
        d->s_dif = cur.dif;
        d->s_spc = cur.spc;
        const bool ready = (rng() % 3) != 0;
        d->m_ready = ready;
        d->eval();
        const bool took = cur_valid && d->s_ready;
        const bool out = d->m_valid && ready;
        if (hold) ASSERT_EQ(took, out) << "HOLD: the item goes with its result " << i;
        if (took) sent.push_back(cur);
        if (d->m_valid && was_stalled) {
            ASSERT_EQ(d->m_rgb, held_rgb) << "output changed while stalled";
            ASSERT_EQ(d->m_tag, held_tag);
        }
        if (out) {
            ASSERT_FALSE(sent.empty());
            const In w = sent.front();
            sent.pop_front();
            ASSERT_EQ(d->m_tag, w.tag) << i;
            ASSERT_EQ(bool(d->m_bypass), w.bypass) << i;
            if (w.bypass) {
                ASSERT_EQ(d->m_rgb, 0u);
                ++bypassed;
            } else {
                const auto rgb = compose(q.obj[w.obj], w.dif, w.spc, 4);
                ASSERT_EQ(d->m_rgb, (rgb[0] << 8) | (rgb[1] << 4) | rgb[2]) << i;
                ++checked;
            }
        }
        was_stalled = d->m_valid && !ready;
        held_rgb = d->m_rgb;
        held_tag = d->m_tag;
        d.tick();
        if (took) cur_valid = false;
        ASSERT_LE(sent.size(), size_t(1)) << "one item in the module at a time";
    }
    EXPECT_GT(checked, hold ? 1000 : 3000);
    EXPECT_GT(bypassed, hold ? 100 : 300);
}
}  // namespace

TEST(BoardComposeSeq, MatchesModelUnderStalls) { check_compose_seq<Vcompose_seq>(false); }

// HOLD = 1 (the iCEBreaker's, with one multiplier bit a clock): the same results with no copy of the item.
TEST(BoardComposeSeq, HoldMatchesModelUnderStalls) { check_compose_seq<Vcompose_seq_hold>(true); }

// sync_fifo.v (8 deep + its output queue) under random valid/ready: nothing lost, duplicated or reordered;
// with both sides always ready, one item per clock (QUEUE = 3 or 0) or two in three clocks (QUEUE = 1);
// tvalid held until taken.
template <class Dut>
static void fifo_in_order(int max_cycles_at_full_rate) {
    for (double p : {1.0, 0.7, 0.3}) {
        BoardDut<Dut> d;
        d->rst_n = 0;
        d.tick();
        d->rst_n = 1;
        std::mt19937 rng(17);
        std::bernoulli_distribution offer(p), take(p);
        uint32_t next_in = 0, next_out = 0;
        int cycles = 0;
        while (next_out < 5000) {
            const bool v = offer(rng) && next_in < 5000;
            d->s_valid = v;
            d->s_data = next_in & 0xffffu;
            d->m_ready = take(rng);
            d->eval();
            const bool in = v && d->s_ready, out = d->m_valid && d->m_ready;
            if (out) ASSERT_EQ(d->m_data, next_out++ & 0xffffu);
            if (in) ++next_in;
            d.tick();
            ASSERT_LT(++cycles, 100000);
        }
        if (p == 1.0) EXPECT_LE(cycles, max_cycles_at_full_rate) << "items per clock";
    }
}

TEST(BoardSyncFifo, InOrderUnderRandomStalls) { fifo_in_order<Vsync_fifo>(5010); }

TEST(BoardSyncFifo, OneRegisterQueueInOrderUnderRandomStalls) { fifo_in_order<Vsync_fifo_q1>(7510); }

// QUEUE = 0 (the iCEBreaker's): the block RAM's read register is the head; one item a clock
TEST(BoardSyncFifo, NoQueueInOrderUnderRandomStalls) { fifo_in_order<Vsync_fifo_q0>(5010); }

// light_gen.v against board_model's light_q for every one of the 256 frames.
TEST(BoardLightGen, EveryFrameMatchesModel) {
    BoardDut<Vlight_gen> d;
    d->rst_n = 0;
    d.tick();
    d->rst_n = 1;
    const Quant q = quantize(make_board_scene("640x480", 16));
    for (unsigned f = 0; f < 256; ++f) {
        d->f = f;
        d->start = 1;
        d.tick();
        d->start = 0;
        int c = 0;
        while (d->busy) {
            d.tick();
            ASSERT_LT(++c, 200);
        }
        const LightQ L = light_q(q, f);
        EXPECT_EQ(int16_t(d->l_x), L.l[0]) << f;
        EXPECT_EQ(int16_t(d->l_y), L.l[1]) << f;
        EXPECT_EQ(int16_t(d->l_z), L.l[2]) << f;
        EXPECT_EQ(int16_t(d->h_x), L.h[0]) << f;
        EXPECT_EQ(int16_t(d->h_y), L.h[1]) << f;
        EXPECT_EQ(int16_t(d->h_z), L.h[2]) << f;
    }
}
