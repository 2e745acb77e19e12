// cmd_bench_shader.cpp - specsim bench-shader (make bench): clocks a span of spec_shader in each configuration on
// three span streams - the default scene's spans (512 x 512, triangle spans, nothing shared), the iCEBreaker's
// (320 x 240, K = 8) and the ULX3S's racing stream (640 x 480, K = 16) as the board model sends them (the diffuse
// and specular beat of each sub-span, sim/board/board_shaders.h) - and pixels per clock of the ecp5 shader on the
// default scene at 512 x 512 and 1920 x 1080 beside spec_stream alone on the same spans. Cycle counts are exact:
// every beat streamed back to back, the sink always ready.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "Vspec_stream.h"
#include "board_scene.h"
#include "board_shaders.h"
#include "cli.h"
#include "commands.h"
#include "mesh.h"
#include "raster.h"
#include "scene.h"
#include "setup_render.h"
#include "stream_driver.h"

namespace spec {

const char* const kBenchShaderUsage =
    "  bench-shader  clocks a span of spec_shader in each configuration (ecp5, up5k) on the default scene's spans\n"
    "                and on the iCEBreaker's and the ULX3S's span streams; pixels per clock of the ecp5 shader on\n"
    "                the default scene (512 x 512, 1920 x 1080) against spec_stream alone on the same spans\n"
    "                --spans N (10..100000, default 2000: beats of each stream through each configuration)\n"
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
    const SetupFormat sf = setup_format_config("ecp5");
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
    // the shader, ecp5
    std::unique_ptr<ShaderRtl> shader = make_shader_rtl(SetupConfig::ecp5);
    const uint64_t c0 = shader->cycles();
    shader->run(beats);
    r.shader_cycles = shader->cycles() - c0;
    // spec_stream alone on the setup model's descriptors
    const SetupModel sm(setup_format_config("ecp5"));
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

struct StreamRun {
    std::string config, stream;
    size_t spans = 0;
    uint64_t pixels = 0, cycles = 0;
};

// The first n beats of a stream through the configuration's shader.
StreamRun run_stream(SetupConfig c, const std::string& name, std::vector<SetupInput> beats, size_t n) {
    if (beats.size() > n) beats.resize(n);
    StreamRun r;
    r.config = setup_config_name(c);
    r.stream = name;
    r.spans = beats.size();
    for (const SetupInput& b : beats) r.pixels += b.l + 1;
    std::unique_ptr<ShaderRtl> sh = make_shader_rtl(c);
    const uint64_t c0 = sh->cycles();
    sh->run(beats);
    r.cycles = sh->cycles() - c0;
    return r;
}

}  // namespace

int cmd_bench_shader(int argc, char** argv) {
    long long n_spans = 2000;
    std::string json;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string fl = a.flag();
        if (fl == "--help" || fl == "-h") {
            std::cout << "usage: specsim bench-shader [options]\n" << kBenchShaderUsage;
            return 0;
        }
        if (fl == "--spans") n_spans = parse_int(fl, a.value(fl), 10, 100000);
        else if (fl == "--json") json = a.value(fl);
        else throw UsageError("bench-shader: unknown option " + fl);
    }
    // clocks a span: each configuration on each stream
    const std::vector<std::pair<std::string, std::vector<SetupInput>>> streams = {
        {"default", scene_beats(512, 512)},
        {"icebreaker", board::board_beats(board::make_board_scene("320x240", 8), 0)},
        {"ulx3s", board::board_beats(board::make_board_scene("640x480", 16), 0)},
    };
    std::vector<StreamRun> sruns;
    for (SetupConfig c : {SetupConfig::ecp5, SetupConfig::up5k})
        for (const auto& st : streams) sruns.push_back(run_stream(c, st.first, st.second, size_t(n_spans)));
    std::printf("spec_shader, clocks a span (a 256-bit beat), the beats streamed back to back, the sink always ready:\n\n");
    std::printf("| configuration | stream | beats | pixels a beat | cycles | clocks a span |\n|---|---|---|---|---|---|\n");
    for (const StreamRun& r : sruns)
        std::printf("| %s | %s | %zu | %.2f | %llu | %.2f |\n", r.config.c_str(), r.stream.c_str(), r.spans,
                    double(r.pixels) / double(r.spans), (unsigned long long)r.cycles, double(r.cycles) / double(r.spans));

    std::vector<SceneRun> runs{run_scene(512, 512), run_scene(1920, 1080)};
    std::printf("\nspec_shader (ecp5) on the default scene's spans, streamed back to back, sink always ready:\n\n");
    std::printf("| image | spans | pixels | pixels a span | spec_shader cycles | spec_shader pixels per clock |"
                " spec_stream alone, pixels per clock | shader / stream alone |\n|---|---|---|---|---|---|---|---|\n");
    for (const SceneRun& r : runs) {
        const double sp = double(r.pixels) / double(r.shader_cycles), st = double(r.pixels) / double(r.stream_cycles);
        std::printf("| %s | %zu | %llu | %.2f | %llu | %.4f | %.4f | %.4f |\n", r.name.c_str(), r.spans,
                    (unsigned long long)r.pixels, double(r.pixels) / double(r.spans), (unsigned long long)r.shader_cycles,
                    sp, st, sp / st);
    }
    if (!json.empty()) {
        std::ostringstream o;
        o << "{\n  \"clocks_a_span\": [\n";
        for (size_t i = 0; i < sruns.size(); ++i) {
            const StreamRun& r = sruns[i];
            o << "    {\"config\": \"" << r.config << "\", \"stream\": \"" << r.stream << "\", \"spans\": " << r.spans
              << ", \"pixels\": " << r.pixels << ", \"cycles\": " << r.cycles
              << ", \"clocks_a_span\": " << double(r.cycles) / double(r.spans) << "}" << (i + 1 < sruns.size() ? "," : "")
              << "\n";
        }
        o << "  ],\n  \"by\": {";
        for (size_t i = 0; i < sruns.size(); ++i)
            o << (i ? ", " : "") << "\"" << sruns[i].config << "_" << sruns[i].stream
              << "\": " << double(sruns[i].cycles) / double(sruns[i].spans);
        o << "},\n  \"scenes\": [\n";
        for (size_t i = 0; i < runs.size(); ++i) {
            const SceneRun& r = runs[i];
            o << "    {\"image\": \"" << r.w << "x" << r.h << "\", \"spans\": " << r.spans << ", \"pixels\": " << r.pixels
              << ", \"shader_cycles\": " << r.shader_cycles << ", \"stream_cycles\": " << r.stream_cycles << "}"
              << (i + 1 < runs.size() ? "," : "") << "\n";
        }
        o << "  ]\n}\n";
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
