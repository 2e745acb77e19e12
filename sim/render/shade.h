// shade.h - Phong-Blinn shading of the rasterized spans: ambient + Lambert diffuse (shared by every model)
// plus the specular term from a choice of models.
//
//   I = ka Ia (x) Cd  +  kd Is Lc (x) Cd max(0, N.L)  +  [Is ks max(0, N.H)^n] Lc (x) Cs
//
// (x) is the per-channel product; Lc light colour, Cd material colour, Cs specular colour, all in [0, 1].
// The bracket is the BRDF, the same for the three channels: the core computes it once per span with
// C = Is ks A^n in register 1, and the host multiplies its output by Lc (x) Cs per channel
// (RgbMode::once, the default). RgbMode::per_channel runs the core three times per span instead, with
// C = Is ks A^n Lc Cs of each channel (docs/renderer.md compares the two).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "image.h"
#include "raster.h"
#include "span_core.h"
#include "span_ends_core.h"
#include "span_host.h"

namespace spec {
namespace render {

enum class SpecModel {
    rtl,        // a core that runs spans: the Verilated spec_unit through its ports (the caller passes it)
    golden,     // the bit-exact C++ model of spec_unit (same pixels as rtl, faster)
    ref,        // double precision, exact Blinn-Phong for the interpolated vectors (per pixel slerp of N, H)
    prototype,  // Abbas, Szirmay-Kalos, Horvath: C cos^2(sqrt(n/2) zeta), 0 past pi/2, in double
    host,       // the host's angles with exact cos^n in double: the host's own share of the error
    shader,     // a core that does the setup itself (SpanEndsCore: the Verilated spec_shader, sim/setup): the
                // span's end vectors in, setup and core in the RTL
};
const char* model_name(SpecModel m);
// Throws InputError for an unknown name.
SpecModel parse_model(const std::string& s);

enum class RgbMode { once, per_channel };

// What every model shares: background, ambient and diffuse, and the specular tint Lc (x) Cs per pixel.
struct Shading {
    int w = 0, h = 0;
    std::vector<float> base;       // rgb
    std::vector<float> tint;       // rgb
    std::vector<uint8_t> covered;  // 1 where an object is
};
Shading shade_base(const Scene& sc, const Frame& f);

struct SpecRun {
    std::vector<float> spec;   // rgb per pixel: the specular term
    host::Counters counters;   // degenerate spans met by the host
    uint64_t spans = 0;        // spans evaluated
    uint64_t core_pixels = 0;  // pixels computed by the model (whole spans, hidden pixels included)
    uint64_t core_runs = 0;    // spans sent to the core (3 per span with RgbMode::per_channel)
    uint64_t core_cycles = 0;  // rtl: clock cycles simulated
    double seconds = 0;        // wall time of the specular stage
};

using Progress = std::function<void(size_t done, size_t total)>;
// The specular term of every span. core: what runs the spans of SpecModel::rtl and SpecModel::golden (a
// SpanCore: the Verilated spec_unit of sim/rtl, spec_stream, the bit-exact model); the renderer never builds
// a Verilated model itself. SpecModel::rtl needs one (std::invalid_argument without); golden without one
// uses the bit-exact model (ModelCore). mode: what ROM 9 holds (patent: sqrt(n/k), Fig. 10; tuned: minimax
// scale and table, docs/tuned.md) - the format the host quantizes for and the core's output is read in; it
// must be the core's. The other models do not use a core.
SpecRun shade_specular(const Scene& sc, const Frame& f, SpecModel m, SpanCore* core, RgbMode rgb,
                       host::GammaRule rule = host::GammaRule::patent, const Progress& progress = {},
                       Mode mode = Mode::patent);
// The same without a core (every model but rtl).
SpecRun shade_specular(const Scene& sc, const Frame& f, SpecModel m, RgbMode rgb,
                       host::GammaRule rule = host::GammaRule::patent, const Progress& progress = {},
                       Mode mode = Mode::patent);

// SpecModel::shader: the specular term of every span through a core that takes the span's ends (spec_shader),
// in batches of `batch` spans streamed back to back; nothing per span is computed here beyond what the
// rasterizer interpolated. The counters count the core's flags; core_cycles are its clock cycles.
// RgbMode::per_channel runs every span three times with the strength times each channel's tint (shade_ends.cpp).
SpecRun shade_specular(const Scene& sc, const Frame& f, SpanEndsCore& core, RgbMode rgb,
                       host::GammaRule rule = host::GammaRule::patent, const Progress& progress = {},
                       size_t batch = 4096);

// base + spec, clamped to [0, 1], rounded to 8 bits.
Image compose(const Shading& s, const SpecRun& r);

// The prototype's BRDF: cos^2(sqrt(n/2) |zeta|), 0 once the scaled angle reaches pi/2; n = 0 gives 1.
double prototype_brdf(unsigned n, double zeta);

}  // namespace render
}  // namespace spec
