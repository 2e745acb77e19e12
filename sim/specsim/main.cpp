// specsim - the command-line front end of the UA 71489 specular-shading core.
//
//   specsim span --n N --c C --zeta0 Z --dzeta D --len L [--model rtl|stream|golden|ref] [--mode patent|tuned]
//                [--vcd FILE]
//   specsim fig8 [--all]
//   specsim demo [--vcd FILE] [--diagram FILE]
//   specsim vectors --out FILE [--spans N] [--seed S]
//   specsim render | render-bench | plots | export-obj   (cmd_render.cpp: host side and renderer)
//   specsim highlight | normalize | parallax             (cmd_highlight.cpp, ...: the companion papers)
//
// Bad input: a one-line message on stderr and exit code 2.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <iostream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis.h"
#include "cli.h"
#include "commands.h"
#include "spec_model.h"
#include "Vspec_stream.h"
#include "Vspec_stream_tuned.h"
#include "stream_driver.h"
#include "unit_driver.h"

using namespace spec;

namespace {

const char* kUsage =
    "usage: specsim <command> [options]\n"
    "\n"
    "commands:\n"
    "  span     one span through the core; prints CSV 'i,value', l + 1 rows\n"
    "           --n N        exponent, 0..1023\n"
    "           --c C        intensity factor C, decimal in [0, 1)\n"
    "           --zeta0 Z    start angle in radians (the unscaled -lambda), |Z| < 8\n"
    "           --dzeta D    angle step per pixel in radians\n"
    "           --len L      number of intervals l, 0..65535 (l + 1 pixels)\n"
    "           --model M    rtl (Verilated spec_unit, default) | stream (Verilated spec_stream) |\n"
    "                        golden (bit-exact C++ model) |\n"
    "                        ref (double precision C * max(0, cos(zeta0 + i*dzeta))^n)\n"
    "           --mode M     patent (default: ROM 9 holds sqrt(n/k), Fig. 10 decoder) | tuned (minimax scale and\n"
    "                        table in ROM 9, the RTL Verilated with DECODER_ROM = 1; docs/tuned.md)\n"
    "           --vcd FILE   with --model rtl: write a waveform of the run\n"
    "  fig8     the recomputed Fig. 8 table and q(n), a(n) for the Fig. 10 rule (--all: every n)\n"
    "           --mode tuned: the same with the minimax scale (docs/tuned.md)\n"
    "  demo     the Fig. 11/12 span and representative spans through the RTL beside the double reference\n"
    "           --vcd FILE      waveform of the Fig. 11 run\n"
    "           --diagram FILE  text timing diagram of the Fig. 11 run\n"
    "  accuracy the core's worst error per BRDF range against double precision, every n, beside the\n"
    "           approximation's own error (q, a) and the patent's claims\n"
    "           --model golden|rtl (default golden; equal bit for bit)  --points P (100..100000, default 4000)\n"
    "           --tbl-aw N   (golden only) model a ROM 12 of 2^N positions per table instead of the default\n"
    "           --config C   (golden only) default | up5k (interpolated 4 x 256 tables, docs/stream.md)\n"
    "           --mode M     patent (default) | tuned (docs/tuned.md)\n"
    "           --tables K,K,...  (golden only) ROM 12's powers k instead of 1,2,4,16 (table in ROM 9)\n"
    "  vectors  test vectors from the bit-exact model for the Icarus testbench\n"
    "           --out FILE --spans N (1..5000, default 200) --seed S --mode patent|tuned --tables K,K,...\n";

struct SpanArgs {
    SpanRegs regs;
    double c = 0, zeta0 = 0, dzeta = 0;
    std::string model = "rtl";
    std::string vcd;
    Mode mode = Mode::patent;
};

Mode parse_mode_flag(const std::string& fl, const std::string& v) {
    try {
        return parse_mode(v);
    } catch (const std::invalid_argument& e) {
        throw UsageError(fl + ": " + e.what());
    }
}

SpanArgs parse_span(int argc, char** argv) {
    const Model m;
    const Format& f = m.format();
    SpanArgs s;
    bool have_n = false, have_c = false, have_z = false, have_d = false, have_l = false;
    Args a(argc, argv, 2);
    while (!a.done()) {
        std::string fl = a.flag();
        if (fl == "--n") {
            s.regs.n = static_cast<uint32_t>(parse_int(fl, a.value(fl), 0, (1 << f.n_w) - 1));
            have_n = true;
        } else if (fl == "--c") {
            s.c = parse_double(fl, a.value(fl));
            if (s.c < 0.0 || s.c >= 1.0) throw UsageError("--c: C must be in [0, 1)");
            s.regs.c = m.quantize_c(s.c);
            have_c = true;
        } else if (fl == "--zeta0" || fl == "--dzeta") {
            double v = parse_double(fl, a.value(fl));
            int64_t q;
            try {
                q = m.quantize_angle(v);
            } catch (const std::out_of_range& e) {
                throw UsageError(fl + ": " + e.what());
            }
            if (fl == "--zeta0") { s.zeta0 = v; s.regs.zeta0 = q; have_z = true; }
            else { s.dzeta = v; s.regs.dzeta = q; have_d = true; }
        } else if (fl == "--len") {
            s.regs.len = static_cast<uint32_t>(parse_int(fl, a.value(fl), 0, (int64_t(1) << f.l_w) - 1));
            have_l = true;
        } else if (fl == "--model") {
            s.model = a.value(fl);
            if (s.model != "rtl" && s.model != "stream" && s.model != "golden" && s.model != "ref") {
                throw UsageError("--model: '" + s.model + "' is not one of rtl, stream, golden, ref");
            }
        } else if (fl == "--vcd") {
            s.vcd = a.value(fl);
        } else if (fl == "--mode") {
            s.mode = parse_mode_flag(fl, a.value(fl));
        } else {
            throw UsageError("span: unknown option " + fl);
        }
    }
    if (!have_n) throw UsageError("span: --n is required");
    if (!have_c) throw UsageError("span: --c is required");
    if (!have_z) throw UsageError("span: --zeta0 is required");
    if (!have_d) throw UsageError("span: --dzeta is required");
    if (!have_l) throw UsageError("span: --len is required");
    const int64_t last = s.regs.zeta0 + int64_t(s.regs.len) * s.regs.dzeta;
    if (last < m.angle_min() || last > m.angle_max()) {
        throw UsageError("span: the last angle zeta0 + len*dzeta = " + std::to_string(m.angle_value(last)) +
                         " rad leaves the angle format's range [-8, 8)");
    }
    if (!s.vcd.empty() && s.model != "rtl") throw UsageError("--vcd: only with --model rtl");
    return s;
}

double reference(double c, double angle, unsigned n) {
    return c * std::pow(std::max(0.0, std::cos(angle)), static_cast<double>(n));
}

std::string fmt_out(const Format& f, uint32_t raw) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", f.out_w, std::ldexp(static_cast<double>(raw), -f.out_w));
    return buf;
}

int cmd_span(int argc, char** argv) {
    SpanArgs s = parse_span(argc, argv);
    Format fmt;
    fmt.mode = s.mode;
    const Model m(fmt);
    std::ostringstream o;
    o << "i,value\n";
    if (s.model == "ref") {
        char buf[64];
        for (uint64_t i = 0; i <= s.regs.len; ++i) {
            std::snprintf(buf, sizeof buf, "%.16f", reference(s.c, s.zeta0 + double(i) * s.dzeta, s.regs.n));
            o << i << "," << buf << "\n";
        }
    } else {
        std::vector<uint32_t> px;
        if (s.model == "golden") {
            px = m.span(s.regs);
        } else if (s.model == "stream") {
            std::mt19937_64 rng(1);
            std::vector<StreamPixel> out;
            if (s.mode == Mode::tuned) out = StreamDriver<Vspec_stream_tuned>().run({s.regs}, Stalls{}, rng);
            else out = StreamDriver<Vspec_stream>().run({s.regs}, Stalls{}, rng);
            for (const StreamPixel& p : out) px.push_back(p.value);
        } else {
            px = make_unit_driver(s.mode, s.vcd)->span(s.regs);
        }
        if (px.size() != size_t(s.regs.len) + 1) {
            throw std::runtime_error("the core produced " + std::to_string(px.size()) + " pixels, expected " +
                                     std::to_string(size_t(s.regs.len) + 1));
        }
        for (size_t i = 0; i < px.size(); ++i) o << i << "," << fmt_out(m.format(), px[i]) << "\n";
    }
    std::cout << o.str();
    return 0;
}

int cmd_fig8(int argc, char** argv) {
    bool all = false;
    Mode mode = Mode::patent;
    Args a(argc, argv, 2);
    while (!a.done()) {
        std::string fl = a.flag();
        if (fl == "--all") all = true;
        else if (fl == "--mode") mode = parse_mode_flag(fl, a.value(fl));
        else throw UsageError("fig8: unknown option " + fl);
    }
    std::cout << fig8_report(all, mode);
    return 0;
}

// One-character-per-cycle waveform row.
std::string wave(const std::vector<bool>& v) {
    std::string s;
    for (bool b : v) s += b ? "‾" : "_";
    return s;
}

int cmd_demo(int argc, char** argv) {
    std::string vcd, diagram;
    Args a(argc, argv, 2);
    while (!a.done()) {
        std::string fl = a.flag();
        if (fl == "--vcd") vcd = a.value(fl);
        else if (fl == "--diagram") diagram = a.value(fl);
        else throw UsageError("demo: unknown option " + fl);
    }
    const Model m;
    const Format& f = m.format();

    // Fig. 11/12: a span of l = 3 intervals (four pixels), traced signal by signal.
    {
        SpanArgs s;
        s.c = 0.75; s.zeta0 = -0.15; s.dzeta = 0.1;
        s.regs = SpanRegs{m.quantize_c(s.c), m.quantize_angle(s.dzeta), m.quantize_angle(s.zeta0), 10, 3};
        UnitDriver d(vcd);
        d.steps(2);
        d.write(s.regs);
        // rows: start, 28 (ff39), 37, 36, 34, 35, busy_o, valid_o; column 0 = the cycle Start is applied
        std::vector<std::vector<bool>> rows(8);
        auto record = [&](bool start, const CtrlSignals& c) {
            const bool v[8] = {start, c.s28, c.s37, c.s36, c.s34, c.s35_n, c.busy, c.valid};
            for (int r = 0; r < 8; ++r) rows[r].push_back(v[r]);
        };
        record(true, d.signals());
        d.observer = [&](uint64_t, const CtrlSignals& c) { record(false, c); };
        auto px = d.run();
        d.steps(3);
        const size_t ncyc = rows[0].size();
        std::ostringstream t;
        t << "Fig. 11 run (l = 3, n = 10, C = 0.75, zeta0 = -0.15, dzeta = 0.1), one character per clock,\n"
          << "cycle 0 = the cycle Start is high; from the Verilated spec_unit (specsim demo --diagram)\n\n";
        const char* names[] = {"start      26 ", "ff39       28 ", "strobe     37 ", "select     36 ",
                               "count      34 ", "borrow_n   35 ", "busy_o     28 ", "valid_o    29 "};
        std::string ruler;
        for (size_t c = 0; c < ncyc; ++c) ruler += (c % 5 == 0) ? std::to_string(c % 10) : " ";
        t << "              " << ruler << "\n";
        for (int r = 0; r < 8; ++r) t << names[r] << wave(rows[r]) << "\n";
        t << "\npixels (valid_o): ";
        for (size_t i = 0; i < px.size(); ++i) t << (i ? ", " : "") << fmt_out(f, px[i]);
        t << "\n";
        std::cout << t.str() << "\n";
        if (!diagram.empty()) {
            std::ofstream os(diagram);
            if (!(os << t.str())) throw std::runtime_error("cannot write " + diagram);
        }
        if (!vcd.empty()) std::cout << "waveform of the Fig. 11 run: " << vcd << "\n\n";
    }

    // Representative spans: the highlight crossed from -1.5x to +1.5x the epicentre, 9 pixels.
    UnitDriver d;
    const unsigned ns[] = {1, 3, 10, 100, 1000};
    std::printf("Representative spans through the RTL (C = 0.9, 9 pixels across the highlight):\n");
    for (unsigned n : ns) {
        const double e = epicentre_end(n);
        const double z0 = -1.5 * e, dz = 3.0 * e / 8.0, c = 0.9;
        SpanRegs r{m.quantize_c(c), m.quantize_angle(dz), m.quantize_angle(z0), n, 8};
        auto px = d.span(r);
        std::printf("\n n = %u (k = %d), epicentre |angle| <= %.4f rad\n", n, k_of_n(n), e);
        std::printf("   i   angle(rad)       rtl          ref        error   error(LSB)  in epicentre\n");
        for (size_t i = 0; i < px.size(); ++i) {
            const double ang = z0 + double(i) * dz;
            const double ref = reference(c, ang, n);
            const double out = m.out_value(px[i]);
            std::printf("  %2zu  %+9.5f  %11.8f  %11.8f  %+10.2e  %+9.2f   %s\n", i, ang, out, ref, out - ref,
                        std::ldexp(out - ref, f.out_w), std::fabs(ang) <= e ? "yes" : "no");
        }
    }
    return 0;
}

// The fixed-point core against double precision: for every n, one span from angle 0 to pi/2 (P + 1
// pixels, C = 1 - 2^-16) through the bit-exact model or the RTL; ref = C * cos(angle)^n at the angle the
// core holds in register 8.
int cmd_accuracy(int argc, char** argv) {
    std::string model = "golden";
    long long points = 4000;
    Format fmt;
    Args a(argc, argv, 2);
    while (!a.done()) {
        std::string fl = a.flag();
        if (fl == "--model") {
            model = a.value(fl);
            if (model != "golden" && model != "rtl") throw UsageError("--model: '" + model + "' is not golden or rtl");
        } else if (fl == "--points") {
            points = parse_int(fl, a.value(fl), 100, 100000);
        } else if (fl == "--tbl-aw") {
            fmt.tbl_aw = static_cast<int>(parse_int(fl, a.value(fl), 4, 16));
        } else if (fl == "--config") {
            try {
                const Mode mode = fmt.mode;
                const std::vector<int> tables = fmt.tables;
                fmt = config_format(a.value(fl));
                fmt.mode = mode;
                fmt.tables = tables;
            } catch (const std::invalid_argument& e) {
                throw UsageError(std::string("--config: ") + e.what());
            }
        } else if (fl == "--mode") {
            fmt.mode = parse_mode_flag(fl, a.value(fl));
        } else if (fl == "--tables") {
            fmt.tables = parse_tables(fl, a.value(fl));
        } else {
            throw UsageError("accuracy: unknown option " + fl);
        }
    }
    if (model == "rtl" && (fmt.tbl_aw != Format().tbl_aw || fmt.interp || fmt.tables != patent_tables())) {
        throw UsageError("--tbl-aw, --config, --tables: only with --model golden");
    }
    try {
        fmt.validate();
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("accuracy: ") + e.what());
    }
    const Model m(fmt);
    const Format& f = m.format();
    const ErrorTable& e = mode_errors(f);
    std::unique_ptr<SpanCore> d;
    if (model == "rtl") d = make_unit_driver(f.mode);
    const CoreErrors ce = core_errors(m, static_cast<uint32_t>(points), 0,
                                      d ? SpanRunner([&](const SpanRegs& r) { return d->span(r); }) : SpanRunner());
    const std::vector<double>& rel_in = ce.rel_in;
    const std::vector<double>& abs_all = ce.abs_all;
    struct Range {
        const char* name;
        unsigned lo, hi;
        const char* claim;
    } ranges[] = {{"n = 1 (cos)", 1, 1, "<= 1 %"},          {"n = 2 (cos^2)", 2, 2, "<= 1 %"},
                  {"n = 3..6 (cos^4)", 3, 6, "<= 1 %"},      {"n = 7..1000 (cos^16)", 7, 1000, "<= 1 %, <= 0.6 % (n >= 6)"},
                  {"n = 1001..1023 (cos^16)", 1001, 1023, "-"}, {"n = 0 (C)", 0, 0, "-"}};
    std::string tables;
    for (int k : f.tables) tables += (tables.empty() ? "" : ", ") + std::to_string(k);
    std::printf("Core (%s model, %s mode, tables k = %s, ROM 12 with 2^%d positions per table%s, %lld points per n "
                "on [0, pi/2], C = 1 - 2^-16)\nagainst double precision\n\n",
                model.c_str(), mode_name(f.mode), tables.c_str(), f.tbl_aw, f.interp ? " and interpolation" : "",
                points);
    std::printf("| BRDF range | patent's claim | approximation q (double) | core, max rel. error in epicentre |"
                " approximation a (double) | core, max abs. error / C on [0, pi/2] |\n"
                "|---|---|---|---|---|---|\n");
    for (const auto& rg : ranges) {
        unsigned qn = rg.lo, cn = rg.lo, an = rg.lo, bn = rg.lo;
        for (unsigned n = rg.lo; n <= rg.hi; ++n) {
            if (e.q[n] > e.q[qn]) qn = n;
            if (rel_in[n] > rel_in[cn]) cn = n;
            if (e.a[n] > e.a[an]) an = n;
            if (abs_all[n] > abs_all[bn]) bn = n;
        }
        std::printf("| %s | %s | %.3f %% (n = %u) | %.3f %% (n = %u) | %.3f %% (n = %u) | %.3f %% (n = %u) |\n",
                    rg.name, rg.claim, 100 * e.q[qn], qn, 100 * rel_in[cn], cn, 100 * e.a[an], an,
                    100 * abs_all[bn], bn);
    }
    double worst_extra = 0;
    unsigned wn = 0;
    for (unsigned n = 0; n < 1024; ++n) {
        if (rel_in[n] - e.q[n] > worst_extra) { worst_extra = rel_in[n] - e.q[n]; wn = n; }
    }
    std::printf("\nFixed point adds at most %.4f %% to the approximation's relative error in the epicentre (n = %u).\n",
                100 * worst_extra, wn);
    return 0;
}

int cmd_vectors(int argc, char** argv) {
    std::string out;
    long long spans = 200, seed = 1;
    Format fmt;
    Args a(argc, argv, 2);
    while (!a.done()) {
        std::string fl = a.flag();
        if (fl == "--out") out = a.value(fl);
        else if (fl == "--spans") spans = parse_int(fl, a.value(fl), 1, 5000);
        else if (fl == "--seed") seed = parse_int(fl, a.value(fl), 0, 1LL << 40);
        else if (fl == "--mode") fmt.mode = parse_mode_flag(fl, a.value(fl));
        else if (fl == "--tables") fmt.tables = parse_tables(fl, a.value(fl));
        else throw UsageError("vectors: unknown option " + fl);
    }
    if (out.empty()) throw UsageError("vectors: --out is required");
    const Model m(fmt);
    std::mt19937_64 rng(static_cast<uint64_t>(seed));
    std::ostringstream o;
    char buf[32];
    auto word = [&](uint64_t w) {
        std::snprintf(buf, sizeof buf, "%08llx\n", static_cast<unsigned long long>(w & 0xffffffffULL));
        o << buf;
    };
    o << "// spans for tests/iverilog/tb_spec_unit.v: count, then per span c, dzeta, zeta0, n, len, pixels\n";
    word(static_cast<uint64_t>(spans));
    for (long long s = 0; s < spans; ++s) {
        SpanRegs r;
        r.n = (s < 1024) ? static_cast<uint32_t>((s * 37) % 1024) : static_cast<uint32_t>(rng() % 1024);
        r.c = static_cast<uint32_t>(rng() % 65536);
        r.len = static_cast<uint32_t>(rng() % 24);
        const double e = epicentre_end(r.n);
        std::uniform_real_distribution<double> z(-2.0 * e - 0.1, 2.0 * e + 0.1);
        r.zeta0 = m.quantize_angle(z(rng));
        r.dzeta = m.quantize_angle((z(rng) - m.angle_value(r.zeta0)) / (r.len ? r.len : 1));
        word(r.c);
        word(static_cast<uint64_t>(r.dzeta));
        word(static_cast<uint64_t>(r.zeta0));
        word(r.n);
        word(r.len);
        for (uint32_t p : m.span(r)) word(p);
    }
    std::ofstream os(out + ".tmp");
    os << o.str();
    os.close();
    if (!os || std::rename((out + ".tmp").c_str(), out.c_str()) != 0) {
        std::remove((out + ".tmp").c_str());
        throw std::runtime_error("cannot write " + out);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        if (argc < 2) throw UsageError("missing command (span, fig8, demo, accuracy, vectors); see specsim --help");
        const std::string cmd = argv[1];
        if (cmd == "--help" || cmd == "-h" || cmd == "help") {
            std::cout << kUsage << kRenderUsage << kBenchUsage << kTunedUsage << kMethodsUsage << kSetupUsage << kBenchShaderUsage << kSetupAccuracyUsage;
            return 0;
        }
        if (cmd == "span") return cmd_span(argc, argv);
        if (cmd == "fig8") return cmd_fig8(argc, argv);
        if (cmd == "demo") return cmd_demo(argc, argv);
        if (cmd == "vectors") return cmd_vectors(argc, argv);
        if (cmd == "accuracy") return cmd_accuracy(argc, argv);
        if (cmd == "render") return cmd_render(argc, argv);
        if (cmd == "render-bench") return cmd_render_bench(argc, argv);
        if (cmd == "bench-stream") return cmd_bench_stream(argc, argv);
        if (cmd == "stream-diagram") return cmd_stream_diagram(argc, argv);
        if (cmd == "plots") return cmd_plots(argc, argv);
        if (cmd == "export-obj") return cmd_export_obj(argc, argv);
        if (cmd == "highlight") return cmd_highlight(argc, argv);
        if (cmd == "normalize") return cmd_normalize(argc, argv);
        if (cmd == "parallax") return cmd_parallax(argc, argv);
        if (cmd == "compare") return cmd_compare(argc, argv);
        if (cmd == "tables") return cmd_tables(argc, argv);
        if (cmd == "setup") return cmd_setup(argc, argv);
        if (cmd == "bench-shader") return cmd_bench_shader(argc, argv);
        if (cmd == "setup-accuracy") return cmd_setup_accuracy(argc, argv);
        throw UsageError("unknown command '" + cmd + "'; see specsim --help");
    } catch (const std::exception& e) {   // UsageError and every other error: one line, exit 2
        std::cerr << "specsim: " << spec::printable(e.what()) << "\n";
        return 2;
    }
}
