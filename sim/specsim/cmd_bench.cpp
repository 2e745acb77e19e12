// specsim bench-stream: cycles per pixel of spec_stream and spec_unit, and simulation speed under
// Verilator and Icarus Verilog, on one workload (make bench-stream).
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "Vspec_stream.h"
#include "analysis.h"
#include "cli.h"
#include "commands.h"
#include "spec_model.h"
#include "stream_driver.h"
#include "unit_driver.h"

namespace spec {

const char* const kBenchUsage =
    "  stream-diagram  a text timing diagram of spec_stream's AXI4-Stream ports from a simulation\n"
    "                --out FILE (also print it)\n"
    "  bench-stream  cycles per pixel of spec_stream (no stalls, random stalls) and spec_unit, and simulated\n"
    "                pixels per second under Verilator and Icarus Verilog on one workload (make bench-stream)\n"
    "                --spans N (100..3000, default 2000) --runs R (1..15, default 5) --seed S\n"
    "                --src DIR (the repository, for Icarus; default: where specsim was built from)\n"
    "                --json FILE (also write the figures as JSON)\n";

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t k = v.size() / 2;
    return v.size() % 2 ? v[k] : 0.5 * (v[k - 1] + v[k]);
}

// Spans around the highlight of a random n, lengths 0..max_len; the same generator for every simulator.
std::vector<SpanRegs> workload(std::mt19937_64& rng, const Model& m, size_t count, uint32_t max_len) {
    std::vector<SpanRegs> v;
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (size_t i = 0; i < count; ++i) {
        SpanRegs r;
        r.n = static_cast<uint32_t>(rng() % 1024);
        r.c = static_cast<uint32_t>(rng() & 0xffff);
        r.len = static_cast<uint32_t>(rng() % (max_len + 1));
        const double reach = std::min(M_PI, 4.0 * epicentre_end(r.n));
        r.zeta0 = m.quantize_angle(reach * u(rng));
        r.dzeta = m.quantize_angle(r.len ? (reach * u(rng) - m.angle_value(r.zeta0)) / r.len : 0.0);
        v.push_back(r);
    }
    return v;
}

// The vector file of tests/iverilog/tb_*.v (as `specsim vectors` writes it).
void write_vectors(const std::string& path, const Model& m, const std::vector<SpanRegs>& spans) {
    std::ofstream os(path);
    char buf[32];
    auto word = [&](uint64_t w) {
        std::snprintf(buf, sizeof buf, "%08llx\n", static_cast<unsigned long long>(w & 0xffffffffULL));
        os << buf;
    };
    word(spans.size());
    for (const auto& r : spans) {
        word(r.c);
        word(static_cast<uint64_t>(r.dzeta));
        word(static_cast<uint64_t>(r.zeta0));
        word(r.n);
        word(r.len);
        for (uint32_t p : m.span(r)) word(p);
    }
    if (!os) throw std::runtime_error("cannot write " + path);
}

int run_quiet(const std::string& cmd) {
    const int st = std::system((cmd + " > /dev/null 2>&1").c_str());
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

}  // namespace

int cmd_bench_stream(int argc, char** argv) {
    long long nspans = 2000, runs = 5, seed = 1;
    std::string src = SPEC_SOURCE_DIR, json;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string fl = a.flag();
        if (fl == "--spans") nspans = parse_int(fl, a.value(fl), 100, 3000);
        else if (fl == "--runs") runs = parse_int(fl, a.value(fl), 1, 15);
        else if (fl == "--seed") seed = parse_int(fl, a.value(fl), 0, 1LL << 40);
        else if (fl == "--src") src = a.value(fl);
        else if (fl == "--json") json = a.value(fl);
        else throw UsageError("bench-stream: unknown option " + fl);
    }
    const Model m;
    std::mt19937_64 rng(static_cast<uint64_t>(seed));
    const auto spans = workload(rng, m, static_cast<size_t>(nspans), 24);
    size_t pixels = 0;
    for (const auto& r : spans) pixels += r.len + 1;

    // 1. cycles per pixel (exact counts, independent of the machine)
    struct Cpp {
        const char* what;
        double in_valid, out_ready;
        double cpp;
    } cpp[] = {{"spec_stream, no stalls", 1.0, 1.0, 0},
               {"spec_stream, source and sink ready 90 % of cycles", 0.9, 0.9, 0},
               {"spec_stream, sink ready 50 % of cycles", 1.0, 0.5, 0}};
    // a long run for the no-stall figure: 50 x the workload, back to back
    std::vector<SpanRegs> longrun;
    for (int i = 0; i < 50; ++i) longrun.insert(longrun.end(), spans.begin(), spans.end());
    for (auto& c : cpp) {
        StreamDriver<Vspec_stream> d;
        std::mt19937_64 r2(7);
        const auto& w = c.in_valid == 1.0 && c.out_ready == 1.0 ? longrun : spans;
        size_t px = 0;
        for (const auto& s : w) px += s.len + 1;
        const uint64_t c0 = d.cycle();
        auto out = d.run(w, Stalls{c.in_valid, c.out_ready}, r2);
        if (out.size() != px) throw std::runtime_error("bench: spec_stream lost pixels");
        c.cpp = double(d.cycle() - c0) / double(px);
    }
    double unit_cpp;
    {
        UnitDriver d;
        const uint64_t c0 = d.cycle();
        size_t px = 0;
        for (const auto& s : spans) px += d.span(s).size();
        unit_cpp = double(d.cycle() - c0) / double(px);
    }

    // 2. simulation speed: median wall time of `runs` runs of the whole workload
    std::vector<double> t_unit, t_stream, t_ivl_unit, t_ivl_stream;
    for (long long r = 0; r < runs; ++r) {
        {
            UnitDriver d;
            const auto t0 = std::chrono::steady_clock::now();
            for (const auto& s : spans) d.span(s);
            t_unit.push_back(seconds_since(t0));
        }
        {
            StreamDriver<Vspec_stream> d;
            std::mt19937_64 r2(7);
            const auto t0 = std::chrono::steady_clock::now();
            d.run(spans, Stalls{}, r2);
            t_stream.push_back(seconds_since(t0));
        }
    }
    char dir[] = "/tmp/specbench.XXXXXX";
    if (!mkdtemp(dir)) throw std::runtime_error("cannot make a temporary directory");
    const std::string work = dir;
    write_vectors(work + "/vectors.hex", m, spans);
    bool icarus = true;
    for (const char* tb : {"tb_spec_unit", "tb_spec_stream"}) {
        const std::string cmd = "iverilog -g2005 -I" + src + "/rom -o " + work + "/" + tb + ".vvp -s " + tb + " " +
                                src + "/tests/iverilog/" + tb + ".v " + src + "/rtl/*.v";
        if (run_quiet(cmd) != 0) icarus = false;
    }
    if (icarus) {
        for (long long r = 0; r < runs; ++r) {
            for (int k = 0; k < 2; ++k) {
                const std::string tb = k == 0 ? "tb_spec_unit" : "tb_spec_stream";
                const auto t0 = std::chrono::steady_clock::now();
                const int rc = run_quiet("cd " + src + " && vvp -n " + work + "/" + tb + ".vvp +vectors=" + work +
                                         "/vectors.hex +stall=0");
                if (rc != 0) throw std::runtime_error("bench: Icarus " + tb + " failed");
                (k == 0 ? t_ivl_unit : t_ivl_stream).push_back(seconds_since(t0));
            }
        }
    }
    run_quiet("rm -rf " + work);

    const double pu = pixels / median(t_unit), ps = pixels / median(t_stream);
    std::printf("Workload: %lld spans, %zu pixels (l = 0..24, random n), %lld runs, medians\n\n", nspans, pixels,
                runs);
    std::printf("| core and stalls | clock cycles per pixel |\n|---|---|\n");
    for (const auto& c : cpp) std::printf("| %s | %.4f |\n", c.what, c.cpp);
    std::printf("| spec_unit (patent control block, span by span) | %.4f |\n\n", unit_cpp);
    std::printf("| simulator | core | simulated pixels per second | ratio to Verilator spec_stream |\n"
                "|---|---|---|---|\n");
    std::printf("| Verilator 5.006 | spec_stream | %.3g | 1 |\n", ps);
    std::printf("| Verilator 5.006 | spec_unit | %.3g | %.2f |\n", pu, pu / ps);
    double iu = 0, is = 0;
    if (icarus) {
        iu = pixels / median(t_ivl_unit);
        is = pixels / median(t_ivl_stream);
        std::printf("| Icarus 11 (vvp, incl. start-up) | spec_stream | %.3g | %.3f |\n", is, is / ps);
        std::printf("| Icarus 11 (vvp, incl. start-up) | spec_unit | %.3g | %.3f |\n", iu, iu / ps);
    } else {
        std::printf("| Icarus 11 | - | not run (iverilog failed; is it installed?) | - |\n");
    }
    if (!json.empty()) {
        std::ofstream os(json + ".tmp");
        os << "{\"spans\": " << nspans << ", \"pixels\": " << pixels << ", \"runs\": " << runs
           << ", \"cycles_per_pixel\": {\"stream_no_stalls\": " << cpp[0].cpp << ", \"stream_stalls_90\": "
           << cpp[1].cpp << ", \"stream_sink_50\": " << cpp[2].cpp << ", \"unit\": " << unit_cpp
           << "}, \"pixels_per_second\": {\"verilator_stream\": " << ps << ", \"verilator_unit\": " << pu
           << ", \"icarus_stream\": " << is << ", \"icarus_unit\": " << iu << "}}\n";
        os.close();
        if (!os || std::rename((json + ".tmp").c_str(), json.c_str()) != 0) throw std::runtime_error("cannot write " + json);
    }
    return 0;
}

// Three spans (l = 2, 0, 1) through spec_stream with a two-cycle sink stall, drawn one character per clock.
int cmd_stream_diagram(int argc, char** argv) {
    std::string out;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string fl = a.flag();
        if (fl == "--out") out = a.value(fl);
        else throw UsageError("stream-diagram: unknown option " + fl);
    }
    const Model m;
    StreamDriver<Vspec_stream> d;
    auto& t = d.top();
    const std::vector<SpanRegs> spans = {
        SpanRegs{m.quantize_c(0.9), m.quantize_angle(0.05), m.quantize_angle(-0.05), 10, 2},
        SpanRegs{m.quantize_c(0.5), 0, 0, 0, 0},
        SpanRegs{m.quantize_c(0.7), m.quantize_angle(0.1), m.quantize_angle(0.0), 3, 1}};
    std::vector<std::string> rows(7);
    std::vector<uint32_t> px;
    size_t next = 0;
    const int ncyc = 32;
    for (int c = 0; c < ncyc; ++c) {
        t.s_axis_tvalid = next < spans.size();
        if (next < spans.size()) {
            uint32_t w[kDescWords];
            pack_descriptor(spans[next], w);
            for (int i = 0; i < kDescWords; ++i) t.s_axis_tdata[i] = w[i];
        }
        t.m_axis_tready = !(c == 24 || c == 25);  // the sink stalls for two cycles
        t.eval();
        const bool in_fire = t.s_axis_tvalid && t.s_axis_tready;
        const bool out_fire = t.m_axis_tvalid && t.m_axis_tready;
        const bool v[7] = {bool(t.s_axis_tvalid), bool(t.s_axis_tready), in_fire, bool(t.m_axis_tvalid),
                           bool(t.m_axis_tready), bool(t.m_axis_tlast && t.m_axis_tvalid), out_fire};
        for (int r = 0; r < 7; ++r) rows[r] += v[r] ? "\u203e" : "_";
        if (out_fire) px.push_back(t.m_axis_tdata);
        d.step();
        if (in_fire) ++next;
    }
    std::ostringstream o;
    o << "spec_stream: descriptors l = 2, 0, 1 back to back, the sink stalls in cycles 24-25; one character per\n"
      << "clock, from the Verilated spec_stream (specsim stream-diagram)\n\n";
    std::string ruler;
    for (int c = 0; c < ncyc; ++c) ruler += (c % 5 == 0) ? std::to_string(c % 10) : " ";
    o << "                 " << ruler << "\n";
    const char* names[] = {"s_axis_tvalid    ", "s_axis_tready    ", "  descriptor in  ", "m_axis_tvalid    ",
                           "m_axis_tready    ", "m_axis_tlast     ", "  pixel out      "};
    for (int r = 0; r < 7; ++r) o << names[r] << rows[r] << "\n";
    o << "\npixels out: ";
    for (size_t i = 0; i < px.size(); ++i) o << (i ? ", " : "") << px[i];
    o << "  (UQ0.16 codes; model: ";
    size_t k = 0;
    for (const auto& s : spans)
        for (uint32_t p : m.span(s)) o << (k++ ? ", " : "") << p;
    o << ")\n";
    std::cout << o.str();
    if (!out.empty()) {
        std::ofstream os(out);
        if (!(os << o.str())) throw std::runtime_error("cannot write " + out);
    }
    return 0;
}

}  // namespace spec
