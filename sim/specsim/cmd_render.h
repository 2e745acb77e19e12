// cmd_render.h - specsim render: a scene rendered by scanline spans with the specular term from a chosen
// model, split into parse (render_parse.cpp), compute (render_compute.cpp) and report (render_report.cpp).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "highlight.h"
#include "scene.h"
#include "setup_rtl.h"
#include "shade.h"
#include "span_core.h"
#include "stats.h"

namespace spec {

struct RenderOptions {
    std::string scene = "default", obj, out, panel, stats;
    int size = 512;
    render::SpecModel model = render::SpecModel::rtl;
    Mode mode = Mode::patent;
    render::RgbMode rgb = render::RgbMode::once;
    host::GammaRule gamma = host::GammaRule::patent;
    double amp = 16;
    int progress = -1;  // -1: when stderr is a terminal
    bool cull = false;  // --cull-specular
    SetupConfig shader_config = SetupConfig::ecp5;   // --shader-config (--model shader, docs/setup.md)
    // overrides of the scene's light, material and camera
    bool has_light_dir = false, has_light_color = false, has_intensity = false, has_ambient = false;
    render::dvec3 light_dir, light_color, ambient;
    double intensity = 1;
    bool has_n = false, has_ks = false, has_kd = false, has_ka = false, has_color = false, has_spec_color = false;
    long long n = 0;
    double ks = 0, kd = 0, ka = 0;
    render::dvec3 color, spec_color;
    bool has_eye = false, has_target = false, has_up = false, has_fov = false, has_view = false;
    render::dvec3 eye, target, up, view;
    double fov = 0;
};

// Throws UsageError (InputError for a bad --model name).
RenderOptions parse_render(int argc, char** argv);
// The scene with the options applied, validated: a built-in one, or the OBJ file framed automatically
// (InputError for a malformed file or a scene that cannot be rendered).
render::Scene build_scene(const RenderOptions& o);

struct ModelResult {
    render::SpecModel model;
    render::SpecRun run;
    render::Image img;
    render::ImageStats st;   // against ref (when compared)
    bool pow_column = false;  // the pow column of the comparison: the golden model in pow mode (docs/pow.md)
    const char* name() const { return pow_column ? "pow" : render::model_name(model); }
};
struct RenderResult {
    render::Frame frame;
    render::Shading base;
    double t_raster = 0;                    // seconds: rasterization and diffuse
    bool compared = false;                  // the comparison models were rendered (--panel, --stats)
    bool culled = false;
    methods::CullResult cull;               // --cull-specular
    // the chosen model first, then ref, golden, prototype, host, and (unless the chosen mode is pow) the golden
    // model in pow mode, the panel's pow column
    std::vector<ModelResult> results;
    const ModelResult* find(render::SpecModel m) const;   // the first of model m (not the pow column)
    const ModelResult* find_pow() const;                  // the pow column, or null
};
// What runs the spans of the rtl model: a core of the given mode (the Verilated spec_unit in specsim).
using CoreFactory = std::function<std::unique_ptr<SpanCore>(Mode)>;
// What runs the spans of the shader model: a core that takes span ends (the Verilated spec_shader in specsim).
using ShaderFactory = std::function<std::unique_ptr<SpanEndsCore>(SetupConfig)>;
// progress_for(model): the progress callback of that model's specular pass (empty: none). make_shader is
// needed only for --model shader (std::invalid_argument without).
RenderResult render_compute(const RenderOptions& o, const render::Scene& sc, const CoreFactory& make_core,
                            const std::function<render::Progress(render::SpecModel)>& progress_for = {},
                            const ShaderFactory& make_shader = {});

// The statistics JSON (--stats) of a computed render.
std::string render_stats_json(const RenderOptions& o, const render::Scene& sc, const RenderResult& r);

}  // namespace spec
