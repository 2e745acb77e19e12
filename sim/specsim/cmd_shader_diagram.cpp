// cmd_shader_diagram.cpp - specsim shader-diagram: spec_shader's AXI4-Stream ports cycle by cycle from a
// simulation of the Verilated RTL (README, docs/setup.md): three spans (3, 1 and 2 pixels) offered back to
// back, the sink stalling for one clock in the second span; the input side's cycles, then the output side's
// around the first pixels, and the latency from a beat's acceptance to its first pixel.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "Vspec_shader.h"
#include "Vspec_shader_up5k.h"
#include "cli.h"
#include "commands.h"
#include "setup_driver.h"
#include "setup_eval.h"
#include "setup_rtl.h"

namespace spec {

const char* const kShaderDiagramUsage =
    "  shader-diagram  spec_shader's ports cycle by cycle from a simulation: three spans (3, 1, 2 pixels)\n"
    "                back to back, one clock of sink stall; latency from a beat's acceptance to its first pixel\n"
    "                --config ecp5|up5k (default ecp5)\n";

namespace {
struct Sample {
    bool s_valid, s_ready, m_valid, m_ready, m_last;
    unsigned user;
};

template <class V>
std::vector<Sample> simulate(const std::vector<SetupInput>& spans) {
    ShaderDriver<V> d;
    std::vector<Sample> w;
    std::mt19937_64 rng(1);
    uint64_t first_px = 0;
    d.run(spans, 1.0, 1.0, rng, 0, [&](V& t) {
        if (t.m_axis_tvalid && first_px == 0) first_px = w.size();
        // one clock of sink stall on the output's fifth cycle
        if (first_px && w.size() == first_px + 4) t.m_axis_tready = 0;
        t.eval();
        w.push_back({t.s_axis_tvalid != 0, t.s_axis_tready != 0, t.m_axis_tvalid != 0, t.m_axis_tready != 0,
                     t.m_axis_tlast != 0, static_cast<unsigned>(t.m_axis_tuser)});
    });
    return w;
}

std::string row(const char* name, const std::vector<Sample>& w, size_t a, size_t b, char (*f)(const Sample&)) {
    std::string s = name;
    s.resize(16, ' ');
    for (size_t c = a; c < b && c < w.size(); ++c) s += std::string("   ") + f(w[c]);
    return s;
}
}  // namespace

int cmd_shader_diagram(int argc, char** argv) {
    SetupConfig cfg = SetupConfig::ecp5;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string fl = a.flag();
        if (fl == "--config") {
            try {
                cfg = parse_setup_config(a.value(fl));
            } catch (const std::invalid_argument& e) {
                throw UsageError(std::string("--config: ") + e.what());
            }
        } else {
            throw UsageError("shader-diagram: unknown option " + fl);
        }
    }
    // three spans: a highlight across the span (N constant, H turning), n = 10, Is*ks = 1
    const SetupFormat sf = setup_format_config("ecp5");
    std::vector<SetupInput> spans;
    const uint32_t lens[3] = {2, 0, 1};
    for (uint32_t l : lens) {
        SetupInput in;
        in.n1[2] = in.n2[2] = component_code(sf, 1.0);
        in.h1[0] = component_code(sf, -0.1);
        in.h2[0] = component_code(sf, 0.1);
        in.h1[2] = in.h2[2] = component_code(sf, 0.995);
        in.strength = 1u << sf.str_frac;
        in.n = 10;
        in.l = l;
        spans.push_back(in);
    }
    const std::vector<Sample> w = cfg == SetupConfig::up5k ? simulate<Vspec_shader_up5k>(spans)
                                                           : simulate<Vspec_shader>(spans);
    size_t acc0 = w.size(), px0 = w.size(), px_end = 0;
    for (size_t c = 0; c < w.size(); ++c) {
        if (acc0 == w.size() && w[c].s_valid && w[c].s_ready) acc0 = c;
        if (px0 == w.size() && w[c].m_valid) px0 = c;
        if (w[c].m_valid) px_end = c;
    }
    if (acc0 == w.size() || px0 == w.size()) throw std::runtime_error("shader-diagram: no handshake seen");
    std::printf("spec_shader (%s configuration), Verilated: cycles counted from the reset's release\n\n",
                setup_config_name(cfg));
    auto table = [&](size_t a0, size_t b0) {
        std::string head = "cycle";
        head.resize(16, ' ');
        for (size_t c = a0; c < b0 && c < w.size(); ++c) {
            char b[8];
            std::snprintf(b, sizeof b, "%4zu", c % 10000);
            head += b;
        }
        std::printf("%s\n", head.c_str());
        std::printf("%s\n", row("s_axis_tvalid", w, a0, b0, [](const Sample& s) { return s.s_valid ? '1' : '0'; }).c_str());
        std::printf("%s\n", row("s_axis_tready", w, a0, b0, [](const Sample& s) { return s.s_ready ? '1' : '0'; }).c_str());
        std::printf("%s\n", row("m_axis_tvalid", w, a0, b0, [](const Sample& s) { return s.m_valid ? '1' : '0'; }).c_str());
        std::printf("%s\n", row("m_axis_tready", w, a0, b0, [](const Sample& s) { return s.m_ready ? '1' : '0'; }).c_str());
        std::printf("%s\n", row("m_axis_tlast", w, a0, b0, [](const Sample& s) { return s.m_last ? '1' : '0'; }).c_str());
        std::printf("%s\n", row("m_axis_tuser", w, a0, b0, [](const Sample& s) {
            return s.m_valid ? "0123456789abcdef"[s.user & 15] : '.';
        }).c_str());
    };
    std::printf("input side (a beat is taken where s_axis_tvalid and s_axis_tready are both 1):\n");
    table(acc0 > 1 ? acc0 - 1 : 0, acc0 + 5);
    std::printf("\noutput side (a pixel is taken where m_axis_tvalid and m_axis_tready are both 1; tuser in hex):\n");
    table(px0 - 1, std::min(px_end + 2, px0 + 12));
    std::printf("\nlatency: %zu clocks from the first beat's acceptance (cycle %zu) to its first pixel (cycle %zu); "
                "the 6 pixels in %zu clocks with one stall\n",
                px0 - acc0, acc0, px0, px_end - px0 + 1);
    return 0;
}

}  // namespace spec
