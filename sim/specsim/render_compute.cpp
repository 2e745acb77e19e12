// render_compute.cpp - specsim render's work: rasterize, shade with the chosen model (and the comparison
// models for --panel / --stats), compare against ref. No printing: render_report.cpp prints.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "cmd_render.h"

namespace spec {

const ModelResult* RenderResult::find(render::SpecModel m) const {
    for (const ModelResult& r : results) {
        if (r.model == m && !r.pow_column) return &r;
    }
    return nullptr;
}

const ModelResult* RenderResult::find_pow() const {
    for (const ModelResult& r : results) {
        if (r.pow_column) return &r;
    }
    return nullptr;
}

RenderResult render_compute(const RenderOptions& ra, const render::Scene& sc, const CoreFactory& make_core,
                            const std::function<render::Progress(render::SpecModel)>& progress_for,
                            const ShaderFactory& make_shader) {
    RenderResult res;
    const auto t0 = std::chrono::steady_clock::now();
    res.frame = render::rasterize(sc, ra.size, ra.size);
    res.base = render::shade_base(sc, res.frame);
    res.t_raster = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    std::vector<render::SpecModel> models{ra.model};
    res.compared = !ra.panel.empty() || !ra.stats.empty();
    if (res.compared) {
        for (auto m : {render::SpecModel::ref, render::SpecModel::golden, render::SpecModel::prototype,
                       render::SpecModel::host}) {
            if (m == render::SpecModel::golden && ra.model != render::SpecModel::rtl) continue;
            if (std::find(models.begin(), models.end(), m) == models.end()) models.push_back(m);
        }
    }
    // --cull-specular (companion paper A, docs/methods.md): the chosen model's specular pass runs on the spans of
    // the triangles whose N.H bound lets the core output anything; diffuse and the comparison models see all
    render::Frame culled;
    if (ra.cull) {
        Format cf;
        cf.mode = ra.mode;
        res.cull = methods::cull_spans(sc, res.frame, Model(cf));
        res.culled = true;
        culled = methods::kept_frame(res.frame, res.cull);
    }
    for (auto m : models) {
        ModelResult r;
        r.model = m;
        const render::Frame& spec_frame = ra.cull && m == ra.model ? culled : res.frame;
        const render::Progress prog = progress_for ? progress_for(m) : render::Progress();
        if (m == render::SpecModel::shader) {
            if (!make_shader) throw std::invalid_argument("render_compute: the shader model needs a ShaderFactory");
            const std::unique_ptr<SpanEndsCore> shader = make_shader(ra.shader_config);
            r.run = render::shade_specular(sc, spec_frame, *shader, ra.rgb, ra.gamma, prog);
        } else {
            std::unique_ptr<SpanCore> core;
            if (m == render::SpecModel::rtl) core = make_core(ra.mode);
            r.run = render::shade_specular(sc, spec_frame, m, core.get(), ra.rgb, ra.gamma, prog, ra.mode);
        }
        r.img = render::compose(res.base, r.run);
        res.results.push_back(std::move(r));
    }
    if (res.compared && ra.mode != Mode::pow) {   // the pow column: the bit-exact model in pow mode
        ModelResult r;
        r.model = render::SpecModel::golden;
        r.pow_column = true;
        r.run = render::shade_specular(sc, res.frame, render::SpecModel::golden, nullptr, ra.rgb, ra.gamma,
                                       render::Progress(), Mode::pow);
        r.img = render::compose(res.base, r.run);
        res.results.push_back(std::move(r));
    }
    if (res.compared) {
        const render::Image& ref = res.find(render::SpecModel::ref)->img;
        for (ModelResult& r : res.results) r.st = render::compare(r.img, ref, res.base.covered);
    }
    return res;
}

namespace {
// A JSON string literal (the scene's name is an OBJ path: quotes, backslashes, control characters escaped)
std::string json_str(const std::string& t) {
    std::string o = "\"";
    char b[8];
    for (unsigned char c : t) {
        if (c == '"' || c == '\\') o += '\\', o += char(c);
        else if (c < 0x20) std::snprintf(b, sizeof b, "\\u%04x", c), o += b;
        else o += char(c);
    }
    return o + "\"";
}

std::string json_num(double v) {
    if (std::isinf(v)) return "null";
    char b[64];
    std::snprintf(b, sizeof b, "%.6g", v);
    return b;
}
}  // namespace

std::string render_stats_json(const RenderOptions& ra, const render::Scene& sc, const RenderResult& res) {
    const auto& hc = res.results.front().run.counters;
    const render::Frame& frame = res.frame;
    std::ostringstream j;
    j << "{\n  \"scene\": " << json_str(sc.name) << ",\n  \"size\": " << ra.size << ",\n  \"model\": \""
      << render::model_name(ra.model) << "\",\n  \"mode\": \"" << mode_name(ra.mode) << "\",\n  \"rgb\": \""
      << (ra.rgb == render::RgbMode::once ? "once" : "per-channel") << "\",\n  \"host_gamma\": \""
      << (ra.gamma == host::GammaRule::patent ? "patent" : "midpoint") << "\",\n";
    j << "  \"triangles\": " << frame.triangles << ",\n  \"spans\": " << frame.spans.size()
      << ",\n  \"hidden_spans\": " << frame.hidden_spans << ",\n";
    if (sc.obj.loaded) {
        const render::ObjStats& o = sc.obj;
        j << "  \"obj\": {\"faces\": " << o.faces << ", \"polygons\": " << o.polygons << ", \"triangles\": "
          << o.triangles << ", \"degenerate\": " << o.degenerate << ", \"normals_computed\": "
          << o.normals_computed() << ", \"normals_missing\": " << o.normals_missing << ", \"normals_zero\": "
          << o.normals_zero << ", \"normals_not_finite\": " << o.normals_not_finite << "},\n";
    }
    j << "  \"host\": {\"spans\": " << hc.spans << ", \"flat\": " << hc.flat << ", \"opposite_normals\": "
      << hc.opposite << ", \"no_highlight\": " << hc.no_highlight << ", \"c_saturated\": " << hc.c_saturated
      << ", \"single_pixel\": " << hc.single_pixel << ", \"gamma_fallback\": " << hc.gamma_fallback << "},\n";
    j << "  \"against_ref\": {\n";
    for (size_t i = 0; i < res.results.size(); ++i) {
        const auto& r = res.results[i];
        j << "    \"" << r.name() << "\": {\"max_abs\": " << r.st.max_abs
          << ", \"mean_abs\": " << json_num(r.st.mean_abs) << ", \"psnr_db\": " << json_num(r.st.psnr)
          << ", \"pixels_over_4\": " << r.st.over_4 << ", \"pixels_differing\": " << r.st.differing
          << ", \"model_pixels\": " << r.run.core_pixels << ", \"seconds\": " << json_num(r.run.seconds) << "}"
          << (i + 1 < res.results.size() ? "," : "") << "\n";
    }
    j << "  },\n  \"covered_pixels\": " << (res.compared ? res.results.front().st.covered : 0) << "\n}\n";
    return j.str();
}

}  // namespace spec
