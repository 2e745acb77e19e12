// setup_render.h - spec_shader as the renderer's SpanEndsCore (sim/render/span_ends_core.h; specsim render
// --model shader): each span's ends, as the rasterizer interpolated them, quantized into the span-ends beat
// (Q1.14 components, Is*ks UQ1.15 saturated to the format's largest code); setup and core run in the RTL (or in
// their bit-exact models).
#pragma once

#include <memory>

#include "setup_rtl.h"
#include "shade.h"

namespace spec {

// The span-ends beat of a span's ends: N and H quantized, Is*ks (saturated to the format's largest code), n, l,
// the gamma rule.
SetupInput span_beat(const SetupFormat& sf, const SpanEndsJob& job);

// The Verilated spec_shader of configuration c as a SpanEndsCore (spans streamed back to back, the sink
// always ready; cycle() counts its clocks).
std::unique_ptr<SpanEndsCore> make_shader_core(SetupConfig c);
// The same through the bit-exact models (the configuration's setup model, then the core's Model): what the RTL
// must give.
std::unique_ptr<SpanEndsCore> make_shader_models(SetupConfig c);

// The renderer's specular pass through them (render::shade_specular with the core above).
render::SpecRun shade_shader(const render::Scene& sc, const render::Frame& f, SetupConfig c, render::RgbMode rgb,
                             host::GammaRule rule, const render::Progress& progress = {});
render::SpecRun shade_shader_models(const render::Scene& sc, const render::Frame& f, SetupConfig c, render::RgbMode rgb,
                                    host::GammaRule rule);

}  // namespace spec
