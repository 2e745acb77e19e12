// setup_render.cpp - spec_shader (Verilated, or its bit-exact models) behind the renderer's SpanEndsCore.
#include "setup_render.h"

#include <algorithm>
#include <cmath>

#include "setup_eval.h"

namespace spec {

SetupInput span_beat(const SetupFormat& sf, const SpanEndsJob& job) {
    SetupInput in;
    const host::Vec* v[4] = {&job.ends.n1, &job.ends.n2, &job.ends.h1, &job.ends.h2};
    int32_t* dst[4] = {in.n1, in.n2, in.h1, in.h2};
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 3; ++k) dst[i][k] = component_code(sf, (*v[i])[k]);
    const double top = std::ldexp(1.0, sf.str_w) - 1;
    in.strength = static_cast<uint32_t>(std::min(top, std::max(0.0, std::nearbyint(std::ldexp(job.strength, sf.str_frac)))));
    in.n = job.n;
    in.l = job.l;
    in.midpoint = job.rule == host::GammaRule::midpoint;
    return in;
}

namespace {
std::vector<SetupInput> beats_of(const std::vector<SpanEndsJob>& jobs) {
    const SetupFormat sf = setup_format_config("ecp5");   // the beat's formats are both configurations'
    std::vector<SetupInput> beats;
    beats.reserve(jobs.size());
    for (const SpanEndsJob& j : jobs) beats.push_back(span_beat(sf, j));
    return beats;
}

// The Verilated spec_shader (ShaderRtl, setup_rtl.h)
class ShaderCore : public SpanEndsCore {
public:
    explicit ShaderCore(SetupConfig c) : rtl_(make_shader_rtl(c)), model_(shader_core_format(c)) {}
    std::vector<SpanEndsResult> spans(const std::vector<SpanEndsJob>& jobs) override {
        std::vector<SpanEndsResult> out;
        for (ShaderRtl::Span& s : rtl_->run(beats_of(jobs))) out.push_back({std::move(s.pixels), s.flags});
        return out;
    }
    uint64_t cycle() const override { return rtl_->cycles(); }
    const Model& pixel_model() const override { return model_; }

private:
    std::unique_ptr<ShaderRtl> rtl_;
    Model model_;
};

// The bit-exact models: the configuration's setup model, then the core's Model
class ShaderModels : public SpanEndsCore {
public:
    explicit ShaderModels(SetupConfig c) : setup_(c), core_(shader_core_format(c)) {}
    std::vector<SpanEndsResult> spans(const std::vector<SpanEndsJob>& jobs) override {
        std::vector<SpanEndsResult> out;
        for (const SetupInput& in : beats_of(jobs)) {
            const SetupResult r = setup_.run(in);
            out.push_back({core_.span(r.regs), r.flags});
        }
        return out;
    }
    uint64_t cycle() const override { return 0; }
    const Model& pixel_model() const override { return core_; }

private:
    ConfigSetupModel setup_;
    Model core_;
};
}  // namespace

std::unique_ptr<SpanEndsCore> make_shader_core(SetupConfig c) { return std::make_unique<ShaderCore>(c); }
std::unique_ptr<SpanEndsCore> make_shader_models(SetupConfig c) { return std::make_unique<ShaderModels>(c); }

render::SpecRun shade_shader(const render::Scene& sc, const render::Frame& f, SetupConfig c, render::RgbMode rgb,
                             host::GammaRule rule, const render::Progress& progress) {
    const std::unique_ptr<SpanEndsCore> core = make_shader_core(c);
    return render::shade_specular(sc, f, *core, rgb, rule, progress);
}

render::SpecRun shade_shader_models(const render::Scene& sc, const render::Frame& f, SetupConfig c, render::RgbMode rgb,
                                    host::GammaRule rule) {
    const std::unique_ptr<SpanEndsCore> core = make_shader_models(c);
    return render::shade_specular(sc, f, *core, rgb, rule);
}

}  // namespace spec
