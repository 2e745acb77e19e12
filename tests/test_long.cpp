// test_long.cpp - make test-long (docs/verification.md): millions of random pixels through the Verilated
// spec_stream, spec_stream_seq and spec_unit against the bit-exact model, with random stalls on both sides,
// resets in the middle of spans, back-to-back spans and inputs that must be ignored. Not part of make test.
//
// SPEC_LONG_PIXELS (default 10000000; make test-long passes 10^8) pixels through each core in the patent's configuration, a tenth of
// that through spec_stream's up5k configuration, both cores in tuned mode, and each core in pow mode (spec_unit,
// spec_stream with LANES = 1 and 4 packed, the up5k configuration's with 2 packed, spec_stream_seq: docs/pow.md);
// SPEC_LONG_SEED (default 1) picks the run.
// Each test prints how many pixels it checked; a mismatch stops it with the span, pixel and cycle.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <algorithm>
#include <chrono>
#include <deque>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "Vspec_stream.h"
#include "Vspec_stream_seq.h"
#include "Vspec_stream_seq_tuned.h"
#include "Vspec_stream_seq_up5k.h"
#include "Vspec_stream_l2p_up5k.h"
#include "Vspec_stream_l4.h"
#include "Vspec_stream_l4p.h"
#include "Vspec_stream_pow.h"
#include "Vspec_stream_pow_l2p_up5k.h"
#include "Vspec_stream_pow_l4p.h"
#include "Vspec_stream_seq_pow.h"
#include "Vspec_stream_tuned.h"
#include "Vspec_stream_up5k.h"
#include "Vspec_unit.h"
#include "Vspec_unit_pow.h"
#include "Vspec_unit_tuned.h"
#include "analysis.h"
#include "cli.h"
#include "common.h"
#include "spec_model.h"
#include "stream_driver.h"
#include "unit_driver.h"

using namespace spec;
using spec::test::random_stream_span;

namespace {
const uint64_t kPixels = spec::test::env_u64("SPEC_LONG_PIXELS", 10000000);
const uint64_t kSeed = spec::test::env_u64("SPEC_LONG_SEED", 1);


// What each run checked, for SPEC_LONG_JSON (make test-long writes docs/data/test_long.json, the table of
// docs/verification.md through scripts/docgen.py).
struct RunRow {
    std::string core;
    uint64_t pixels, spans, cycles;
    std::string events, other;
};
std::vector<RunRow>& rows() {
    static std::vector<RunRow> r;
    return r;
}
std::string count(uint64_t v, const char* what) { return std::to_string(v) + " " + what; }

class ReportOnExit : public ::testing::Environment {
public:
    void SetUp() override { t0_ = std::chrono::steady_clock::now(); }
    void TearDown() override {
        const char* path = std::getenv("SPEC_LONG_JSON");
        if (!path || !*path) return;
        if (!::testing::UnitTest::GetInstance()->Passed()) {
            std::fprintf(stderr, "spec_long: a run failed, %s not written\n", path);
            return;
        }
        std::FILE* f = std::fopen(path, "w");
        if (!f) {
            std::fprintf(stderr, "spec_long: cannot write %s\n", path);
            return;
        }
        const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
        std::fprintf(f, "{\n \"seed\": %llu,\n \"pixels\": %llu,\n \"seconds\": %.0f,\n \"runs\": [",
                     (unsigned long long)kSeed, (unsigned long long)kPixels, secs);
        for (size_t i = 0; i < rows().size(); ++i) {
            const RunRow& r = rows()[i];
            std::fprintf(f, "%s\n  {\"core\": \"%s\", \"pixels\": %llu, \"spans\": %llu, \"cycles\": %llu, "
                         "\"events\": \"%s\", \"other\": \"%s\"}", i ? "," : "", r.core.c_str(),
                         (unsigned long long)r.pixels, (unsigned long long)r.spans, (unsigned long long)r.cycles,
                         r.events.c_str(), r.other.c_str());
        }
        std::fprintf(f, "\n ]\n}\n");
        std::fclose(f);
    }

private:
    std::chrono::steady_clock::time_point t0_;
};
::testing::Environment* const kReport = ::testing::AddGlobalTestEnvironment(new ReportOnExit);

struct Expected {
    uint32_t value;
    bool last;
    uint64_t span;
    uint32_t index;
};
}  // namespace

// spec_stream: an AXI source that holds each descriptor until it is taken; every 4096 cycles a new regime of
// per-cycle probabilities for the source offering and the sink being ready (1/1, 1/0.9, 0.9/1, 0.5/0.5,
// 1/0.1, 0.2/1, 0.97/0.97); a reset at a random point about 40 times a run. Every pixel and tlast is checked against the model in order; after a reset the
// pixels of spans accepted before it must not appear. AXI rules are checked each cycle.
// LANES > 1 (issue 14): each beat's kept slots are checked in order against the model; PACK = 0: a span's
// last pixel ends its beat and tlast is set exactly there, PACK = 1: tlast exactly on beats that end a span.
template <class V, int L = 1, bool P = false>
void stream_run(const char* name, const Model& m, uint64_t pixels, uint64_t seed) {
    StreamDriver<V, L, P> d;
    auto& t = d.top();
    std::mt19937_64 rng(seed);
    std::deque<Expected> want;
    uint64_t checked = 0, spans_in = 0, resets = 0, cycles = 0, lost_by_reset = 0, idle_ready = 0;
    bool offering = false;
    SpanRegs cur;
    bool prev_stalled = false;
    uint64_t prev_data = 0;
    unsigned prev_keep = 0;
    bool prev_last = false;
    const uint64_t slot_mask = (uint64_t(1) << spec_params::OUT_W) - 1;
    double p_ready = 1.0, p_offer = 1.0;
    const uint64_t reset_gap = std::max<uint64_t>(2000, pixels / 25);   // a reset every ~reset_gap cycles
    uint64_t next_reset = reset_gap / 4 + rng() % reset_gap;
    while (checked < pixels) {
        ++cycles;
        if (cycles % 4096 == 0) {   // a new stall regime now and then
            static const double regimes[][2] = {{1, 1}, {1, 0.9}, {0.9, 1}, {0.5, 0.5}, {1, 0.1}, {0.2, 1}, {0.97, 0.97}};
            const auto& g = regimes[rng() % 7];
            p_offer = g[0];
            p_ready = g[1];
        }
        const bool reset_now = cycles == next_reset;
        if (!offering && std::bernoulli_distribution(p_offer)(rng)) {
            cur = random_stream_span(rng, m, rng() % 4096 == 0 ? 65535 : rng() % 8 == 0 ? 400 : 24);
            offering = true;
        }
        t.s_axis_tvalid = offering;
        if (offering) {
            uint32_t w[kDescWords];
            pack_descriptor(cur, w);
            for (int i = 0; i < kDescWords; ++i) t.s_axis_tdata[i] = w[i];
        }
        t.m_axis_tready = std::bernoulli_distribution(p_ready)(rng);
        t.rst_n = !reset_now;
        t.eval();
        // AXI4-Stream source rules on the pixel side
        if (prev_stalled) {
            ASSERT_TRUE(t.m_axis_tvalid) << "tvalid dropped before tready, cycle " << d.cycle();
            ASSERT_EQ(uint64_t(t.m_axis_tdata), prev_data) << "tdata changed while stalled, cycle " << d.cycle();
            ASSERT_EQ(unsigned(t.m_axis_tkeep), prev_keep) << "tkeep changed while stalled, cycle " << d.cycle();
            ASSERT_EQ(t.m_axis_tlast != 0, prev_last) << "tlast changed while stalled, cycle " << d.cycle();
        }
        const bool in_fire = t.s_axis_tvalid && t.s_axis_tready && !reset_now;
        const bool out_fire = t.m_axis_tvalid && t.m_axis_tready;
        if (out_fire) {
            const unsigned keep = unsigned(t.m_axis_tkeep);
            const bool tlast = t.m_axis_tlast != 0;
            int kept = 0;
            while (kept < L && ((keep >> kept) & 1u)) ++kept;
            ASSERT_TRUE(kept > 0 && (keep >> kept) == 0) << "tkeep " << keep << " not slots 0 .. k-1, cycle " << d.cycle();
            bool ends = false, ends_last = false;
            for (int j = 0; j < kept; ++j) {
                ASSERT_FALSE(want.empty()) << "a pixel nobody asked for, cycle " << d.cycle();
                const Expected e = want.front();
                want.pop_front();
                ASSERT_EQ((uint64_t(t.m_axis_tdata) >> (j * spec_params::OUT_W)) & slot_mask, e.value)
                    << "span " << e.span << " pixel " << e.index << " slot " << j << " cycle " << d.cycle();
                if (e.last) {
                    ends = true;
                    ends_last = j == kept - 1;
                    if (!P) ASSERT_TRUE(ends_last) << "a beat goes on after span " << e.span << "'s last pixel";
                }
                ++checked;
            }
            if (P) {
                ASSERT_EQ(tlast, ends) << "tlast on a beat that " << (ends ? "ends" : "does not end") << " a span, cycle "
                                       << d.cycle();
            } else {
                ASSERT_EQ(tlast, ends_last) << "tlast, cycle " << d.cycle();
                if (kept < L) ASSERT_TRUE(ends_last) << "empty slots in a beat that ends no span, cycle " << d.cycle();
            }
        }
        // no deadlock: a ready sink waits only for the pipeline while spans are outstanding (the formal bound
        // is 19 cycles at the reduced widths; 1000 leaves room for any configuration) - fail, never hang
        idle_ready = (t.m_axis_tready && !t.m_axis_tvalid && !want.empty()) ? idle_ready + 1 : 0;
        ASSERT_LT(idle_ready, 1000u) << "no pixel for 1000 cycles of a ready sink with " << want.size()
                                     << " pixels outstanding, cycle " << d.cycle();
        prev_stalled = t.m_axis_tvalid && !t.m_axis_tready && !reset_now;
        prev_data = uint64_t(t.m_axis_tdata);
        prev_keep = unsigned(t.m_axis_tkeep);
        prev_last = t.m_axis_tlast != 0;
        if (in_fire) {
            const auto px = m.span(cur);
            for (uint32_t i = 0; i < px.size(); ++i) want.push_back({px[i], i + 1 == px.size(), spans_in, i});
            ++spans_in;
            offering = false;
        }
        d.step();
        if (reset_now) {
            // whatever was in flight is gone; the source keeps offering its descriptor
            lost_by_reset += want.size();
            want.clear();
            ++resets;
            next_reset = cycles + reset_gap / 4 + rng() % reset_gap;
            t.rst_n = 1;
            t.s_axis_tvalid = 0;
            t.eval();
            ASSERT_FALSE(t.m_axis_tvalid) << "tvalid in the cycle after a reset";
            ASSERT_FALSE(t.s_axis_tready) << "tready in the cycle after a reset";
            prev_stalled = false;
        }
    }
    std::printf("%s: %llu pixels checked against the model (%llu spans, %llu cycles, %llu resets, "
                "%llu pixels dropped by resets as specified)\n",
                name, (unsigned long long)checked, (unsigned long long)spans_in, (unsigned long long)cycles,
                (unsigned long long)resets, (unsigned long long)lost_by_reset);
    ::testing::Test::RecordProperty(std::string(name) + " pixels", std::to_string(checked));
    rows().push_back({name, checked, spans_in, cycles, count(resets, "resets"),
                      lost_by_reset ? count(lost_by_reset, "pixels dropped by resets as specified") : ""});
    EXPECT_GT(resets, 0u);
}

TEST(Long, StreamAgainstModel) { stream_run<Vspec_stream>("spec_stream", Model(), kPixels, kSeed * 1000 + 1); }
// LANES = 4 (PACK = 0 and 1) and LANES = 2 packed in the up5k configuration (issue 14), a tenth of the pixels
TEST(Long, StreamFourLanesAgainstModel) {
    stream_run<Vspec_stream_l4, 4, false>("spec_stream (LANES = 4)", Model(), kPixels / 10, kSeed * 1000 + 5);
}
TEST(Long, StreamFourLanesPackedAgainstModel) {
    stream_run<Vspec_stream_l4p, 4, true>("spec_stream (LANES = 4, PACK = 1)", Model(), kPixels / 10,
                                          kSeed * 1000 + 6);
}
TEST(Long, StreamTwoLanesPackedUp5kAgainstModel) {
    stream_run<Vspec_stream_l2p_up5k, 2, true>("spec_stream (up5k, LANES = 2, PACK = 1)",
                                               Model(config_format("up5k")), kPixels / 10, kSeed * 1000 + 7);
}
TEST(Long, StreamUp5kAgainstModel) {
    stream_run<Vspec_stream_up5k>("spec_stream (up5k)", Model(config_format("up5k")), kPixels / 10, kSeed * 1000 + 3);
}
TEST(Long, StreamTunedAgainstModel) {
    Format f;
    f.mode = Mode::tuned;
    stream_run<Vspec_stream_tuned>("spec_stream (tuned)", Model(f), kPixels / 10, kSeed * 1000 + 4);
}
// spec_stream_seq, the compact back end (issue 15): the same ports, rules and pixels as spec_stream with
// LANES = 1, so the same run; a tenth of the pixels in the up5k and tuned configurations
TEST(Long, StreamSeqAgainstModel) {
    stream_run<Vspec_stream_seq>("spec_stream_seq", Model(), kPixels, kSeed * 1000 + 8);
}
TEST(Long, StreamSeqUp5kAgainstModel) {
    stream_run<Vspec_stream_seq_up5k>("spec_stream_seq (up5k)", Model(config_format("up5k")), kPixels / 10,
                                      kSeed * 1000 + 9);
}
TEST(Long, StreamSeqTunedAgainstModel) {
    Format f;
    f.mode = Mode::tuned;
    stream_run<Vspec_stream_seq_tuned>("spec_stream_seq (tuned)", Model(f), kPixels / 10, kSeed * 1000 + 10);
}

// pow mode (issue 30): a tenth of the pixels through each core
Format pow_format(const char* config = "default") {
    Format f = config_format(config);
    f.mode = Mode::pow;
    return f;
}
TEST(Long, StreamPowAgainstModel) {
    stream_run<Vspec_stream_pow>("spec_stream (pow)", Model(pow_format()), kPixels / 10, kSeed * 1000 + 11);
}
TEST(Long, StreamPowFourLanesPackedAgainstModel) {
    stream_run<Vspec_stream_pow_l4p, 4, true>("spec_stream (pow, LANES = 4, PACK = 1)", Model(pow_format()),
                                              kPixels / 10, kSeed * 1000 + 12);
}
TEST(Long, StreamPowUp5kTwoLanesPackedAgainstModel) {
    stream_run<Vspec_stream_pow_l2p_up5k, 2, true>("spec_stream (pow, up5k, LANES = 2, PACK = 1)",
                                                   Model(pow_format("up5k")), kPixels / 10, kSeed * 1000 + 13);
}
TEST(Long, StreamSeqPowAgainstModel) {
    stream_run<Vspec_stream_seq_pow>("spec_stream_seq (pow)", Model(pow_format()), kPixels / 10, kSeed * 1000 + 14);
}

// spec_unit: registers written in the cycle of Start or before it, Start in the cycle busy_o falls (back to
// back) or after idle cycles, Start/writes/loads with random values while busy (ignored), init_n low in the
// middle of some spans, now and then a Start without a new load (the length register's l again: the last
// loaded one, 0 after init_n). Start acts on its rising edge: the noise while busy leaves Start low in the
// last busy cycle, so that Start in the cycle busy_o falls is an edge (Start high from a busy cycle into the
// first idle one begins nothing: tests/test_start.cpp). Each pixel is checked against the model and against
// its cycle: pixel i's valid_o exactly 15 + 2i cycles after Start.
template <class V>
void unit_run(const char* name, const Model& m, uint64_t pixels, uint64_t seed) {
    UnitDriverT<V> d;
    auto& t = d.top();
    std::mt19937_64 rng(seed);
    uint64_t checked = 0, spans = 0, inits = 0, noload = 0, chained = 0;
    const int kFirst = m.format().unit_first_pixel();   // 15 (rom/gen/spec_format.h)
    uint32_t len_reg = 0;       // the length register: the last l loaded (0 after init_n)
    SpanRegs regs{};            // what registers 1-4 hold
    bool start_now = false;     // Start in the cycle busy_o falls
    while (checked < pixels) {
        // idle: maybe some cycles with nothing, writes now or in the Start cycle
        SpanRegs next = random_stream_span(rng, m, rng() % 8 == 0 ? 400 : 30);
        bool load = true;
        if (rng() % 64 == 0) {
            load = false;   // Start without a new load: the length register's l
            next.len = len_reg;
            ++noload;
        }
        len_reg = next.len;
        if (!start_now) {
            const int gap = static_cast<int>(rng() % 4);
            for (int i = 0; i < gap; ++i) d.step();
        }
        const bool split = !start_now && rng() % 2;   // write some registers in an earlier cycle
        if (start_now) ++chained;
        if (split) {
            t.c_i = next.c;
            t.c_we = 1;
            t.n_i = next.n;
            t.n_we = 1;
            d.step();
        }
        t.c_i = next.c;
        t.c_we = !split;
        t.n_i = next.n;
        t.n_we = !split;
        t.dzeta_i = static_cast<uint32_t>(next.dzeta);
        t.dzeta_we = 1;
        t.zeta0_i = static_cast<uint32_t>(next.zeta0);
        t.zeta0_we = 1;
        t.len_i = next.len;
        t.len_load_n = !load;
        t.start = 1;
        ASSERT_FALSE(t.busy_o) << "busy before Start, span " << spans;
        regs = next;
        d.step();
        ++spans;
        const auto want = m.span(regs);
        // run the span: noise while busy, maybe an init
        const uint64_t init_at = rng() % 16 == 0 ? 1 + rng() % (kFirst + 2 * want.size()) : 0;
        size_t got = 0;
        start_now = false;
        for (uint64_t c = 1;; ++c) {
            t.eval();
            if (init_at && c == init_at) {
                t.init_n = 0;
                d.step();
                ++inits;
                t.eval();
                ASSERT_FALSE(t.busy_o) << "busy after init_n";
                ASSERT_FALSE(t.valid_o) << "valid after init_n";
                ASSERT_EQ(t.intensity_o, 0u);
                regs = SpanRegs{};
                len_reg = 0;
                break;
            }
            // busy_o must fall in cycle 15 + 2l (checked below); past it, fail rather than loop forever
            ASSERT_LE(c, uint64_t(kFirst + 2 * want.size() - 1)) << "busy_o stuck high, span " << spans;
            if (!t.busy_o) {
                ASSERT_EQ(got, want.size()) << "span " << spans << " ended after " << got << " of " << want.size()
                                            << " pixels";
                ASSERT_EQ(c, uint64_t(kFirst + 2 * want.size() - 1)) << "busy_o fell late or early, span " << spans;
                start_now = rng() % 2;
                break;
            }
            const bool pixel_cycle = c >= kFirst && (c - kFirst) % 2 == 0 && (c - kFirst) / 2 < want.size();
            ASSERT_EQ(t.valid_o != 0, pixel_cycle) << "valid_o in cycle " << c << " of span " << spans;
            if (t.valid_o) {
                ASSERT_EQ(t.intensity_o, want[got]) << "span " << spans << " pixel " << got << " n=" << regs.n;
                ++got;
                ++checked;
            }
            // noise: everything here must be ignored while busy
            if (rng() % 4 == 0) {
                t.start = c + 2 < uint64_t(kFirst + 2 * want.size()) ? rng() % 2 : 0;
                t.c_we = rng() % 2;
                t.c_i = static_cast<uint32_t>(rng());
                t.n_we = rng() % 2;
                t.n_i = static_cast<uint32_t>(rng());
                t.dzeta_we = rng() % 2;
                t.dzeta_i = static_cast<uint32_t>(rng());
                t.zeta0_we = rng() % 2;
                t.zeta0_i = static_cast<uint32_t>(rng());
                t.len_load_n = rng() % 2;
                t.len_i = static_cast<uint32_t>(rng());
            }
            d.step();
        }
    }
    std::printf("%s: %llu pixels checked against the model (%llu spans, %llu back to back, %llu cut by "
                "init_n, %llu without a new load, %llu cycles)\n",
                name, (unsigned long long)checked, (unsigned long long)spans, (unsigned long long)chained,
                (unsigned long long)inits, (unsigned long long)noload, (unsigned long long)d.cycle());
    ::testing::Test::RecordProperty(std::string(name) + " pixels", std::to_string(checked));
    rows().push_back({name, checked, spans, d.cycle(), count(inits, "cut by init_n"),
                      count(chained, "back to back") + ", " + count(noload, "without a new load")});
    EXPECT_GT(inits, 0u);
}

TEST(Long, UnitAgainstModel) { unit_run<Vspec_unit>("spec_unit", Model(), kPixels, kSeed * 1000 + 2); }
TEST(Long, UnitTunedAgainstModel) {
    Format f;
    f.mode = Mode::tuned;
    unit_run<Vspec_unit_tuned>("spec_unit (tuned)", Model(f), kPixels / 10, kSeed * 1000 + 5);
}
TEST(Long, UnitPowAgainstModel) {
    unit_run<Vspec_unit_pow>("spec_unit (pow)", Model(pow_format()), kPixels / 10, kSeed * 1000 + 15);
}
