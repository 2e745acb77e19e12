// board_shaders.cpp - shader-pass models for the board model (see board_shaders.h).
#include "board_shaders.h"

namespace spec {
namespace board {

Shader host_shader(const Model& m, host::GammaRule rule) {
    return [&m, rule](const ShadeIn& in) {
        host::SpanEnds e;
        e.n1 = host::Vec(in.n1[0], in.n1[1], in.n1[2]);
        e.n2 = host::Vec(in.n2[0], in.n2[1], in.n2[2]);
        e.h1 = e.h2 = host::Vec(in.light[0], in.light[1], in.light[2]);
        const host::SpanSetup st = host::setup_span(m, e, in.strength / 65536.0, in.n, in.l, rule);
        return m.span(st.regs);
    };
}

Shader rtl_shader(const Model& m) {
    return [&m](const ShadeIn& in) {
        SpanRegs r;
        r.c = in.strength;
        r.n = 0;
        r.len = in.l;
        return m.span(r);
    };
}

}  // namespace board
}  // namespace spec
