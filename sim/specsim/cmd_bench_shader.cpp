// cmd_bench_shader.cpp - specsim bench-shader: pixels per clock of spec_shader on the default scene's spans at
// 512 x 512 and 1920 x 1080, beside spec_stream alone on the same spans (its descriptors from the setup's model),
// and spans per clock of the small configuration (make bench). Cycle counts are exact: every span streamed back
// to back, the sink always ready.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "Vspec_stream.h"
#include "cli.h"
#include "commands.h"
#include "mesh.h"
#include "raster.h"
#include "scene.h"
#include "setup_render.h"
#include "stream_driver.h"

namespace spec {

const char* const kBenchShaderUsage =
    "  bench-shader  clock cycles of spec_shader on the default scene's spans (512 x 512, 1920 x 1080) against\n"
    "                spec_stream alone on the same spans; spans per clock of the small configuration\n"
    "                --small-spans N (10..100000, default 2000: spans through the small configuration)\n"
    "                --json FILE (also write the figures as JSON)\n";

namespace {

struct SceneRun {
    std::string name;
    int w = 0, h = 0;
    size_t spans = 0;
    uint64_t pixels = 0;
    uint64_t shader_cycles = 0, stream_cycles = 0;
};

// Every visible span of the default scene at w x h as span-ends beats (the renderer's interpolated end vectors).
std::vector<SetupInput> scene_beats(int w, int h) {
    const render::Scene sc = render::make_scene("default");
    const render::Frame f = render::rasterize(sc, w, h);
    const SetupFormat sf;
    std::vector<SetupInput> v;
    v.reserve(f.spans.size());
    for (const render::Span& sp : f.spans) {
        const render::Material& m = sc.objects[sp.obj].mat;
        v.push_back(span_beat(sf, {sp.ends, sc.light.intensity * m.ks, m.n, sp.l, host::GammaRule::patent}));
    }
    return v;
}

SceneRun run_scene(int w, int h) {
    SceneRun r;
    r.w = w;
    r.h = h;
    r.name = std::to_string(w) + " x " + std::to_string(h);
    const std::vector<SetupInput> beats = scene_beats(w, h);
    r.spans = beats.size();
    for (const SetupInput& b : beats) r.pixels += b.l + 1;
    // the shader, pipelined
    std::unique_ptr<ShaderRtl> shader = make_shader_rtl(SetupConfig::pipelined);
    const uint64_t c0 = shader->cycles();
    shader->run(beats);
    r.shader_cycles = shader->cycles() - c0;
    // spec_stream alone on the setup model's descriptors
    const SetupModel sm;
    std::vector<SpanRegs> regs;
    regs.reserve(beats.size());
    for (const SetupInput& b : beats) regs.push_back(sm.run(b).regs);
    StreamDriver<Vspec_stream> d;
    std::mt19937_64 rng(1);
    const uint64_t s0 = d.cycle();
    d.run(regs, Stalls{}, rng);
    r.stream_cycles = d.cycle() - s0;
    return r;
}

}  // namespace

int cmd_bench_shader(int argc, char** argv) {
    long long small_spans = 2000;
    std::string json;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string fl = a.flag();
        if (fl == "--help" || fl == "-h") {
            std::cout << "usage: specsim bench-shader [options]\n" << kBenchShaderUsage;
            return 0;
        }
        if (fl == "--small-spans") small_spans = parse_int(fl, a.value(fl), 10, 100000);
        else if (fl == "--json") json = a.value(fl);
        else throw UsageError("bench-shader: unknown option " + fl);
    }
    std::vector<SceneRun> runs{run_scene(512, 512), run_scene(1920, 1080)};
    std::printf("spec_shader (pipelined setup) on the default scene's spans, streamed back to back, sink always ready:\n\n");
    std::printf("| image | spans | pixels | pixels a span | spec_shader cycles | spec_shader pixels per clock |"
                " spec_stream alone, pixels per clock | shader / stream alone |\n|---|---|---|---|---|---|---|---|\n");
    for (const SceneRun& r : runs) {
        const double sp = double(r.pixels) / double(r.shader_cycles), st = double(r.pixels) / double(r.stream_cycles);
        std::printf("| %s | %zu | %llu | %.2f | %llu | %.4f | %.4f | %.4f |\n", r.name.c_str(), r.spans,
                    (unsigned long long)r.pixels, double(r.pixels) / double(r.spans), (unsigned long long)r.shader_cycles,
                    sp, st, sp / st);
    }
    // the small configuration: spans per clock on the first spans of the 512 x 512 scene
    std::vector<SetupInput> beats = scene_beats(512, 512);
    beats.resize(std::min<size_t>(beats.size(), size_t(small_spans)));
    uint64_t px = 0;
    for (const SetupInput& b : beats) px += b.l + 1;
    std::unique_ptr<ShaderRtl> small = make_shader_rtl(SetupConfig::small);
    const uint64_t c0 = small->cycles();
    small->run(beats);
    const uint64_t cyc = small->cycles() - c0;
    std::printf("\nsmall configuration (setup one span at a time), first %zu spans of the 512 x 512 scene: %llu cycles,"
                " %.6f spans per clock (%.1f clocks a span), %.5f pixels per clock\n",
                beats.size(), (unsigned long long)cyc, double(beats.size()) / double(cyc), double(cyc) / double(beats.size()),
                double(px) / double(cyc));
    if (!json.empty()) {
        std::ostringstream o;
        o << "{\n  \"scenes\": [\n";
        for (size_t i = 0; i < runs.size(); ++i) {
            const SceneRun& r = runs[i];
            o << "    {\"image\": \"" << r.w << "x" << r.h << "\", \"spans\": " << r.spans << ", \"pixels\": " << r.pixels
              << ", \"shader_cycles\": " << r.shader_cycles << ", \"stream_cycles\": " << r.stream_cycles << "}"
              << (i + 1 < runs.size() ? "," : "") << "\n";
        }
        o << "  ],\n  \"small\": {\"spans\": " << beats.size() << ", \"pixels\": " << px << ", \"cycles\": " << cyc
          << "}\n}\n";
        std::ofstream os(json + ".tmp");
        os << o.str();
        os.close();
        if (!os || std::rename((json + ".tmp").c_str(), json.c_str()) != 0) {
            std::remove((json + ".tmp").c_str());
            throw render::InputError("cannot write " + json);
        }
    }
    return 0;
}

}  // namespace spec
