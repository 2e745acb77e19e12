// Per-module tests: each patent block Verilated on its own, against its definition and the model.
#include <gtest/gtest.h>

#include <deque>
#include <memory>
#include <random>

#include "Vspec_accum.h"
#include "Vspec_counter.h"
#include "Vspec_ctrl.h"
#include "Vspec_datapath.h"
#include "Vspec_decoder.h"
#include "Vspec_mul11.h"
#include "Vspec_mul13.h"
#include "spec_model.h"
#include "harness.h"

using namespace spec;

namespace {
// Every module test on the one harness (sim/rtl/harness.h): own context, tick(), reset().
template <class V>
ResetPort<V> rst_port() {
    return active_high<V>([](V& v) -> CData& { return v.rst; });
}
}  // namespace

// Decoder 10: the Fig. 10 rule on every 10-bit n, one-hot 30..33 and the table code.
TEST(Decoder10, Fig10RuleExhaustive) {
    Harness<Vspec_decoder> d;  // combinational: eval() only
    for (unsigned n = 0; n < 1024; ++n) {
        d->n = n;
        d->eval();
        const int t = table_of_n(n);
        EXPECT_EQ(d->d30, t == 0) << n;
        EXPECT_EQ(d->d31, t == 1) << n;
        EXPECT_EQ(d->d32, t == 2) << n;
        EXPECT_EQ(d->d33, t == 3) << n;
        EXPECT_EQ(d->d30 + d->d31 + d->d32 + d->d33, 1) << "one-hot at n = " << n;
        EXPECT_EQ(d->table_sel, t) << n;
    }
}

// Counter 5: load (active low), count down, borrow 35 low exactly on the 0 -> max step.
TEST(Counter5, LoadCountBorrow) {
    Harness<Vspec_counter> c(rst_port<Vspec_counter>());
    c.reset();
    EXPECT_EQ(c->q, 0);
    c->load_n = 0;
    c->d = 3;
    c->count = 1;  // load has priority
    c->eval();
    EXPECT_TRUE(c->borrow_n) << "no borrow while loading";
    c.tick();
    EXPECT_EQ(c->q, 3);
    c->load_n = 1;
    for (int expect = 2; expect >= 0; --expect) {
        c->eval();
        EXPECT_TRUE(c->borrow_n);
        c.tick();
        EXPECT_EQ(c->q, expect);
    }
    c->eval();
    EXPECT_FALSE(c->borrow_n) << "borrow on the 0 -> max step";
    c.tick();
    EXPECT_EQ(c->q, 0xffff);
    c->count = 0;
    c->eval();
    EXPECT_TRUE(c->borrow_n);
    c.tick();
    EXPECT_EQ(c->q, 0xffff) << "holds without count";
}

// Adder 6, multiplexer 7, register 8: select 36 picks register 3 or the saturating sum.
TEST(Accum678, MatchesModel) {
    Harness<Vspec_accum> a(rst_port<Vspec_accum>());
    const Model m;
    std::mt19937_64 rng(3);
    a.reset();
    EXPECT_EQ(a->angle, 0u);
    int64_t ref = 0;
    for (int i = 0; i < 20000; ++i) {
        const int64_t start = static_cast<int32_t>(rng());
        int64_t step = static_cast<int32_t>(rng());
        if (rng() % 2) step >>= rng() % 31;  // small steps too
        const bool we = rng() % 4 != 0, sel = rng() % 8 != 0;
        a->start = static_cast<uint32_t>(start);
        a->step = static_cast<uint32_t>(step);
        a->we = we;
        a->sel = sel;
        a.tick();
        if (we) ref = sel ? m.accumulate(ref, step) : start;
        ASSERT_EQ(static_cast<int32_t>(a->angle), ref) << i;
    }
}

// Multiplier 11 against the model for random angles and every ROM 9 word, plus the pi/2 edge.
TEST(Mul11, MatchesModel) {
    Harness<Vspec_mul11> u;
    const Model m;
    std::mt19937_64 rng(4);
    u->ce = 1;
    auto check = [&](int64_t angle, unsigned n) {
        u->angle = static_cast<uint32_t>(angle);
        u->scale = m.rom9_word(n);
        for (int s = 0; s < 7; ++s) u.tick();  // seven pipeline stages
        const TablePos p = m.mul11(angle, n);
        ASSERT_EQ(u->index, p.index) << angle << " n=" << n;
        ASSERT_EQ(u->zero, p.zero) << angle << " n=" << n;
    };
    for (unsigned n = 0; n < 1024; ++n) {
        for (int i = 0; i < 20; ++i) check(static_cast<int32_t>(rng()) >> (rng() % 8), n);
        check(m.angle_min(), n);
        check(m.angle_max(), n);
        check(0, n);
        if (n > 0) {  // around the quarter turn
            const double edge = (M_PI / 2) / std::sqrt(double(n) / k_of_n(n));
            if (edge < 7.9) {
                const int64_t e = m.quantize_angle(edge);
                for (int64_t d = -40000; d <= 40000; d += 997) check(e + d, n);
            }
        }
    }
    // ce = 0 holds both stages
    u->angle = 12345678;
    u->scale = m.rom9_word(5);
    for (int s = 0; s < 7; ++s) u.tick();
    const auto held = u->index;
    u->ce = 0;
    u->angle = 0x7654321;
    for (int s = 0; s < 7; ++s) u.tick();
    EXPECT_EQ(u->index, held);
    u->ce = 1;
    for (int s = 0; s < 7; ++s) u.tick();
    EXPECT_EQ(u->index, m.mul11(0x7654321, 5).index);
}

// Multiplier 13: rounding, zero flag, C exactly for the table's 1.0, never overflows.
TEST(Mul13, MatchesModel) {
    Harness<Vspec_mul13> u;
    const Model m;
    std::mt19937_64 rng(5);
    u->rst = 0;
    u->en = 1;
    u->ce = 1;
    auto check = [&](uint32_t c, uint32_t v, bool zero) {
        u->c = c;
        u->value = v;
        u->zero = zero;
        u.tick();
        u.tick();
        u.tick();  // inputs, product, rounding
        ASSERT_EQ(u->out, m.mul13(c, v, zero)) << c << " " << v << " " << zero;
    };
    for (int i = 0; i < 50000; ++i) check(rng() & 0xffff, rng() % 0x10001, rng() % 8 == 0);
    for (uint32_t c : {0u, 1u, 0x7fffu, 0x8000u, 0xffffu}) {
        check(c, 0x10000, false);
        ASSERT_EQ(u->out, c) << "1.0 gives C exactly";
        check(c, 0x10000, true);
        ASSERT_EQ(u->out, 0u);
    }
    u->rst = 1;
    u.tick();
    EXPECT_EQ(u->out, 0u);
}

// Control block 14 alone, with counter 5 modelled beside it: the Fig. 11 sequence for l = 3.
TEST(Ctrl14, Fig11SequenceStandalone) {
    Harness<Vspec_ctrl> c(active_low<Vspec_ctrl>([](Vspec_ctrl& v) -> CData& { return v.init_n; }));
    c->borrow_n = 1;
    c.reset();
    unsigned counter = 3;
    std::string s37, s36, s34, s28;
    c->start = 1;
    for (int cyc = 0; cyc < 14; ++cyc) {
        c->borrow_n = !(c->sig34 && counter == 0);
        c->eval();
        s37 += c->sig37 ? '1' : '0';
        s36 += c->sig36 ? '1' : '0';
        s34 += c->sig34 ? '1' : '0';
        s28 += c->sig28 ? '1' : '0';
        const bool count = c->sig34;
        c.tick();
        c->start = 0;
        if (count) counter = (counter + 0xffff) & 0xffff;
    }
    // cycle 0: Start; 39 set from cycle 1; strobes every other clock from cycle 2
    EXPECT_EQ(s28, "01111111110000");
    EXPECT_EQ(s37, "00101010100000");
    EXPECT_EQ(s36, "00011111110000");
    EXPECT_EQ(s34, "00010101010000");
    EXPECT_EQ(counter, 0xffffu);
}

// spec_datapath with its own valid/last pipeline (CTRL = 1, as in spec_unit) under a stalling ce. spec_unit
// ties ce to 1, so only this test stalls that pipeline: ce = 0 must hold every stage (ROM 12's read register,
// the valid and last flags and the output), and the pixels must come out in order, each exactly the model's,
// whatever the inputs are during a stall.
TEST(Datapath, StallHoldsEveryStage) {
    Harness<Vspec_datapath> u(rst_port<Vspec_datapath>());
    u->ce = 1;
    u.reset();
    const Model m;
    std::mt19937_64 rng(11);
    struct Px {
        uint32_t out;
        bool last;
    };
    std::deque<Px> want;
    size_t got = 0, stalls_with_output = 0;
    auto drive = [&](bool ce, bool valid) {
        const unsigned n = rng() % 1024;
        const int64_t angle = static_cast<int32_t>(rng()) >> (rng() % 8);
        const uint32_t c = rng() & 0xffff;
        const bool last = rng() & 1;
        u->ce = ce;
        u->in_valid = valid;
        u->in_last = last;
        u->angle = static_cast<uint32_t>(angle);
        u->scale = m.rom9_word(n);
        u->table_sel = m.table(n);
        u->c = c;
        if (ce && valid) want.push_back({m.pixel(c, angle, n), last});
        const uint32_t out0 = u->out;
        const bool valid0 = u->out_valid, last0 = u->out_last;
        u.tick();
        if (!ce) {  // a stall changes nothing that is visible
            ASSERT_EQ(u->out, out0) << "a stall changed the output";
            ASSERT_EQ(u->out_valid, valid0) << "a stall moved the valid flags";
            ASSERT_EQ(u->out_last, last0) << "a stall moved the last flags";
            if (valid0) ++stalls_with_output;
        } else if (u->out_valid) {
            ASSERT_FALSE(want.empty()) << "a pixel out that never went in, after " << got;
            ASSERT_EQ(u->out, want.front().out) << "pixel " << got;
            ASSERT_EQ(bool(u->out_last), want.front().last) << "pixel " << got;
            want.pop_front();
            ++got;
        }
    };
    for (int cyc = 0; cyc < 30000; ++cyc) drive(rng() % 3 != 0, rng() % 4 != 0);
    for (int cyc = 0; cyc < 40; ++cyc) drive(true, false);  // drain
    EXPECT_TRUE(want.empty()) << want.size() << " pixels never came out";
    EXPECT_FALSE(u->busy);
    EXPECT_GT(got, 10000u);
    EXPECT_GT(stalls_with_output, 1000u);
    // reset clears the flags whatever ce is
    drive(true, true);
    u->ce = 0;
    u.reset();
    EXPECT_FALSE(u->busy);
    EXPECT_FALSE(u->out_valid);
}
