// board_shaders.cpp - shader-pass models for the board model (see board_shaders.h).
#include "board_shaders.h"

#include <memory>

#include "setup_model.h"

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

Shader rtl_shader(const Model& m, const SetupFormat& sf) {
    // the setup's descriptor is the default core format's (the board RTL's spec_setup reads rom/spec_params.vh)
    const auto setup = std::make_shared<const SetupModel>(sf);
    return [&m, setup](const ShadeIn& in) {
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
        return m.span(setup->run(si).regs);
    };
}

const char* board_setup_config(const std::string& board) { return board == "icebreaker" ? "narrow" : "default"; }

}  // namespace board
}  // namespace spec
