// board_shaders.cpp - shader-pass models for the board model (see board_shaders.h).
#include "board_shaders.h"

#include <memory>


namespace spec {
namespace board {

Shader host_shader(const Model& m, host::GammaRule rule) {
    return [&m, rule](const ShadeIn& in) {
        host::SpanEnds e;
        e.n1 = host::Vec(in.n1[0], in.n1[1], in.n1[2]);
        e.n2 = host::Vec(in.n2[0], in.n2[1], in.n2[2]);
        e.h1 = e.h2 = host::Vec(in.light[0], in.light[1], in.light[2]);
        const host::SpanSetup st = host::setup_span(m, e, in.strength / 32768.0, in.n, in.l, rule);
        return m.span(st.regs);
    };
}

SetupInput shade_beat(const ShadeIn& in) {
    SetupInput si;
    for (int k = 0; k < 3; ++k) {
        si.n1[k] = in.n1[size_t(k)];
        si.n2[k] = in.n2[size_t(k)];
        si.h1[k] = si.h2[k] = in.light[size_t(k)];
    }
    si.strength = in.strength;
    si.n = in.n;
    si.l = in.l;
    si.midpoint = true;
    return si;
}

Shader rtl_shader(const Model& m, SetupConfig c) {
    // the setup's descriptor is the default core format's (the board RTL's setup reads rom/spec_params.vh)
    const auto setup = std::make_shared<const ConfigSetupModel>(c);
    return [&m, setup](const ShadeIn& in) { return m.span(setup->run(shade_beat(in)).regs); };
}

SetupConfig board_setup_config(const std::string& board, const std::string& mode) {
    return (board == "ulx3s" && (mode == "1280x720" || mode == "128x96-race")) ? SetupConfig::ecp5 : SetupConfig::up5k;
}

std::vector<SetupInput> board_beats(const BoardScene& s, unsigned f) {
    std::vector<SetupInput> beats;
    const Shader record = [&beats](const ShadeIn& in) {
        beats.push_back(shade_beat(in));
        return std::vector<uint32_t>(size_t(in.l) + 1, 0u);
    };
    model_frame(s, record, f, 8, 0, s.mode.v_active);
    return beats;
}

}  // namespace board
}  // namespace spec
