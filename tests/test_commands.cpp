// specsim's commands as library functions (parse -> compute -> report, sim/specsim/cmd_*.h): the numbers each
// compute step returns, checked against the model and the analysis; the exit codes; --help of every command.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis.h"
#include "cmd_accuracy.h"
#include "cmd_bench.h"
#include "cmd_demo.h"
#include "cmd_render.h"
#include "cmd_span.h"
#include "cmd_tuned.h"
#include "cmd_vectors.h"
#include "common.h"
#include "exit_codes.h"
#include "unit_driver.h"

using namespace spec;
using namespace spec::test;

namespace {
// argv for a parse_* function: "specsim CMD args..."
struct Argv {
    std::vector<std::string> s;
    std::vector<char*> p;
    explicit Argv(const std::vector<std::string>& args) : s(args) {
        s.insert(s.begin(), {"specsim", "cmd"});
        for (auto& x : s) p.push_back(&x[0]);
        p.push_back(nullptr);
    }
    int argc() const { return int(s.size()); }
    char** argv() { return p.data(); }
};
}  // namespace

TEST(ExitCodes, BadInputIsTwoAndEverythingElseIsThree) {
    std::ostringstream err;
    EXPECT_EQ(exit_code_of([] { return 0; }, err), 0);
    EXPECT_EQ(exit_code_of([]() -> int { throw UsageError("--n: bad"); }, err), 2);
    EXPECT_EQ(exit_code_of([]() -> int { throw InputError("cannot write x"); }, err), 2);
    EXPECT_EQ(err.str(), "specsim: --n: bad\nspecsim: cannot write x\n");
    std::ostringstream e3;
    EXPECT_EQ(exit_code_of([]() -> int { throw std::runtime_error("the core produced 3 pixels"); }, e3), 3);
    EXPECT_EQ(exit_code_of([]() -> int { throw std::invalid_argument("n"); }, e3), 3);
    EXPECT_EQ(exit_code_of([]() -> int { throw std::out_of_range("x\ny"); }, e3), 3);
    EXPECT_EQ(exit_code_of([]() -> int { throw 42; }, e3), 3);
    EXPECT_EQ(lines(e3.str()).size(), 4u) << "one line each, control characters escaped: " << e3.str();
    EXPECT_EQ(e3.str().rfind("specsim: internal error: the core produced 3 pixels\n", 0), 0u);
}

TEST(SpecsimHelp, EveryCommandAnswersHelpWithExitZero) {
    const char* cmds[] = {"span", "fig8", "demo", "accuracy", "vectors", "render", "render-bench", "plots",
                          "export-obj", "stream-diagram", "bench-stream", "compare", "tables", "highlight",
                          "normalize", "parallax", "bench-lanes"};
    for (const char* c : cmds) {
        for (const char* h : {" --help", " -h", " --n 3 --help"}) {
            const CliRun r = specsim(std::string(c) + h);
            EXPECT_EQ(r.code, 0) << c << h << ": " << r.err;
            EXPECT_TRUE(r.err.empty()) << c << h << ": " << r.err;
            EXPECT_EQ(r.out.rfind("usage: specsim " + std::string(c), 0), 0u) << c << h << ": " << r.out;
            EXPECT_NE(r.out.find("\n  " + std::string(c) + " "), std::string::npos) << c << ": its own block";
            EXPECT_GE(lines(r.out).size(), 2u) << c;
        }
    }
    const CliRun all = specsim("--help");
    EXPECT_EQ(all.code, 0);
    for (const char* c : cmds) EXPECT_NE(all.out.find("\n  " + std::string(c) + " "), std::string::npos) << c;
}

TEST(SpanCommand, ParseComputeReport) {
    Argv a({"--n", "10", "--c", "0.75", "--zeta0", "-0.15", "--dzeta", "0.1", "--len", "3", "--model", "golden"});
    const SpanOptions o = parse_span(a.argc(), a.argv());
    const Model m;
    EXPECT_EQ(o.regs.n, 10u);
    EXPECT_EQ(o.regs.c, m.quantize_c(0.75));
    EXPECT_EQ(o.regs.zeta0, m.quantize_angle(-0.15));
    EXPECT_EQ(o.regs.len, 3u);
    const auto gold = span_pixels(o);
    EXPECT_EQ(gold, m.span(o.regs));
    SpanOptions rtl = o, stream = o;
    rtl.model = "rtl";
    stream.model = "stream";
    EXPECT_EQ(span_pixels(rtl), gold);
    EXPECT_EQ(span_pixels(stream), gold);
    SpanOptions ref = o;
    ref.model = "ref";
    const auto r = span_reference(ref);
    ASSERT_EQ(r.size(), 4u);
    for (int i = 0; i < 4; ++i) EXPECT_DOUBLE_EQ(r[i], 0.75 * std::pow(std::cos(-0.15 + 0.1 * i), 10));
    EXPECT_THROW(span_pixels(ref), std::invalid_argument) << "ref does not run a core";
    const auto csv = lines(span_csv(Format(), gold));
    ASSERT_EQ(csv.size(), 5u);
    EXPECT_EQ(csv[0], "i,value");
    EXPECT_NEAR(std::stod(csv[1].substr(2)), m.out_value(gold[0]), 1e-16);
    Argv bad({"--n", "10"});
    EXPECT_THROW(parse_span(bad.argc(), bad.argv()), UsageError);
    SpanOptions vcd = rtl;
    vcd.vcd = "/nonexistent-dir/w.vcd";
    EXPECT_THROW(span_pixels(vcd), InputError) << "an unwritable waveform is bad input, not an internal error";
}

TEST(AccuracyCommand, WorstErrorsAreTheAnalysisAndTheCoresAndRtlEqualsGolden) {
    AccuracyOptions o;
    o.points = 200;
    const AccuracyResult g = accuracy(o);
    const ErrorTable& e = fig10_errors();
    ASSERT_EQ(g.rows.size(), 6u);
    const AccuracyRow& big = g.rows[3];   // n = 7..1000
    EXPECT_EQ(big.lo, 7u);
    EXPECT_EQ(big.hi, 1000u);
    double q = 0;
    for (unsigned n = 7; n <= 1000; ++n) q = std::max(q, e.q[n]);
    EXPECT_DOUBLE_EQ(big.q, q);
    EXPECT_EQ(e.q[big.q_n], q);
    EXPECT_GE(big.core_rel, 0.0);
    EXPECT_LT(big.core_rel, q + 0.002) << "the core adds at most 0.2 % in the epicentre";
    EXPECT_LT(g.worst_extra, 0.002);
    EXPECT_EQ(g.rows[5].core_abs, 0.0) << "n = 0 gives C exactly";
    UnitDriver unit;
    AccuracyOptions r = o;
    r.model = "rtl";
    const AccuracyResult v = accuracy(r, &unit);
    for (size_t i = 0; i < g.rows.size(); ++i) {
        EXPECT_EQ(v.rows[i].core_rel, g.rows[i].core_rel) << i;
        EXPECT_EQ(v.rows[i].core_abs, g.rows[i].core_abs) << i;
    }
    EXPECT_NE(accuracy_report(o, g).find("| n = 7..1000 (cos^16) |"), std::string::npos);
}

TEST(VectorsCommand, SpansVisitEveryNAndCarryTheModelsPixels) {
    const Model m;
    const auto spans = vector_spans(m, 1100, 5);
    ASSERT_EQ(spans.size(), 1100u);
    std::vector<int> seen(1024, 0);
    for (size_t i = 0; i < 1024; ++i) ++seen[spans[i].n];
    for (unsigned n = 0; n < 1024; ++n) EXPECT_EQ(seen[n], 1) << n;
    const auto l = lines(vectors_text(m, {spans[3]}));
    ASSERT_EQ(l.size(), 1u + 1 + 5 + spans[3].len + 1);
    EXPECT_EQ(std::stoul(l[1], nullptr, 16), 1u);
    const auto px = m.span(spans[3]);
    for (size_t i = 0; i < px.size(); ++i) EXPECT_EQ(std::stoul(l[7 + i], nullptr, 16), px[i]);
    EXPECT_EQ(vector_spans(m, 50, 5).front().c, spans.front().c) << "deterministic in the seed";
}

TEST(DemoCommand, Fig11RunAndRepresentativeSpans) {
    const Fig11Run run = fig11_run();
    ASSERT_EQ(run.rows.size(), 8u);
    EXPECT_EQ(run.pixels, Model().span(run.regs));
    int valid = 0;
    for (bool b : run.rows[7]) valid += b;
    EXPECT_EQ(valid, 4) << "four valid_o pulses for l = 3";
    EXPECT_TRUE(run.rows[0][0]) << "column 0 is the Start cycle";
    EXPECT_NE(fig11_diagram(run).find("valid_o    29 "), std::string::npos);
    UnitDriver d;
    const auto px = representative_spans(d);
    ASSERT_EQ(px.size(), 5u * 9u);
    const ErrorTable& e = fig10_errors();
    for (const DemoPixel& p : px) {
        const double bound = p.in_epicentre ? p.ref * (e.q[p.n] + 0.002) + std::ldexp(1.0, -14)
                                            : 0.9 * (e.a[p.n] + 0.002) + std::ldexp(1.0, -13);
        EXPECT_LE(std::fabs(p.out - p.ref), bound) << "n = " << p.n << " i = " << p.i;
    }
}

TEST(BenchStreamCommand, CyclesPerPixel) {
    const Model m;
    std::mt19937_64 rng(3);
    const auto spans = bench_workload(rng, m, 300, 24);
    std::vector<SpanRegs> longrun;
    for (int i = 0; i < 10; ++i) longrun.insert(longrun.end(), spans.begin(), spans.end());
    const double none = stream_cycles_per_pixel(longrun, Stalls{});
    EXPECT_GE(none, 1.0);
    EXPECT_LT(none, 1.001) << "one pixel per clock across spans";
    EXPECT_GT(stream_cycles_per_pixel(spans, Stalls{1.0, 0.5}), 1.8) << "a sink ready half the time";
    size_t px = 0;
    for (const auto& s : spans) px += s.len + 1;
    const double unit = unit_cycles_per_pixel(spans);
    // two clocks a pixel plus the per-span overhead of the patent's control block (Start to busy_o low)
    EXPECT_GT(unit, 2.0);
    EXPECT_LT(unit, 2.0 + 20.0 * double(spans.size()) / double(px));
    const StreamTrace t = stream_trace();
    std::vector<uint32_t> want;
    for (const auto& s : t.spans)
        for (uint32_t p : m.span(s)) want.push_back(p);
    EXPECT_EQ(t.pixels, want);
}

TEST(CompareCommand, TunedBeatsPatentInTheEpicentre) {
    const auto cols = compare_modes(100, 0);
    ASSERT_EQ(cols.size(), 4u);
    EXPECT_EQ(cols[1].name, "patent");
    EXPECT_EQ(cols[2].name, "tuned");
    EXPECT_EQ(cols[3].name, "pow");
    const Worst patent = worst_of(cols[1].dbl.q, 7, 1000), tuned = worst_of(cols[2].dbl.q, 7, 1000);
    EXPECT_LT(tuned.v, patent.v);
    EXPECT_LE(worst_of(cols[2].core.rel_in, 1, 1000).v, 0.0025 + 1e-3) << "tuned mode's epicentre bound";
    EXPECT_GT(worst_of(cols[0].dbl.q, 3, 1000).v, patent.v) << "one table (the prototype) is worse";
    // pow mode (issue 30): within 0.1 % of C + 2^-14 for every n, in the core; the per-material table is good for
    // small n and not for the narrow highlights of large n
    EXPECT_LE(worst_of(cols[3].core.abs_all, 0, 1023).v, 0.001 + std::ldexp(1.0, -14));
    EXPECT_LT(worst_of(cols[3].core.rel_in, 1, 1023).v, 0.1 * worst_of(cols[2].core.rel_in, 1, 1023).v);
    const CompareLut lut = compare_lut(100, 0);
    EXPECT_LT(worst_of(lut.dbl.abs_all, 1, 1).v, 1e-4);
    EXPECT_GT(worst_of(lut.dbl.abs_all, 500, 1023).v, 0.1);
    EXPECT_GT(worst_of(lut.fixed.abs_all, 0, 0).v, 1e-4) << "12-bit entries: 1.0 saturates at 4095/4096";
    EXPECT_LT(rom_bits(cols[3].f), rom_bits(cols[1].f));
}

TEST(RenderCommand, ComputeGivesTheStatisticsTheReportPrints) {
    Argv a({"--scene", "sphere", "--size", "64", "--out", "x.png", "--stats", "s.json", "--quiet"});
    const RenderOptions o = parse_render(a.argc(), a.argv());
    const render::Scene sc = build_scene(o);
    int cores = 0;
    const RenderResult r = render_compute(o, sc, [&](Mode m) {
        ++cores;
        return make_unit_driver(m);
    });
    EXPECT_EQ(cores, 1) << "the rtl model's core comes from the caller";
    ASSERT_TRUE(r.compared);
    const ModelResult* rtl = r.find(render::SpecModel::rtl);
    const ModelResult* gold = r.find(render::SpecModel::golden);
    const ModelResult* ref = r.find(render::SpecModel::ref);
    ASSERT_TRUE(rtl && gold && ref && r.find(render::SpecModel::prototype) && r.find(render::SpecModel::host));
    EXPECT_EQ(&r.results.front(), rtl) << "the chosen model first";
    EXPECT_EQ(rtl->img.rgb, gold->img.rgb);
    EXPECT_EQ(ref->st.max_abs, 0);
    EXPECT_LE(rtl->st.max_abs, 4);
    EXPECT_GT(rtl->st.covered, 1000u);
    EXPECT_GT(rtl->run.core_cycles, 2 * rtl->run.core_pixels);
    const std::string j = render_stats_json(o, sc, r);
    EXPECT_NE(j.find("\"max_abs\": " + std::to_string(rtl->st.max_abs)), std::string::npos);
    EXPECT_NE(j.find("\"covered_pixels\": " + std::to_string(rtl->st.covered)), std::string::npos);
}
