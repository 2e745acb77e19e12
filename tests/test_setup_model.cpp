// spec_setup's bit-exact model (the multiplier setup, the ecp5 configuration): its floating-point operations and
// tables against double precision, the schedule against the program, and whole spans through the core against the
// host's double-precision setup within issue 13's bound (every n, every kind of span, both gamma rules).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "setup_config.h"
#include "setup_eval.h"
#include "setup_model.h"
#include "setup_rom.h"
#include "setup_sched.h"

using namespace spec;

namespace {
const SetupFormat kSf = setup_format_config("ecp5");

SetupInput unit_input(double nx, double ny, double nz, double hx, double hy, double hz, unsigned n, uint32_t l,
                      double strength = 0.9) {
    SetupInput in;
    const double nv[3] = {nx, ny, nz}, hv[3] = {hx, hy, hz};
    for (int k = 0; k < 3; ++k) {
        in.n1[k] = in.n2[k] = component_code(kSf, nv[k]);
        in.h1[k] = in.h2[k] = component_code(kSf, hv[k]);
    }
    in.n = n;
    in.l = l;
    in.strength = static_cast<uint32_t>(std::lround(std::ldexp(strength, kSf.str_frac)));
    return in;
}

double ulp(const FpFmt& f, double v) { return std::ldexp(1.0, std::ilogb(v) - (f.m - 1)); }

Fp random_fp(std::mt19937_64& rng, const FpFmt& f, int erange) {
    const double m = 1.0 + std::ldexp(double(rng() % (uint64_t(1) << 40)), -40);
    const int e = int(rng() % uint64_t(2 * erange + 1)) - erange;
    return fp_from_double(f, (rng() & 1 ? -1.0 : 1.0) * std::ldexp(m, e));
}
}  // namespace

// Rounding half up on the magnitude, once, for products and sums; zero, underflow and saturation.
TEST(SetupModel, FloatingPointOperationsRoundOnce) {
    const FpFmt& f = kSf.fp;
    std::mt19937_64 rng(1);
    for (int i = 0; i < 200000; ++i) {
        const Fp a = random_fp(rng, f, 20), b = random_fp(rng, f, 20);
        const double va = fp_value(f, a), vb = fp_value(f, b);
        const double p = fp_value(f, fp_mul(f, a, b));
        ASSERT_LE(std::fabs(p - va * vb), 0.5 * ulp(f, va * vb) * (1 + 1e-12)) << va << " * " << vb;
        const double s = fp_value(f, fp_add(f, a, b)), x = va + vb;
        // the adder keeps g guard bits and drops the smaller operand's bits below them: within one ulp
        if (x != 0.0) ASSERT_LE(std::fabs(s - x), ulp(f, std::max(std::fabs(va), std::fabs(vb))) * (1 + 1e-12)) << va << " + " << vb;
    }
    const Fp one = fp_from_double(f, 1.0);
    EXPECT_TRUE(fp_add(f, one, fp_neg(one)).zero());
    EXPECT_TRUE(fp_mul(f, one, Fp()).zero());
    const Fp tiny = fp_from_double(f, std::ldexp(1.0, f.emin() + 1));
    EXPECT_TRUE(fp_mul(f, tiny, tiny).zero()) << "below 2^emin: zero";
    const Fp huge = fp_from_double(f, std::ldexp(1.5, f.emax()));
    const Fp sat = fp_mul(f, huge, huge);
    EXPECT_EQ(sat.e, f.emax());
    EXPECT_EQ(sat.m, (uint64_t(1) << f.m) - 1) << "above the largest value: saturated";
    // a word and back
    for (int i = 0; i < 1000; ++i) {
        const Fp a = random_fp(rng, f, 100);
        EXPECT_EQ(fp_unword(f, fp_word(f, a)), a);
    }
}

// The EFU's functions from their tables with linear interpolation, against double precision.
TEST(SetupModel, EfuFunctionsAgainstDouble) {
    const SetupModel m(kSf);
    const FpFmt& f = kSf.fp;
    std::mt19937_64 rng(2);
    double worst[4] = {0, 0, 0, 0};
    for (int i = 0; i < 100000; ++i) {
        const double x = std::ldexp(1.0 + std::ldexp(double(rng() % (1u << 30)), -30), int(rng() % 41) - 20);
        const Fp fx = fp_from_double(f, x);
        const double xv = fp_value(f, fx);
        const double rs = fp_value(f, setup_efu(kSf, m.tables(), SetupOp::RSQRT, fx));
        const double rc = fp_value(f, setup_efu(kSf, m.tables(), SetupOp::RCP, fx));
        const double lg = fp_value(f, setup_efu(kSf, m.tables(), SetupOp::LOG2, fx));
        worst[0] = std::max(worst[0], std::fabs(rs * std::sqrt(xv) - 1));
        worst[1] = std::max(worst[1], std::fabs(rc * xv - 1));
        worst[2] = std::max(worst[2], std::fabs(lg - std::log2(xv)));
        const double t = std::ldexp(double(rng() % (1u << 30)), -30);   // atan(t)/t on [0, 1]
        const Fp ft = fp_from_double(f, t);
        const double tv = fp_value(f, ft);
        const double at = fp_value(f, setup_efu(kSf, m.tables(), SetupOp::ATANG, ft));
        worst[3] = std::max(worst[3], std::fabs(at - (tv > 0 ? std::atan(tv) / tv : 1.0)));
    }
    // interpolation over 2^tab_t intervals and the result's rounding: a few units of 2^-m
    const double lim = std::ldexp(8.0, -f.m);
    EXPECT_LT(worst[0], lim) << "rsqrt";
    EXPECT_LT(worst[1], lim) << "rcp";
    EXPECT_LT(worst[2], lim * 8) << "log2 (absolute)";
    EXPECT_LT(worst[3], lim) << "atan(t)/t";
    EXPECT_EQ(fp_value(f, setup_efu(kSf, m.tables(), SetupOp::RSQRT, fp_from_double(f, -1.0))), 0.0);
    EXPECT_EQ(fp_value(f, setup_efu(kSf, m.tables(), SetupOp::RCP, Fp())), 0.0);
    EXPECT_EQ(fp_value(f, setup_efu(kSf, m.tables(), SetupOp::LOG2, Fp())), -1024.0);
}

// The modulo schedule with banked operands, run cycle by cycle (SetupMachineSim), gives the program's values for
// the ecp5 machine and for other unit counts and the narrow format.
TEST(SetupModel, ScheduleRunsTheProgram) {
    std::vector<SetupFormat> fs{kSf, setup_format_config("narrow")};
    SetupFormat few = kSf;
    few.mach.mul = 3;
    few.mach.add = 2;
    few.mach.idot = 1;
    fs.push_back(few);
    for (const SetupFormat& sf : fs) {
        const SetupModel m(sf);
        const SetupSchedule s = setup_schedule(sf, m.program());
        std::mt19937_64 rng(3);
        std::vector<SetupBeat> beats;
        for (int i = 0; i < 40; ++i) {
            SetupInput in = i % 3 ? random_case(rng, sf, SpanKind(i % int(SpanKind::count)), unsigned(rng() % 1024), 40)
                                  : random_raw(rng, sf);
            SetupBeat b;
            if (m.beat(in, &b)) beats.push_back(b);
        }
        SetupMachineSim sim(sf, m.program(), m.tables(), s);
        const std::vector<std::array<Fp, SO_COUNT>> got = sim.run(beats);
        ASSERT_EQ(got.size(), beats.size());
        for (size_t i = 0; i < beats.size(); ++i) {
            const std::vector<Fp> v = setup_eval(sf, m.tables(), m.program(), beats[i]);
            for (int o = 0; o < SO_COUNT; ++o)
                ASSERT_EQ(got[i][o], v[size_t(m.program().out[o])]) << sf.name << " span " << i << " " << setup_out_name(o);
        }
        // the least II: every operation of the busiest unit type has its slot
        for (int ty = 0; ty < kSetupUnitTypes; ++ty) {
            const int units = ty == 0 ? sf.mach.idot : ty == 1 ? sf.mach.mul : ty == 2 ? sf.mach.add : ty == 3 ? sf.mach.efu : sf.mach.misc;
            EXPECT_GE(s.ii * units, m.program().count(SetupUnit(ty)));
        }
    }
}

TEST(SetupModel, DegenerateInputs) {
    const SetupModel m(kSf);
    const Model core;
    // a zero vector: invalid, C = 0
    SetupInput bad = unit_input(0, 0, 1, 0, 0, 1, 10, 5);
    bad.h2[0] = bad.h2[1] = bad.h2[2] = 0;
    SetupResult r = m.run(bad);
    EXPECT_TRUE(r.flags & kSetupInvalid);
    EXPECT_EQ(r.regs.c, 0u);
    EXPECT_EQ(r.regs.zeta0, 0);
    EXPECT_EQ(r.regs.dzeta, 0);
    EXPECT_EQ(r.regs.len, 5u);
    // constant N and H: flat, C = Is * cos^n(theta1), angles 0
    const double th = 0.1;
    r = m.run(unit_input(0, 0, 1, std::sin(th), 0, std::cos(th), 20, 7, 0.5));
    EXPECT_TRUE(r.flags & kSetupFlat);
    EXPECT_FALSE(r.flags & kSetupSinglePixel);
    EXPECT_EQ(r.regs.zeta0, 0);
    EXPECT_EQ(r.regs.dzeta, 0);
    EXPECT_NEAR(r.regs.c / 65536.0, 0.5 * std::pow(std::cos(th), 20), 2e-4);
    // l = 0: single pixel and flat
    r = m.run(unit_input(0.6, 0, 0.8, 0, 0.6, 0.8, 5, 0));
    EXPECT_EQ(r.flags & (kSetupFlat | kSetupSinglePixel), unsigned(kSetupFlat | kSetupSinglePixel));
    // facing away on the whole span: no highlight, C = 0
    r = m.run(unit_input(0, 0, 1, 0, 0.8, -0.6, 5, 9));
    EXPECT_TRUE(r.flags & kSetupNoHighlight);
    EXPECT_EQ(r.regs.c, 0u);
    // n = 0: C = Is even facing away
    r = m.run(unit_input(0, 0, 1, 0, 0.8, -0.6, 0, 9, 0.25));
    EXPECT_FALSE(r.flags & kSetupNoHighlight);
    EXPECT_EQ(r.regs.c, 16384u);
    // strength 1.5 at the peak: C saturates
    r = m.run(unit_input(0, 0, 1, 0, 0, 1, 50, 3, 1.5));
    EXPECT_TRUE(r.flags & kSetupCSaturated);
    EXPECT_EQ(r.regs.c, 65535u);
    // exactly opposite normals: flagged, and the host's rotation axis (checked against the host)
    SetupInput opp = unit_input(0.6, 0, 0.8, 0.6, 0.1, 0.79, 30, 12);
    for (int k = 0; k < 3; ++k) opp.n2[k] = -opp.n1[k];
    for (bool mid : {false, true}) {
        opp.midpoint = mid;
        r = m.run(opp);
        EXPECT_TRUE(r.flags & kSetupOpposite);
        std::mt19937_64 rng(5);
        const SpanCheck c = check_span(core, kSf, opp, core.span(r.regs), rng);
        EXPECT_LE(c.plain_ratio, 1.0) << "exactly opposite normals, midpoint " << mid;
    }
    // the midpoint rule where N.H is not a sinusoid of amplitude <= 1: the patent's gamma, flag 5
    SetupInput fb = unit_input(0, 0, 1, 0, 0, 1, 10, 8);
    fb.n2[0] = component_code(kSf, 0.9);
    fb.n2[2] = component_code(kSf, -0.2);
    fb.h2[0] = component_code(kSf, -0.6);
    fb.h2[2] = component_code(kSf, 0.8);
    fb.midpoint = true;
    const host::SpanSetup hs = host::setup_span(core, host_ends(kSf, fb), host_strength(kSf, fb), fb.n, fb.l, host_rule(fb));
    r = m.run(fb);
    EXPECT_EQ(r.flags & kSetupGammaFallback, hs.flags & host::kGammaFallback);
}

// Issue 13's accuracy, both gamma rules: every n, every kind of span, through the core, against the host in double
// precision with exact cos^n, per pixel within the core's bound plus 0.2 % for the setup.
TEST(SetupModel, WithinTheBoundForEveryNAndKind) {
    const SetupModel m(kSf);
    const Model core;
    std::mt19937_64 rng(6);
    size_t spans = 0, widened = 0;
    double worst = 0;
    for (int k = 0; k < int(SpanKind::count); ++k) {
        for (unsigned n = 0; n < 1024; ++n) {
            SetupInput in = random_case(rng, kSf, SpanKind(k), n, 40);
            in.midpoint = (n + unsigned(k)) % 2;
            const SetupResult r = m.run(in);
            const std::vector<uint32_t> px = core.span(r.regs);
            const SpanCheck c = check_span(core, kSf, in, px, rng);
            ASSERT_LE(c.ratio, 1.0) << kind_name(SpanKind(k)) << " n=" << n << " l=" << in.l << " midpoint " << in.midpoint
                                    << " pixel " << c.worst_pixel << ": out " << c.out << " host " << c.ref << " bound "
                                    << c.bound << " flags " << r.flags;
            worst = std::max(worst, c.ratio);
            widened += c.widened;
            ++spans;
        }
    }
    RecordProperty("worst_ratio", std::to_string(worst));
    EXPECT_LE(double(widened) / double(spans), 0.001) << widened << " of " << spans << " spans needed the widened bound";
}

// A broken setup must fail the same check: lambda with the wrong sign (the highlight on the wrong side).
TEST(SetupModel, TheCheckCatchesAWrongAngle) {
    const SetupModel m(kSf);
    const Model core;
    std::mt19937_64 rng(7);
    size_t caught = 0, tried = 0;
    for (unsigned n = 1; n < 1024; n += 8) {
        const SetupInput in = random_case(rng, kSf, SpanKind::near_equal, n, 20);
        SetupResult r = m.run(in);
        if ((r.flags & kSetupFlat) || r.regs.zeta0 == 0) continue;
        r.regs.zeta0 = -r.regs.zeta0;
        ++tried;
        caught += check_span(core, kSf, in, core.span(r.regs), rng).ratio > 1.0;
    }
    EXPECT_GT(tried, 50u);
    EXPECT_GT(double(caught) / double(tried), 0.5);
}

// The named formats and configurations; an unknown name or an unsupported combination is refused with a reason.
TEST(SetupModel, NamedFormatsAndConfigurations) {
    EXPECT_EQ(setup_format_config("ecp5").fp.m, 22);
    const SetupFormat n = setup_format_config("narrow");
    EXPECT_NO_THROW(n.validate());
    EXPECT_EQ(n.fp.m, 16);
    EXPECT_THROW(setup_format_config("wide"), std::invalid_argument);
    SetupFormat bad = kSf;
    bad.fp.m = 30;   // past the multiplier's 18 x 18 and shift-and-add
    EXPECT_THROW(bad.validate(), std::invalid_argument);
    bad = kSf;
    bad.mach.mul = 0;
    EXPECT_THROW(bad.validate(), std::invalid_argument);
    EXPECT_EQ(parse_setup_config("ecp5"), SetupConfig::ecp5);
    EXPECT_EQ(parse_setup_config("up5k"), SetupConfig::up5k);
    EXPECT_THROW(parse_setup_config("pipelined"), std::invalid_argument);
    // both configurations' models read the same beat
    const SetupInput in = unit_input(0, 0.6, 0.8, 0, 0, 1, 10, 4);
    EXPECT_EQ(ConfigSetupModel(SetupConfig::ecp5).run(in).regs.c, SetupModel(kSf).run(in).regs.c);
    EXPECT_EQ(ConfigSetupModel(SetupConfig::up5k).run(in).regs.c, SmallSetupModel().run(in).regs.c);
}
