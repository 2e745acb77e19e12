// cmd_bench_stream.cpp - specsim bench-stream (make bench-stream): cycles per pixel of spec_stream and
// spec_unit, and simulation speed under Verilator and Icarus Verilog, on one workload.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "Vspec_stream.h"
#include "analysis.h"
#include "cli.h"
#include "cmd_bench.h"
#include "cmd_vectors.h"
#include "commands.h"
#include "fileutil.h"
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

std::vector<SpanRegs> bench_workload(std::mt19937_64& rng, const Model& m, size_t count, uint32_t max_len) {
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

double stream_cycles_per_pixel(const std::vector<SpanRegs>& spans, const Stalls& st, uint64_t seed) {
    StreamDriver<Vspec_stream> d;
    std::mt19937_64 rng(seed);
    size_t px = 0;
    for (const auto& s : spans) px += s.len + 1;
    const uint64_t c0 = d.cycle();
    const auto out = d.run(spans, st, rng);
    if (out.size() != px) throw std::runtime_error("bench: spec_stream lost pixels");
    // run() watches kDrainCycles more after the last pixel: not the workload's
    return double(d.cycle() - c0 - StreamDriver<Vspec_stream>::kDrainCycles) / double(px);
}

double unit_cycles_per_pixel(const std::vector<SpanRegs>& spans) {
    UnitDriver d;
    const uint64_t c0 = d.cycle();
    size_t px = 0;
    for (const auto& s : spans) px += d.span(s).size();
    return double(d.cycle() - c0) / double(px);
}

namespace {
struct BenchStreamOptions {
    long long spans = 2000, runs = 5, seed = 1;
    std::string src = SPEC_SOURCE_DIR, json;
};

BenchStreamOptions parse_bench_stream(int argc, char** argv) {
    BenchStreamOptions o;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string fl = a.flag();
        if (fl == "--spans") o.spans = parse_int(fl, a.value(fl), 100, 3000);
        else if (fl == "--runs") o.runs = parse_int(fl, a.value(fl), 1, 15);
        else if (fl == "--seed") o.seed = parse_int(fl, a.value(fl), 0, 1LL << 40);
        else if (fl == "--src") o.src = a.value(fl);
        else if (fl == "--json") o.json = a.value(fl);
        else throw UsageError("bench-stream: unknown option " + fl);
    }
    return o;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t k = v.size() / 2;
    return v.size() % 2 ? v[k] : 0.5 * (v[k - 1] + v[k]);
}

int run_quiet(const std::string& cmd) {
    const int st = std::system((cmd + " > /dev/null 2>&1").c_str());
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

struct Cpp {
    const char* what;
    double in_valid, out_ready;
    double cpp;
};

struct BenchStreamResult {
    size_t pixels = 0;
    std::vector<Cpp> cpp;
    double unit_cpp = 0;
    double pu = 0, ps = 0, iu = 0, is = 0;   // pixels/s: Verilator unit, stream; Icarus unit, stream
    bool icarus = false;
};

BenchStreamResult bench_stream(const BenchStreamOptions& o) {
    const Model m;
    std::mt19937_64 rng(static_cast<uint64_t>(o.seed));
    const auto spans = bench_workload(rng, m, static_cast<size_t>(o.spans), 24);
    BenchStreamResult r;
    for (const auto& s : spans) r.pixels += s.len + 1;

    // 1. cycles per pixel (exact counts, independent of the machine); a long run for the no-stall figure:
    // 50 x the workload, back to back
    r.cpp = {{"spec_stream, no stalls", 1.0, 1.0, 0},
             {"spec_stream, source and sink ready 90 % of cycles", 0.9, 0.9, 0},
             {"spec_stream, sink ready 50 % of cycles", 1.0, 0.5, 0}};
    std::vector<SpanRegs> longrun;
    for (int i = 0; i < 50; ++i) longrun.insert(longrun.end(), spans.begin(), spans.end());
    for (auto& c : r.cpp) {
        const bool none = c.in_valid == 1.0 && c.out_ready == 1.0;
        c.cpp = stream_cycles_per_pixel(none ? longrun : spans, Stalls{c.in_valid, c.out_ready});
    }
    r.unit_cpp = unit_cycles_per_pixel(spans);

    // 2. simulation speed: median wall time of `runs` runs of the whole workload
    std::vector<double> t_unit, t_stream, t_ivl_unit, t_ivl_stream;
    for (long long k = 0; k < o.runs; ++k) {
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
    {
        std::ofstream vf(work + "/vectors.hex");
        vf << vectors_text(m, spans);
        if (!vf) throw std::runtime_error("cannot write " + work + "/vectors.hex");
    }
    r.icarus = true;
    for (const char* tb : {"tb_spec_unit", "tb_spec_stream"}) {
        const std::string cmd = "iverilog -g2005 -I" + o.src + "/rom -o " + work + "/" + tb + ".vvp -s " + tb + " " +
                                o.src + "/tests/iverilog/" + tb + ".v " + o.src + "/rtl/*.v";
        if (run_quiet(cmd) != 0) r.icarus = false;
    }
    if (r.icarus) {
        for (long long k = 0; k < o.runs; ++k) {
            for (int u = 0; u < 2; ++u) {
                const std::string tb = u == 0 ? "tb_spec_unit" : "tb_spec_stream";
                const auto t0 = std::chrono::steady_clock::now();
                const int rc = run_quiet("cd " + o.src + " && vvp -n " + work + "/" + tb + ".vvp +vectors=" + work +
                                         "/vectors.hex +stall=0");
                if (rc != 0) throw std::runtime_error("bench: Icarus " + tb + " failed");
                (u == 0 ? t_ivl_unit : t_ivl_stream).push_back(seconds_since(t0));
            }
        }
    }
    run_quiet("rm -rf " + work);
    r.pu = r.pixels / median(t_unit);
    r.ps = r.pixels / median(t_stream);
    if (r.icarus) {
        r.iu = r.pixels / median(t_ivl_unit);
        r.is = r.pixels / median(t_ivl_stream);
    }
    return r;
}

void report_bench_stream(const BenchStreamOptions& o, const BenchStreamResult& r) {
    std::printf("Workload: %lld spans, %zu pixels (l = 0..24, random n), %lld runs, medians\n\n", o.spans, r.pixels,
                o.runs);
    std::printf("| core and stalls | clock cycles per pixel |\n|---|---|\n");
    for (const auto& c : r.cpp) std::printf("| %s | %.4f |\n", c.what, c.cpp);
    std::printf("| spec_unit (patent control block, span by span) | %.4f |\n\n", r.unit_cpp);
    std::printf("| simulator | core | simulated pixels per second | ratio to Verilator spec_stream |\n"
                "|---|---|---|---|\n");
    std::printf("| Verilator 5.006 | spec_stream | %.3g | 1 |\n", r.ps);
    std::printf("| Verilator 5.006 | spec_unit | %.3g | %.2f |\n", r.pu, r.pu / r.ps);
    if (r.icarus) {
        std::printf("| Icarus 11 (vvp, incl. start-up) | spec_stream | %.3g | %.3f |\n", r.is, r.is / r.ps);
        std::printf("| Icarus 11 (vvp, incl. start-up) | spec_unit | %.3g | %.3f |\n", r.iu, r.iu / r.ps);
    } else {
        std::printf("| Icarus 11 | - | not run (iverilog failed; is it installed?) | - |\n");
    }
    if (!o.json.empty()) {
        render::write_atomic(o.json, [&](const std::string& tmp) {
            std::ofstream os(tmp);
            os << "{\"spans\": " << o.spans << ", \"pixels\": " << r.pixels << ", \"runs\": " << o.runs
               << ", \"cycles_per_pixel\": {\"stream_no_stalls\": " << r.cpp[0].cpp << ", \"stream_stalls_90\": "
               << r.cpp[1].cpp << ", \"stream_sink_50\": " << r.cpp[2].cpp << ", \"unit\": " << r.unit_cpp
               << "}, \"pixels_per_second\": {\"verilator_stream\": " << r.ps << ", \"verilator_unit\": " << r.pu
               << ", \"icarus_stream\": " << r.is << ", \"icarus_unit\": " << r.iu << "}}\n";
            os.close();
            if (!os) throw InputError("cannot write " + o.json);
        });
    }
}
}  // namespace

int cmd_bench_stream(int argc, char** argv) {
    const BenchStreamOptions o = parse_bench_stream(argc, argv);
    report_bench_stream(o, bench_stream(o));
    return 0;
}

}  // namespace spec
