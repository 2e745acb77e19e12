#include "setup_render.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "setup_eval.h"

namespace spec {

SetupInput span_beat(const SetupFormat& sf, const render::Span& sp, double strength, unsigned n, host::GammaRule rule) {
    SetupInput in;
    const host::Vec* v[4] = {&sp.ends.n1, &sp.ends.n2, &sp.ends.h1, &sp.ends.h2};
    int32_t* dst[4] = {in.n1, in.n2, in.h1, in.h2};
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 3; ++k) dst[i][k] = component_code(sf, (*v[i])[k]);
    const double top = std::ldexp(1.0, sf.str_w) - 1;
    in.strength = static_cast<uint32_t>(std::min(top, std::max(0.0, std::nearbyint(std::ldexp(strength, sf.str_frac)))));
    in.n = n;
    in.l = sp.l;
    in.midpoint = rule == host::GammaRule::midpoint;
    return in;
}

namespace {
// Runs spans through the bit-exact models instead of the RTL.
class ShaderModels : public ShaderRtl {
public:
    explicit ShaderModels(SetupConfig c) : core_(shader_core_format(c)) {}
    std::vector<Span> run(const std::vector<SetupInput>& spans) override {
        std::vector<Span> out;
        for (const SetupInput& in : spans) {
            const SetupResult r = setup_.run(in);
            out.push_back({core_.span(r.regs), r.flags});
        }
        return out;
    }
    uint64_t cycles() const override { return 0; }

private:
    SetupModel setup_;
    Model core_;
};

render::SpecRun shade_with(ShaderRtl& shader, const render::Scene& sc, const render::Frame& f, SetupConfig c,
                           render::RgbMode rgb, host::GammaRule rule, const render::Progress& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    render::SpecRun r;
    r.spec.assign(size_t(f.w) * size_t(f.h) * 3, 0.0f);
    const SetupFormat sf;
    const Model core(shader_core_format(c));
    const bool per_channel = rgb == render::RgbMode::per_channel;
    const size_t total = f.spans.size();
    const size_t batch = 4096;
    for (size_t k0 = 0; k0 < total; k0 += batch) {
        const size_t k1 = std::min(total, k0 + batch);
        for (int ch = 0; ch < (per_channel ? 3 : 1); ++ch) {
            std::vector<SetupInput> beats;
            beats.reserve(k1 - k0);
            for (size_t k = k0; k < k1; ++k) {
                const render::Span& sp = f.spans[k];
                const render::Material& m = sc.objects[sp.obj].mat;
                double strength = sc.light.intensity * m.ks;
                if (per_channel) strength *= (sc.light.color * m.spec_color)[ch];
                beats.push_back(span_beat(sf, sp, strength, m.n, rule));
            }
            const std::vector<ShaderRtl::Span> out = shader.run(beats);
            for (size_t k = k0; k < k1; ++k) {
                const render::Span& sp = f.spans[k];
                const render::Material& m = sc.objects[sp.obj].mat;
                const render::dvec3 tint = sc.light.color * m.spec_color;
                const size_t row = size_t(sp.y) * size_t(f.w) + size_t(sp.x0);
                const ShaderRtl::Span& s = out[k - k0];
                if (ch == 0) {
                    r.counters.add(s.flags & 0x3fu);
                    ++r.spans;
                    r.core_pixels += sp.l + 1;
                }
                ++r.core_runs;
                for (uint32_t i = 0; i <= sp.l; ++i) {
                    if (!f.visible(sp, i)) continue;
                    const double v = core.out_value(s.pixels[i]);
                    if (per_channel) r.spec[3 * (row + i) + ch] = float(v);
                    else
                        for (int q = 0; q < 3; ++q) r.spec[3 * (row + i) + q] = float(v * tint[q]);
                }
            }
        }
        if (progress) progress(k1, total);
    }
    r.core_cycles = shader.cycles();
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
}
}  // namespace

render::SpecRun shade_shader(const render::Scene& sc, const render::Frame& f, SetupConfig c, render::RgbMode rgb,
                             host::GammaRule rule, const render::Progress& progress) {
    std::unique_ptr<ShaderRtl> shader = make_shader_rtl(c);
    return shade_with(*shader, sc, f, c, rgb, rule, progress);
}

render::SpecRun shade_shader_models(const render::Scene& sc, const render::Frame& f, SetupConfig c, render::RgbMode rgb,
                                    host::GammaRule rule) {
    ShaderModels m(c);
    return shade_with(m, sc, f, c, rgb, rule, {});
}

}  // namespace spec
