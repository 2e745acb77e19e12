// setup_render.h - the renderer's specular pass through the Verilated spec_shader (specsim render --model
// shader): per span, only the end vectors the rasterizer interpolated, quantized into the span-ends beat
// (Q1.14, Is*ks UQ1.15); setup and core run in the RTL.
#pragma once

#include "setup_rtl.h"
#include "shade.h"

namespace spec {

// The span-ends beat of a rasterized span: N and H at its ends, Is*ks (saturated to the format's largest
// code), n, l, the gamma rule.
SetupInput span_beat(const SetupFormat& sf, const render::Span& sp, double strength, unsigned n, host::GammaRule rule);

// The specular term of every span through spec_shader in configuration c (spans streamed back to back, the
// sink always ready). The counters count the shader's flags (its bits 0-5 are the host's); core_cycles are
// the shader's clock cycles. rgb = per_channel runs every span three times with Is*ks times each channel's
// light colour x specular colour.
render::SpecRun shade_shader(const render::Scene& sc, const render::Frame& f, SetupConfig c, render::RgbMode rgb,
                             host::GammaRule rule, const render::Progress& progress = {});
// The same through the bit-exact models (SetupModel, then the core's Model): what the RTL must give.
render::SpecRun shade_shader_models(const render::Scene& sc, const render::Frame& f, SetupConfig c, render::RgbMode rgb,
                                    host::GammaRule rule);

}  // namespace spec
