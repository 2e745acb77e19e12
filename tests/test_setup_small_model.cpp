// spec_setup_small's bit-exact model (the up5k configuration's CORDIC setup): its pieces against double precision,
// and whole spans through the core against the host's double-precision setup within the bound its narrow format
// supports (setup_config_check(up5k); every n, every kind of span).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "setup_eval.h"
#include "setup_config.h"
#include "setup_small_model.h"

using namespace spec;

namespace {
SetupInput unit_input(double nx, double ny, double nz, double hx, double hy, double hz, unsigned n, uint32_t l,
                      double strength = 0.9) {
    const SetupFormat sf = setup_format_config("ecp5");   // the beat's formats
    SetupInput in;
    const double nv[3] = {nx, ny, nz}, hv[3] = {hx, hy, hz};
    for (int k = 0; k < 3; ++k) {
        in.n1[k] = in.n2[k] = component_code(sf, nv[k]);
        in.h1[k] = in.h2[k] = component_code(sf, hv[k]);
    }
    in.n = n;
    in.l = l;
    in.strength = static_cast<uint32_t>(std::lround(std::ldexp(strength, sf.str_frac)));
    return in;
}
}  // namespace

TEST(SetupSmallModel, GainTermsAndConstants) {
    const SmallSetupModel m;
    const SmallSetupConsts& k = m.consts();
    EXPECT_NEAR(k.gain, 1.6467602581210656, 1e-9);
    EXPECT_NEAR(terms_value(k.gain_terms), k.gain, std::ldexp(1.0, -m.format().gain_frac));
    EXPECT_NEAR(terms_value(k.half_terms), k.gain / 2, std::ldexp(1.0, -m.format().gain_frac));
    // canonical signed digits: no two neighbouring digits
    for (size_t i = 1; i < k.gain_terms.size(); ++i) EXPECT_GE(k.gain_terms[i].shift - k.gain_terms[i - 1].shift, 2);
    // t * G by the terms is within the terms' floors of the exact product
    std::mt19937_64 rng(1);
    for (int i = 0; i < 10000; ++i) {
        const int64_t t = static_cast<int64_t>(rng() % (int64_t(1) << 28)) - (int64_t(1) << 27);
        EXPECT_NEAR(double(m.gain_mul(t, false)), double(t) * terms_value(k.gain_terms), double(k.gain_terms.size()));
    }
    EXPECT_EQ(k.atan.size(), size_t(m.format().iters));
    EXPECT_EQ(k.atan[0], std::llround(std::ldexp(M_PI / 4, m.format().zf)));
}

TEST(SetupSmallModel, Log2AndExp2) {
    const SmallSetupModel m;
    const SmallSetupFormat& sf = m.format();
    std::mt19937_64 rng(2);
    double worst = 0;
    for (int i = 0; i < 200000; ++i) {
        const uint64_t x = 1 + rng() % ((uint64_t(1) << (1 + rng() % 40)));
        const double got = std::ldexp(double(m.log2_fixed(x)), -sf.lf);
        worst = std::max(worst, std::fabs(got - std::log2(double(x))));
    }
    // linear interpolation over 2^tb intervals (h^2/8 max|f''|), the position's truncation, two roundings
    const double bound = std::ldexp(1.0, -2 * sf.tb) / 8 / std::log(2.0) + std::ldexp(1.0, -(sf.tb + sf.rb)) / std::log(2.0) +
                         std::ldexp(2.0, -sf.lf);
    EXPECT_LT(worst, bound);
    EXPECT_GT(worst, bound / 4) << "the bound is not loose";
    EXPECT_EQ(m.log2_fixed(1), 0);
    EXPECT_EQ(m.log2_fixed(uint64_t(1) << 30), int64_t(30) << sf.lf);
    // C codes: round(2^(16 - p)) to within one code (the tables' rounding near a half)
    for (int i = 0; i < 100000; ++i) {
        const int64_t p = 1 + static_cast<int64_t>(rng() % (uint64_t(18) << sf.lf));
        const double exact = std::min(65535.0, std::nearbyint(std::exp2(16.0 - std::ldexp(double(p), -sf.lf))));
        EXPECT_NEAR(double(m.c_code(p)), exact, 1.0) << "p = " << p;
    }
    EXPECT_EQ(m.c_code(int64_t(40) << sf.lf), 0u);
}

TEST(SetupSmallModel, DivisionRoundsToNearest) {
    const SmallSetupModel m;
    std::mt19937_64 rng(3);
    for (int i = 0; i < 100000; ++i) {
        const int64_t g = static_cast<int64_t>(rng() % (uint64_t(1) << 32));
        const uint32_t l = 1 + static_cast<uint32_t>(rng() % 65535);
        const int64_t q = m.divide(g, l);
        const double exact = std::ldexp(double(g), -(m.format().zf - m.core_format().ang_frac)) / l;
        EXPECT_LE(std::fabs(double(q) - exact), 0.5) << g << " / " << l;
    }
}

TEST(SetupSmallModel, PrescaleIsExactAndRejectsZero) {
    const SmallSetupModel m;
    SmallSetupModel::Vec v;
    const int32_t z[3] = {0, 0, 0};
    EXPECT_FALSE(m.prescale(z, &v));
    const int32_t a[3] = {-32768, 5, 1};
    ASSERT_TRUE(m.prescale(a, &v));
    EXPECT_EQ(v.c[0], -(int64_t(1) << (m.format().f - 1)));
    EXPECT_EQ(v.c[1], int64_t(5) << (m.format().f - 16));
    const int32_t b[3] = {0, 0, 1};
    ASSERT_TRUE(m.prescale(b, &v));
    EXPECT_EQ(v.c[2], int64_t(1) << (m.format().f - 1));
}

TEST(SetupSmallModel, PassRotatesEveryLaneAlike) {
    // One pass keeps the angles between the lanes and puts the driver's pair on its positive first axis.
    const SmallSetupModel m;
    std::mt19937_64 rng(4);
    const int fb = m.format().f;
    std::uniform_int_distribution<int64_t> u(-(int64_t(1) << (fb - 1)), (int64_t(1) << (fb - 1)));
    for (int i = 0; i < 2000; ++i) {
        SmallSetupModel::Vec d{{u(rng), u(rng), u(rng)}}, f{{u(rng), u(rng), u(rng)}};
        const SmallSetupModel::Vec d0 = d, f0 = f;
        const bool halve = i % 2;
        m.pass({&d, &f}, 2, 0, halve);   // the (z, x) plane
        const double g = m.consts().gain / (halve ? 2 : 1);
        EXPECT_LE(std::fabs(double(d.c[0])), 64.0 + std::hypot(double(d0.c[2]), double(d0.c[0])) * std::ldexp(4.0, -fb));
        EXPECT_GE(d.c[2], 0);
        EXPECT_NEAR(double(d.c[2]), g * std::hypot(double(d0.c[2]), double(d0.c[0])), 64.0);
        // dot products scale by g^2: the rotation is the same for both lanes
        auto dot = [](const SmallSetupModel::Vec& a, const SmallSetupModel::Vec& b) {
            return double(a.c[0]) * b.c[0] + double(a.c[1]) * b.c[1] + double(a.c[2]) * b.c[2];
        };
        const double scale = std::ldexp(1.0, 2 * (fb - 1));
        EXPECT_NEAR(dot(d, f) / (g * g), dot(d0, f0), scale * std::ldexp(64.0, -fb));
    }
}

TEST(SetupSmallModel, DegenerateInputs) {
    const SmallSetupModel m;
    const Model core;
    const SetupFormat sf = setup_format_config("ecp5");
    // a zero vector: invalid, C = 0
    SetupInput bad = unit_input(0, 0, 1, 0, 0, 1, 10, 5);
    bad.h2[0] = bad.h2[1] = bad.h2[2] = 0;
    SetupResult r = m.run(bad);
    EXPECT_TRUE(r.flags & kSetupInvalid);
    EXPECT_EQ(r.regs.c, 0u);
    EXPECT_EQ(r.regs.zeta0, 0);
    EXPECT_EQ(r.regs.dzeta, 0);
    EXPECT_EQ(r.regs.len, 5u);
    // constant N and H: every pixel Is * cos^n(theta1). (Not flagged flat: the passes leave the angle between H1
    // and H2' at up to about 2^-14 rad in this format, above the flat threshold; lambda follows it, so the
    // pixels stay right while C and the angles are not those of a flat span.)
    const double th = 0.1;
    r = m.run(unit_input(0, 0, 1, std::sin(th), 0, std::cos(th), 20, 7, 0.5));
    EXPECT_FALSE(r.flags & kSetupSinglePixel);
    for (uint32_t px : core.span(r.regs)) EXPECT_NEAR(px / 65536.0, 0.5 * std::pow(std::cos(th), 20), 2e-3);
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
    // exactly opposite normals: flagged, and the host's great circle (checked against the host below)
    SetupInput opp = unit_input(0.6, 0, 0.8, 0.6, 0.1, 0.79, 30, 12);
    for (int k = 0; k < 3; ++k) opp.n2[k] = -opp.n1[k];
    SmallSetupTrace t;
    r = m.run(opp, &t);
    EXPECT_TRUE(r.flags & kSetupOpposite);
    EXPECT_TRUE(t.exact_opposite);
    std::mt19937_64 rng(5);
    CheckOptions co = setup_config_check(SetupConfig::up5k);
    const SpanCheck c = check_span(core, sf, opp, core.span(r.regs), rng, co);
    EXPECT_LE(c.plain_ratio, 1.0) << "exactly opposite normals: the setup takes the host's rotation axis";
}

// Every n, every kind of span, through the core, against the host in double precision with exact cos^n (the
// patent's gamma rule, the only one the small setup has), per pixel within the core's bound plus the narrow
// format's share.
TEST(SetupSmallModel, WithinTheBoundForEveryNAndKind) {
    const SmallSetupModel m;
    const Model core;
    const SetupFormat sf = setup_format_config("ecp5");
    CheckOptions co = setup_config_check(SetupConfig::up5k);
    std::mt19937_64 rng(6);
    size_t spans = 0, widened = 0, pixels = 0;
    double worst = 0;
    for (int k = 0; k < int(SpanKind::count); ++k) {
        for (unsigned n = 0; n < 1024; ++n) {
            const SetupInput in = random_case(rng, sf, SpanKind(k), n, 40);
            const SetupResult r = m.run(in);
            const std::vector<uint32_t> px = core.span(r.regs);
            const SpanCheck c = check_span(core, sf, in, px, rng, co);
            ASSERT_LE(c.ratio, 1.0) << kind_name(SpanKind(k)) << " n=" << n << " l=" << in.l << " pixel " << c.worst_pixel
                                    << ": out " << c.out << " host " << c.ref << " bound " << c.bound << " flags " << r.flags;
            worst = std::max(worst, c.ratio);
            widened += c.widened;
            pixels += px.size();
            ++spans;
        }
    }
    RecordProperty("spans", std::to_string(spans));
    RecordProperty("worst_ratio", std::to_string(worst));
    // ill-conditioned spans are rare: the widened bound is the exception
    EXPECT_LT(double(widened) / double(spans), 0.01) << widened << " of " << spans << " spans needed the widened bound";
}

// A broken setup must fail the same check: the highlight moved by 1/16 rad along the span.
TEST(SetupSmallModel, TheCheckCatchesAWrongAngle) {
    const SmallSetupModel m;
    const Model core;
    const SetupFormat sf = setup_format_config("ecp5");
    CheckOptions co = setup_config_check(SetupConfig::up5k);
    std::mt19937_64 rng(7);
    size_t caught = 0, tried = 0;
    for (unsigned n = 1; n < 1024; n += 8) {
        const SetupInput in = random_case(rng, sf, SpanKind::random, n, 20);
        SetupResult r = m.run(in);
        if ((r.flags & kSetupFlat) || r.regs.zeta0 == 0) continue;
        r.regs.zeta0 += int32_t(1) << (m.core_format().ang_frac - 4);
        ++tried;
        caught += check_span(core, sf, in, core.span(r.regs), rng, co).ratio > 1.0;
    }
    EXPECT_GT(tried, 50u);
    EXPECT_GT(double(caught) / double(tried), 0.5);
}

// The format's limits: the combinations the RTL's back end cannot take are refused with a reason
TEST(SetupSmallModel, TheBackEndsLimits) {
    const SmallSetupFormat n;
    EXPECT_NO_THROW(n.validate());
    EXPECT_NO_THROW(SmallSetupModel{n});
    SmallSetupFormat e = n;
    e.ef = 16;   // the C code's width: no rounding shift left for C >= 1/2
    EXPECT_THROW(SmallSetupModel{e}, std::invalid_argument);
    SmallSetupFormat t = n;
    t.rb = t.f - t.tb + 1;   // tb + rb > f
    t.lf = t.ef = t.tb + t.rb;
    EXPECT_NO_THROW(t.validate());
    EXPECT_THROW(SmallSetupModel{t}, std::invalid_argument);
}
