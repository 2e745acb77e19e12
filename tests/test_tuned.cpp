// Tuned mode (issue 7, docs/tuned.md): the minimax fit, the generator's ROM 9 with the table field, the
// bit-exact model and the Verilated spec_unit / spec_stream in tuned configuration against double precision:
// inside the epicentre |out - ref| <= 0.0025 ref + 2^-14 for every n, elsewhere within patent mode's bound.
// Also other table sets (eight tables) in the generator and the model.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "Vspec_stream_tuned.h"
#include "Vspec_unit_tuned.h"
#include "analysis.h"
#include "common.h"
#include "fit.h"
#include "romgen.h"
#include "spec_model.h"
#include "stream_driver.h"
#include "unit_driver.h"

using namespace spec;
using namespace spec::test;

namespace {
Format tuned_format() {
    Format f;
    f.mode = Mode::tuned;
    return f;
}

const double kLsb14 = std::ldexp(1.0, -14), kLsb13 = std::ldexp(1.0, -13);

// The bounds: inside the epicentre 0.25 % of ref + 2^-14; elsewhere patent mode's test bound
// C (a_patent(n) + 0.002) + 2^-13 (tests/test_spec_unit.cpp).
double tuned_bound(unsigned n, double c, double angle, double ref) {
    if (std::fabs(angle) <= epicentre_end(n)) return 0.0025 * ref + kLsb14;
    return c * (fig10_errors().a[n] + 0.002) + kLsb13;
}


}  // namespace

// The minimax scale equioscillates: the largest positive and negative relative errors are equal, and moving
// the scale either way makes the worst error larger (brute force, dense sampling).
TEST(TunedFit, MinimaxScaleIsOptimal) {
    for (unsigned n : {3u, 5u, 6u, 7u, 9u, 30u, 100u, 1000u, 1023u}) {
        const int k = k_of_n(n);
        double q;
        const double s = minimax_scale(n, k, &q);
        const double qs = rel_error(n, k, s);
        EXPECT_NEAR(qs, q, 1e-9) << n;
        EXPECT_LT(q, rel_error(n, k, std::sqrt(double(n) / k))) << "better than the Taylor scale, n=" << n;
        EXPECT_GT(rel_error(n, k, s * (1 + 1e-4)), q) << n;
        EXPECT_GT(rel_error(n, k, s * (1 - 1e-4)), q) << n;
        // both signs reach the worst error
        double hi = 0, lo = 0;
        const double end = epicentre_end(n);
        for (int i = 0; i <= 20000; ++i) {
            const double d = end * i / 20000.0;
            const double e = approx_scaled(k, s, d) / std::pow(std::cos(d), double(n)) - 1.0;
            hi = std::max(hi, e);
            lo = std::min(lo, e);
        }
        EXPECT_NEAR(hi, -lo, 1e-3 * q) << n;
    }
    double q;
    EXPECT_EQ(minimax_scale(16, 16, &q), 1.0);
    EXPECT_EQ(q, 0.0);
}

// The tuned table choice considers the two tables next to n; no other table does better (all n <= 40 and a
// sample above), and with the patent's tables it is the Fig. 10 rule for every n.
TEST(TunedFit, TableChoiceIsTheBestAndEqualsFig10) {
    const std::vector<TableFit>& fits = table_fits(tuned_format());
    ASSERT_EQ(fits.size(), 1024u);
    for (unsigned n = 0; n < 1024; ++n) EXPECT_EQ(fits[n].table, table_of_n(n)) << n;
    for (unsigned n = 1; n <= 1023; n += (n < 40 ? 1 : 97)) {
        double best;
        minimax_scale(n, fits[n].k, &best);
        for (int k : kTables) {
            double q;
            minimax_scale(n, k, &q);
            EXPECT_GE(q, best * (1 - 1e-9)) << "n=" << n << " k=" << k;
        }
    }
}

// In double precision tuned mode is better than patent mode everywhere: relative error in the epicentre and
// absolute error on [0, pi/2], every n; worst relative error 0.185 % (n = 3) against 1.09 %.
TEST(TunedFit, BetterThanPatentForEveryN) {
    const ErrorTable& t = mode_errors(tuned_format());
    const ErrorTable& p = fig10_errors();
    double worst = 0;
    for (unsigned n = 0; n < 1024; ++n) {
        EXPECT_LE(t.q[n], p.q[n] + 1e-12) << n;
        EXPECT_LE(t.a[n], p.a[n] + 1e-12) << n;
        if (p.q[n] > 1e-6) EXPECT_LT(t.q[n], 0.25 * p.q[n]) << n;
        worst = std::max(worst, t.q[n]);
    }
    EXPECT_GT(worst, 0.0018);
    EXPECT_LT(worst, 0.0019);
    EXPECT_NEAR(t.q[3], worst, 1e-12);
}

TEST(TunedRom, Rom9HoldsMinimaxScaleAndTable) {
    const Format f = tuned_format();
    EXPECT_TRUE(f.decoder_rom());
    EXPECT_EQ(f.rom9_dw(), f.scale_w + 2);
    const auto r9 = make_rom9(f);
    const auto p9 = make_rom9(Format());
    const std::vector<TableFit>& fits = table_fits(f);
    ASSERT_EQ(r9.size(), 1024u);
    for (unsigned n = 0; n < 1024; ++n) {
        EXPECT_EQ(int(r9[n] >> f.scale_w), table_of_n(n)) << n;
        const uint32_t scale = r9[n] & ((1u << f.scale_w) - 1);
        EXPECT_NEAR(std::ldexp(double(scale), -f.scale_frac), fits[n].scale * 2 / M_PI, std::ldexp(0.5, -f.scale_frac));
        if (n == 1 || n == 2 || n == 4 || n == 16) EXPECT_EQ(scale, p9[n]) << "exact table, n=" << n;
    }
    EXPECT_NE(r9[3] & 0x3ffff, p9[3]);
    // the tables themselves are the patent's
    EXPECT_EQ(make_rom12(f), make_rom12(Format()));
    // headers: the table field is declared; the patent's default header says the gates choose
    EXPECT_NE(verilog_header(f).find("`define SPEC_DECODER_ROM 1"), std::string::npos);
    EXPECT_NE(verilog_header(f).find("`define SPEC_TSEL_W 2"), std::string::npos);
    EXPECT_NE(verilog_header(Format()).find("`define SPEC_DECODER_ROM 0"), std::string::npos);
    EXPECT_NE(cpp_header(f).find("DECODER_ROM = 1"), std::string::npos);
}

// Eight tables: three index bits, ROM 12 of 8 tables, the model reads the table from ROM 9.
TEST(TunedRom, OtherTableSets) {
    Format f = tuned_format();
    f.tables = {1, 2, 3, 4, 8, 16, 32, 64};
    EXPECT_EQ(f.tsel_w(), 3);
    const auto r12 = make_rom12(f);
    const size_t per = size_t(1) << f.tbl_aw;
    ASSERT_EQ(r12.size(), 8 * per);
    for (int t = 0; t < 8; ++t) {
        const double x = 1000 * M_PI / 2 / double(per);
        EXPECT_NEAR(std::ldexp(double(r12[t * per + 1000]), -f.tbl_frac), std::pow(std::cos(x), f.tables[t]),
                    std::ldexp(0.5, -f.tbl_frac)) << t;
    }
    const Model m(f);
    EXPECT_EQ(f.tables[m.table(3)], 3);
    EXPECT_EQ(f.tables[m.table(8)], 8);
    EXPECT_EQ(f.tables[m.table(1000)], 64);
    // five tables pad ROM 12 to eight with zero tables
    Format g = f;
    g.tables = {1, 2, 4, 16, 64};
    const auto z = make_rom12(g);
    ASSERT_EQ(z.size(), 8 * per);
    for (size_t i = 5 * per; i < z.size(); ++i) ASSERT_EQ(z[i], 0u);
    // more tables, smaller error in double; patent mode (Taylor scale) on the same set is worse
    const ErrorTable& e8 = mode_errors(f);
    Format p8 = f;
    p8.mode = Mode::patent;
    const ErrorTable& e8p = mode_errors(p8);
    const ErrorTable& e4 = mode_errors(tuned_format());
    double w8 = 0, w4 = 0, w8p = 0;
    for (unsigned n = 0; n < 1024; ++n) {
        w8 = std::max(w8, e8.q[n]);
        w4 = std::max(w4, e4.q[n]);
        w8p = std::max(w8p, e8p.q[n]);
    }
    EXPECT_LT(w8, 0.6 * w4);
    EXPECT_GT(w8p, 3 * w8);
    // bad sets
    Format b;
    b.tables = {2, 1};
    EXPECT_THROW(b.validate(), std::invalid_argument);
    b.tables = {};
    EXPECT_THROW(b.validate(), std::invalid_argument);
}

// The bit-exact model in tuned mode, every n, dense sweeps of the epicentre and of [0, pi/2], C = 1 - 2^-16
// and a smaller C: within the bound everywhere; and measurably better than patent mode.
TEST(TunedModel, WithinBoundForEveryN) {
    const Model m(tuned_format());
    const Model p;
    double worst_ratio = 0, worst_rel = 0;
    unsigned worst_n = 0;
    BoundRatios worst;   // tests/common.h
    for (double c : {1.0 - std::ldexp(1.0, -16), 0.3}) {
        const uint32_t craw = m.quantize_c(c);
        const double cq = m.out_value(craw);
        for (unsigned n = 0; n < 1024; ++n) {
            for (double reach : {epicentre_end(n), M_PI / 2}) {
                const uint32_t len = 600;
                SpanRegs r{craw, m.quantize_angle(reach / len), 0, n, len};
                const auto px = m.span(r);
                const auto ang = m.angles(r);
                for (size_t i = 0; i < px.size(); ++i) {
                    const double x = m.angle_value(ang[i]);
                    const double ref = cq * std::pow(std::max(0.0, std::cos(x)), double(n));
                    const double err = std::fabs(m.out_value(px[i]) - ref);
                    const double bound = tuned_bound(n, cq, x, ref);
                    ASSERT_LE(err, bound) << "n=" << n << " x=" << x << " C=" << c;
                    if (err / bound > worst_ratio) { worst_ratio = err / bound; worst_n = n; }
                    worst.add(m, r, ang[i], px[i], ref, bound, cq, x);
                    if (x <= epicentre_end(n) && c > 0.5) worst_rel = std::max(worst_rel, err / ref);
                }
            }
        }
    }
    RecordProperty("worst_error_over_bound", std::to_string(worst_ratio));
    RecordProperty("worst_fixed_point_over_slack", std::to_string(worst.fixed_over_slack));
    RecordProperty("worst_n", std::to_string(worst_n));
    // the measured values are docs/verification.md's row (checked below); limits with tests/common.h's margins
    EXPECT_LE(worst.error_over_bound, 0.89);
    EXPECT_LE(worst.fixed_over_slack, 0.49) << "fixed-point error grew (worst at n = " << worst.fixed_n << ")";
    expect_documented_ratios("TunedModel.WithinBoundForEveryN", worst, 0.89, 0.49);
    EXPECT_GE(worst.fixed_over_slack, 0.27) << "the measurement itself changed: re-measure and document";
    EXPECT_GT(worst_rel, 0.0015);  // the bound is not loose: n = 3 reaches 0.2 %
    // patent mode does not meet the tuned bound (n = 3 at 1.1 %)
    const uint32_t craw = p.quantize_c(0.99);
    SpanRegs r{craw, p.quantize_angle(epicentre_end(3) / 100), 0, 3, 100};
    bool fails = false;
    const auto px = p.span(r);
    const auto ang = p.angles(r);
    for (size_t i = 0; i < px.size(); ++i) {
        const double x = p.angle_value(ang[i]);
        const double ref = p.out_value(craw) * std::pow(std::cos(x), 3.0);
        if (x <= epicentre_end(3) && std::fabs(p.out_value(px[i]) - ref) > 0.0025 * ref + kLsb14) fails = true;
    }
    EXPECT_TRUE(fails);
}

// The Verilated spec_unit in tuned configuration (DECODER_ROM = 1, build-tree ROM images): the same pixels as
// the tuned model, and within the bound against double precision, every n, random spans.
TEST(TunedUnit, EqualsModelAndMeetsBoundForEveryN) {
    const Model m(tuned_format());
    UnitDriverTuned d;
    std::mt19937_64 rng(71);
    size_t inside = 0, outside = 0;
    BoundRatios worst;   // tests/common.h
    for (int round = 0; round < 2; ++round) {
        for (unsigned n = 0; n < 1024; ++n) {
            const RandomSpan s = random_span(rng, m, n, round ? 120 : 40);
            const auto px = d.span(s.regs);
            ASSERT_EQ(px, m.span(s.regs)) << "n=" << n << " len=" << s.regs.len;
            const auto reg8 = m.angles(s.regs);
            for (size_t i = 0; i < px.size(); ++i) {
                const double ang = s.zeta0 + double(i) * s.dzeta;
                const double ref = s.c * std::pow(std::max(0.0, std::cos(ang)), double(n));
                const double err = std::fabs(m.out_value(px[i]) - ref);
                const double bound = tuned_bound(n, s.c, ang, ref);
                ASSERT_LE(err, bound) << "n=" << n << " angle=" << ang << " ref=" << ref;
                worst.add(m, s.regs, reg8[i], px[i], ref, bound, s.c, ang);
                (std::fabs(ang) <= epicentre_end(n) ? inside : outside) += 1;
            }
        }
    }
    // raw register contents, saturating angles included
    for (int i = 0; i < 300; ++i) {
        SpanRegs r{static_cast<uint32_t>(rng() & 0xffff), static_cast<int32_t>(rng()) >> (rng() % 32),
                   static_cast<int32_t>(rng()), static_cast<uint32_t>(rng() % 1024), static_cast<uint32_t>(rng() % 40)};
        ASSERT_EQ(d.span(r), m.span(r)) << i;
    }
    EXPECT_GT(inside, 10000u);
    EXPECT_GT(outside, 10000u);
    RecordProperty("worst_error_over_bound", std::to_string(worst.error_over_bound));
    RecordProperty("worst_fixed_point_over_slack", std::to_string(worst.fixed_over_slack));
    // the measured values are docs/verification.md's row (checked below); limits with tests/common.h's margins
    EXPECT_LE(worst.error_over_bound, 0.76);
    EXPECT_LE(worst.fixed_over_slack, 0.46) << "fixed-point error grew (worst at n = " << worst.fixed_n << ")";
    expect_documented_ratios("TunedUnit.EqualsModelAndMeetsBoundForEveryN", worst, 0.76, 0.46);
    EXPECT_GE(worst.fixed_over_slack, 0.26) << "the measurement itself changed: re-measure and document";
    // it is the tuned core: n = 3 differs from the patent's
    UnitDriver pd;
    SpanRegs r{m.quantize_c(0.9), m.quantize_angle(0.1), m.quantize_angle(-0.6), 3, 12};
    EXPECT_NE(d.span(r), pd.span(r));
}

TEST(TunedStream, EqualsModelUnderStalls) {
    const Model m(tuned_format());
    StreamDriver<Vspec_stream_tuned> d;
    std::mt19937_64 rng(72);
    std::vector<SpanRegs> spans;
    for (unsigned n = 0; n < 1024; ++n) spans.push_back(random_span(rng, m, n, rng() % 4 ? 3 : 60).regs);
    const auto px = d.run(spans, Stalls{0.7, 0.7}, rng);
    size_t k = 0;
    for (const auto& r : spans) {
        for (uint32_t want : m.span(r)) {
            ASSERT_LT(k, px.size());
            ASSERT_EQ(px[k++].value, want) << "n=" << r.n;
        }
    }
    EXPECT_EQ(k, px.size());
}

TEST(TunedSpecsim, SpanModesAgreeAndDiffer) {
    const std::string span = "span --n 3 --c 0.9 --zeta0 -0.6 --dzeta 0.15 --len 8";
    const CliRun rtl = specsim(span + " --mode tuned");
    const CliRun gold = specsim(span + " --mode tuned --model golden");
    const CliRun stream = specsim(span + " --mode tuned --model stream");
    const CliRun patent = specsim(span + " --mode patent");
    ASSERT_EQ(rtl.code, 0) << rtl.err;
    EXPECT_EQ(rtl.out, gold.out);
    EXPECT_EQ(rtl.out, stream.out);
    EXPECT_NE(rtl.out, patent.out);
    EXPECT_EQ(patent.out, specsim(span).out) << "patent is the default";
    for (const char* bad : {"span --n 3 --c 0.5 --zeta0 0 --dzeta 0 --len 1 --mode",
                            "span --n 3 --c 0.5 --zeta0 0 --dzeta 0 --len 1 --mode fast",
                            "accuracy --mode 1", "accuracy --tables 4,2", "accuracy --tables 1,x",
                            "accuracy --model rtl --tables 1,2,4,8,16", "vectors --out /dev/null --mode none"}) {
        const CliRun r = specsim(bad);
        EXPECT_EQ(r.code, 2) << bad;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << bad << ": " << r.err;
        EXPECT_TRUE(r.out.empty()) << bad;
    }
}

// specsim tables --quick makes the files and its rows are rows of the committed docs/tables.md (make tables),
// so the table README quotes is the one the code makes now.
TEST(TunedSpecsim, TablesQuickRowsMatchCommittedDocs) {
    const std::string dir = ::testing::TempDir() + "/tables_quick." + std::to_string(getpid());
    const CliRun r = specsim("tables --quick --out-dir " + dir);
    ASSERT_EQ(r.code, 0) << r.err;
    for (const char* f : {"tables.md", "tables.csv", "tables.dat", "tables.gp", "tables.png"}) {
        FILE* fp = std::fopen((dir + "/" + f).c_str(), "rb");
        ASSERT_NE(fp, nullptr) << f;
        std::fseek(fp, 0, SEEK_END);
        EXPECT_GT(std::ftell(fp), 100) << f;
        std::fclose(fp);
    }
    std::string doc;
    {
        FILE* fp = std::fopen((std::string(SPEC_SOURCE_DIR) + "/docs/tables.md").c_str(), "rb");
        ASSERT_NE(fp, nullptr) << "docs/tables.md (make tables)";
        char buf[4096];
        size_t k;
        while ((k = std::fread(buf, 1, sizeof buf, fp)) > 0) doc.append(buf, k);
        std::fclose(fp);
    }
    size_t rows = 0, pos = 0;
    while ((pos = r.out.find("\n| ", pos)) != std::string::npos) {
        const size_t end = r.out.find('\n', pos + 1);
        const std::string row = r.out.substr(pos + 1, end - pos - 1);
        pos = end;
        if (row.find(" x 2^") == std::string::npos) continue;  // header
        EXPECT_NE(doc.find(row), std::string::npos) << "not in docs/tables.md (run make tables): " << row;
        ++rows;
    }
    EXPECT_EQ(rows, 12u);
    EXPECT_NE(r.out.find("| 1,2,4,16 | tuned | 4 x 2^12 x 17 | 1024 x 20 |"), std::string::npos);
    for (const char* bad : {"tables", "tables --out-dir", "tables --out-dir /tmp --fast", "compare --points 5",
                            "compare --bogus 1"}) {
        const CliRun b = specsim(bad);
        EXPECT_EQ(b.code, 2) << bad;
        EXPECT_EQ(std::count(b.err.begin(), b.err.end(), '\n'), 1) << bad << ": " << b.err;
    }
    std::system(("rm -rf '" + dir + "'").c_str());
}

// Fig. 8 with the minimax scale: table k = 4 alone keeps the relative error within 1 % for n = 2..1000
// (with sqrt(n/k) only for n = 4..6), and the two tables {1, 4} meet the patent's 1 % claim for every n.
TEST(TunedFit, OneTableCoversFarMoreN) {
    for (unsigned n = 2; n <= 1000; ++n) {
        double q;
        minimax_scale(n, 4, &q);
        ASSERT_LE(q, 0.01) << n;
    }
    EXPECT_GT(q_error(3, 4), 0.01);
    EXPECT_GT(q_error(7, 4), 0.01);
    Format f;
    f.mode = Mode::tuned;
    f.tables = {1, 4};
    const ErrorTable& e = mode_errors(f);
    for (unsigned n = 0; n < 1024; ++n) EXPECT_LE(e.q[n], 0.0075) << n;
    EXPECT_GT(e.q[2], 0.007);
}
