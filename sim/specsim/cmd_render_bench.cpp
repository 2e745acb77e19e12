// cmd_render_bench.cpp - specsim render-bench (make bench-render): the speed of the render's stages, medians
// of runs. Speed is measured here, never asserted by a test (docs: benchmarks, not timed tests).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "cli.h"
#include "commands.h"
#include "fileutil.h"
#include "raster.h"
#include "scene.h"
#include "shade.h"
#include "unit_driver.h"

namespace spec {

namespace {
struct BenchOptions {
    std::string scene = "default", json;
    int size = 512, runs = 5;
};

BenchOptions parse_render_bench(int argc, char** argv) {
    BenchOptions o;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string f = a.flag();
        if (f == "--size") o.size = int(parse_int(f, a.value(f), 16, 4096));
        else if (f == "--runs") o.runs = int(parse_int(f, a.value(f), 3, 15));
        else if (f == "--scene") o.scene = a.value(f);
        else if (f == "--json") o.json = a.value(f);
        else throw UsageError("render-bench: unknown option " + f);
    }
    return o;
}

double now_s() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t k = v.size() / 2;
    return v.size() % 2 ? v[k] : 0.5 * (v[k - 1] + v[k]);
}

// Runs f repeatedly for at least min_s seconds; returns (work items done) / (seconds).
template <class F>
double rate(F f, double min_s) {
    double done = 0;
    const double t0 = now_s();
    double t = t0;
    do {
        done += f();
        t = now_s();
    } while (t - t0 < min_s);
    return done / (t - t0);
}

struct BenchResult {
    size_t spans = 0;
    uint64_t model_px = 0;
    std::vector<double> host_sps, gold_pps, rtl_pps, rtl_cps, ref_pps, frame_rtl, frame_gold;
};

BenchResult render_bench(const BenchOptions& o, const render::Scene& sc) {
    BenchResult b;
    const render::Frame fr = render::rasterize(sc, o.size, o.size);
    const Model core;
    b.spans = fr.spans.size();
    for (const auto& sp : fr.spans) b.model_px += sp.l + 1;
    UnitDriver unit;
    for (int r = 0; r < o.runs; ++r) {
        b.host_sps.push_back(rate([&] {
            double acc = 0;
            for (const auto& sp : fr.spans) {
                const auto& m = sc.objects[sp.obj].mat;
                acc += host::setup_span(core, sp.ends, sc.light.intensity * m.ks, m.n, sp.l).c;
            }
            if (acc < 0) std::printf("?");  // keep the work observable
            return double(fr.spans.size());
        }, 0.3));
        render::SpecRun last;
        b.gold_pps.push_back(rate([&] {
            last = render::shade_specular(sc, fr, render::SpecModel::golden, render::RgbMode::once);
            return double(last.core_pixels);
        }, 0.3));
        uint64_t cycles = 0;
        const double t0 = now_s();
        b.rtl_pps.push_back(rate([&] {
            last = render::shade_specular(sc, fr, render::SpecModel::rtl, &unit, render::RgbMode::once);
            cycles += last.core_cycles;
            return double(last.core_pixels);
        }, 0.3));
        b.rtl_cps.push_back(double(cycles) / (now_s() - t0));
        b.ref_pps.push_back(rate([&] {
            last = render::shade_specular(sc, fr, render::SpecModel::ref, render::RgbMode::once);
            return double(last.core_pixels);
        }, 0.3));
        for (auto m : {render::SpecModel::rtl, render::SpecModel::golden}) {
            const double t1 = now_s();
            const render::Frame f2 = render::rasterize(sc, o.size, o.size);
            const render::Shading base = render::shade_base(sc, f2);
            const render::Image img = render::compose(
                base, render::shade_specular(sc, f2, m, m == render::SpecModel::rtl ? &unit : nullptr,
                                             render::RgbMode::once));
            (m == render::SpecModel::rtl ? b.frame_rtl : b.frame_gold).push_back(now_s() - t1);
        }
    }
    return b;
}

void report_render_bench(const BenchOptions& o, const BenchResult& b) {
    auto line = [](const char* what, const std::vector<double>& v, const char* unit) {
        const auto mm = std::minmax_element(v.begin(), v.end());
        std::printf("  %-34s %12.4g %-10s (runs %.3g .. %.3g)\n", what, median(v), unit, *mm.first, *mm.second);
    };
    line("host: span setup", b.host_sps, "spans/s");
    line("golden model: specular stage", b.gold_pps, "pixels/s");
    line("rtl (Verilated spec_unit): specular", b.rtl_pps, "pixels/s");
    line("rtl: simulated clock", b.rtl_cps, "cycles/s");
    line("ref (double, per-pixel slerp)", b.ref_pps, "pixels/s");
    line("whole frame with rtl", b.frame_rtl, "s");
    line("whole frame with golden", b.frame_gold, "s");
    const double host_s = double(b.spans) / median(b.host_sps), rtl_s = double(b.model_px) / median(b.rtl_pps);
    std::printf("  ratios of medians: golden / rtl = %.1f; ref / rtl = %.1f; host setup = %.0f %% of the rtl specular "
                "stage's time; %.2f rtl clock cycles per pixel (2 per pixel + per-span overhead, %.2f pixels a span)\n",
                median(b.gold_pps) / median(b.rtl_pps), median(b.ref_pps) / median(b.rtl_pps), 100.0 * host_s / rtl_s,
                median(b.rtl_cps) / median(b.rtl_pps), double(b.model_px) / double(b.spans));
    if (o.json.empty()) return;
    // The figures as JSON (make bench-render: docs/data/bench_render.json, which docs/renderer.md's table comes
    // from): per stage the median and the range of the runs.
    render::write_atomic(o.json, [&](const std::string& tmp) {
        std::ofstream os(tmp);
        os.precision(6);
        auto stage = [&](const char* name, const std::vector<double>& v, bool last) {
            const auto mm = std::minmax_element(v.begin(), v.end());
            os << "    \"" << name << "\": {\"median\": " << median(v) << ", \"min\": " << *mm.first << ", \"max\": "
               << *mm.second << "}" << (last ? "\n" : ",\n");
        };
        os << "{\n  \"scene\": \"" << o.scene << "\",\n  \"size\": " << o.size << ",\n  \"runs\": " << o.runs
           << ",\n  \"spans\": " << b.spans << ",\n  \"model_pixels\": " << b.model_px << ",\n  \"stages\": {\n";
        stage("host_spans_per_s", b.host_sps, false);
        stage("golden_pixels_per_s", b.gold_pps, false);
        stage("rtl_pixels_per_s", b.rtl_pps, false);
        stage("rtl_cycles_per_s", b.rtl_cps, false);
        stage("ref_pixels_per_s", b.ref_pps, false);
        stage("frame_rtl_s", b.frame_rtl, false);
        stage("frame_golden_s", b.frame_gold, true);
        os << "  },\n  \"golden_over_rtl\": " << median(b.gold_pps) / median(b.rtl_pps)
           << ",\n  \"ref_over_rtl\": " << median(b.ref_pps) / median(b.rtl_pps) << "\n}\n";
        os.close();
        if (!os) throw InputError("cannot write " + o.json);
    });
}
}  // namespace

int cmd_render_bench(int argc, char** argv) {
    const BenchOptions o = parse_render_bench(argc, argv);
    render::Scene sc = render::make_scene(o.scene);
    sc.validate();
    {
        const render::Frame fr = render::rasterize(sc, o.size, o.size);
        uint64_t px = 0;
        for (const auto& sp : fr.spans) px += sp.l + 1;
        std::printf("render-bench: scene %s, %dx%d, %zu spans, %llu pixels through the model per frame, "
                    "%d runs (medians; each run at least 0.3 s)\n",
                    o.scene.c_str(), o.size, o.size, fr.spans.size(), (unsigned long long)px, o.runs);
        std::fflush(stdout);
    }
    report_render_bench(o, render_bench(o, sc));
    return 0;
}

}  // namespace spec
