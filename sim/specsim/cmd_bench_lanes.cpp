// cmd_bench_lanes.cpp - specsim bench-lanes (make bench-stream): pixels per clock of spec_stream with LANES =
// 1, 2, 4 and PACK = 0, 1 on the spans a scene gives at several frame sizes (issue 14, docs/stream.md).
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "Vspec_stream.h"
#include "Vspec_stream_l2.h"
#include "Vspec_stream_l2p.h"
#include "Vspec_stream_l4.h"
#include "Vspec_stream_l4p.h"
#include "cli.h"
#include "cmd_bench.h"
#include "commands.h"
#include "fileutil.h"
#include "raster.h"
#include "scene.h"
#include "shade.h"

namespace spec {

const char* const kBenchLanesUsage =
    "  bench-lanes   pixels per clock of spec_stream with LANES = 1, 2, 4 (PACK = 0 and 1) on the spans of a\n"
    "                scene, no stalls (make bench-stream)\n"
    "                --scene NAME (default: default) --sizes WxH,... (default 512x512,1920x1080,3840x2160)\n"
    "                --json FILE (also write the figures as JSON)\n";

namespace {
// A SpanCore that keeps the registers of every span the renderer sends (the model computes the pixels).
class Recorder : public SpanCore {
public:
    explicit Recorder(const Model& m) : m_(m) {}
    std::vector<uint32_t> span(const SpanRegs& r) override {
        regs.push_back(r);
        return m_.span(r);
    }
    uint64_t cycle() const override { return 0; }
    std::vector<SpanRegs> regs;

private:
    const Model& m_;
};

template <class V, int L, bool P>
LanesFigure run_lanes(const char* name, const std::vector<SpanRegs>& spans, uint64_t pixels) {
    StreamDriver<V, L, P> d;
    std::mt19937_64 rng(1);
    const uint64_t c0 = d.cycle(), b0 = d.beats();
    const auto out = d.run(spans, Stalls{}, rng);
    if (out.size() != pixels) throw std::runtime_error(std::string("bench-lanes: ") + name + " lost pixels");
    // run() watches kDrainCycles more after the last pixel: not the workload's
    const uint64_t cycles = d.cycle() - c0 - StreamDriver<V, L, P>::kDrainCycles;
    return {name, L, P, cycles, d.beats() - b0, double(pixels) / double(cycles)};
}

struct BenchLanesOptions {
    std::string scene = "default", json;
    std::vector<std::pair<int, int>> sizes{{512, 512}, {1920, 1080}, {3840, 2160}};
};

BenchLanesOptions parse_bench_lanes(int argc, char** argv) {
    BenchLanesOptions o;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string fl = a.flag();
        if (fl == "--scene") {
            o.scene = a.value(fl);
        } else if (fl == "--json") {
            o.json = a.value(fl);
        } else if (fl == "--sizes") {
            o.sizes.clear();
            std::istringstream is(a.value(fl));
            std::string item;
            while (std::getline(is, item, ',')) {
                const size_t x = item.find('x');
                if (x == std::string::npos) throw UsageError("--sizes: '" + item + "' is not WxH");
                const int w = int(parse_int(fl, item.substr(0, x), 16, 4096));
                const int h = int(parse_int(fl, item.substr(x + 1), 16, 4096));
                o.sizes.push_back({w, h});
            }
            if (o.sizes.empty()) throw UsageError("--sizes: no size given");
        } else {
            throw UsageError("bench-lanes: unknown option " + fl);
        }
    }
    return o;
}
}  // namespace

std::vector<SpanRegs> scene_spans(const std::string& scene, int w, int h) {
    const render::Scene sc = render::make_scene(scene);
    const render::Frame f = render::rasterize(sc, w, h);
    const Model m;
    Recorder rec(m);
    render::shade_specular(sc, f, render::SpecModel::rtl, &rec, render::RgbMode::once);
    return rec.regs;
}

LanesRow bench_lanes_row(const std::vector<SpanRegs>& spans, int w, int h) {
    LanesRow r;
    r.w = w;
    r.h = h;
    r.spans = spans.size();
    for (const auto& s : spans) r.pixels += uint64_t(s.len) + 1;
    r.figures.push_back(run_lanes<Vspec_stream, 1, false>("l1", spans, r.pixels));
    r.figures.push_back(run_lanes<Vspec_stream_l2, 2, false>("l2", spans, r.pixels));
    r.figures.push_back(run_lanes<Vspec_stream_l2p, 2, true>("l2p", spans, r.pixels));
    r.figures.push_back(run_lanes<Vspec_stream_l4, 4, false>("l4", spans, r.pixels));
    r.figures.push_back(run_lanes<Vspec_stream_l4p, 4, true>("l4p", spans, r.pixels));
    return r;
}

int cmd_bench_lanes(int argc, char** argv) {
    const BenchLanesOptions o = parse_bench_lanes(argc, argv);
    render::make_scene(o.scene);   // an unknown scene: InputError before any work
    std::vector<LanesRow> rows;
    for (const auto& s : o.sizes) rows.push_back(bench_lanes_row(scene_spans(o.scene, s.first, s.second), s.first,
                                                                 s.second));
    std::printf("Scene '%s', spans as the renderer sends them, no stalls: pixels per clock (pixels / clock cycles "
                "from the first descriptor to the last beat)\n\n",
                o.scene.c_str());
    std::printf("| frame | spans | pixels | pixels per span | LANES = 1 | 2 | 2, PACK | 4 | 4, PACK |\n"
                "|---|---|---|---|---|---|---|---|---|\n");
    for (const auto& r : rows) {
        std::printf("| %dx%d | %llu | %llu | %.1f |", r.w, r.h, (unsigned long long)r.spans,
                    (unsigned long long)r.pixels, double(r.pixels) / double(r.spans ? r.spans : 1));
        for (const auto& f : r.figures) std::printf(" %.3f |", f.ppc);
        std::printf("\n");
    }
    if (!o.json.empty()) {
        render::write_atomic(o.json, [&](const std::string& tmp) {
            std::ofstream os(tmp);
            os << "{\"scene\": \"" << o.scene << "\", \"rows\": [";
            for (size_t i = 0; i < rows.size(); ++i) {
                const auto& r = rows[i];
                os << (i ? ", " : "") << "{\"w\": " << r.w << ", \"h\": " << r.h << ", \"spans\": " << r.spans
                   << ", \"pixels\": " << r.pixels << ", \"ppc\": {";
                for (size_t k = 0; k < r.figures.size(); ++k) {
                    const auto& f = r.figures[k];
                    os << (k ? ", " : "") << "\"" << f.name << "\": {\"lanes\": " << f.lanes << ", \"pack\": "
                       << (f.pack ? 1 : 0) << ", \"cycles\": " << f.cycles << ", \"beats\": " << f.beats
                       << ", \"pixels_per_clock\": " << f.ppc << "}";
                }
                os << "}}";
            }
            os << "]}\n";
            os.close();
            if (!os) throw InputError("cannot write " + o.json);
        });
    }
    return 0;
}

}  // namespace spec
