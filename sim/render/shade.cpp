#include "shade.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>

#include <glm/geometric.hpp>

#include <stdexcept>

namespace spec {
namespace render {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

const char* model_name(SpecModel m) {
    switch (m) {
        case SpecModel::rtl: return "rtl";
        case SpecModel::golden: return "golden";
        case SpecModel::ref: return "ref";
        case SpecModel::prototype: return "prototype";
        case SpecModel::host: return "host";
        case SpecModel::shader: return "shader";
    }
    return "?";
}

SpecModel parse_model(const std::string& s) {
    for (SpecModel m : {SpecModel::rtl, SpecModel::golden, SpecModel::ref, SpecModel::prototype, SpecModel::host,
                        SpecModel::shader}) {
        if (s == model_name(m)) return m;
    }
    throw InputError("--model: '" + s + "' is not one of rtl, golden, ref, prototype, host, shader");
}

double prototype_brdf(unsigned n, double zeta) {
    if (n == 0) return 1.0;
    const double z = std::sqrt(double(n) / 2.0) * std::fabs(zeta);
    if (z >= kPi / 2) return 0.0;
    const double c = std::cos(z);
    return c * c;
}

Shading shade_base(const Scene& sc, const Frame& f) {
    Shading s;
    s.w = f.w;
    s.h = f.h;
    const size_t np = size_t(f.w) * size_t(f.h);
    s.base.assign(np * 3, 0.0f);
    s.tint.assign(np * 3, 0.0f);
    s.covered.assign(np, 0);
    for (size_t p = 0; p < np; ++p) {
        for (int c = 0; c < 3; ++c) s.base[3 * p + c] = float(sc.background[c]);
    }
    const dvec3 L = f.light_dir;
    for (const Span& sp : f.spans) {
        const Material& m = sc.objects[sp.obj].mat;
        const dvec3 amb = m.ka * sc.ambient * m.color;
        const dvec3 dif = m.kd * sc.light.intensity * sc.light.color * m.color;
        const dvec3 tint = sc.light.color * m.spec_color;
        for (uint32_t i = 0; i <= sp.l; ++i) {
            if (!f.visible(sp, i)) continue;
            const double t = sp.l ? double(i) / double(sp.l) : 0.0;
            const dvec3 n = host::slerp(sp.ends.n1, sp.ends.n2, t);
            const dvec3 v = amb + dif * std::max(0.0, glm::dot(n, L));
            const size_t p = size_t(sp.y) * size_t(f.w) + size_t(sp.x0) + i;
            for (int c = 0; c < 3; ++c) {
                s.base[3 * p + c] = float(v[c]);
                s.tint[3 * p + c] = float(tint[c]);
            }
            s.covered[p] = 1;
        }
    }
    return s;
}

SpecRun shade_specular(const Scene& sc, const Frame& f, SpecModel model, RgbMode rgb, host::GammaRule rule,
                       const Progress& progress, Mode mode) {
    return shade_specular(sc, f, model, nullptr, rgb, rule, progress, mode);
}

SpecRun shade_specular(const Scene& sc, const Frame& f, SpecModel model, SpanCore* drv, RgbMode rgb,
                       host::GammaRule rule, const Progress& progress, Mode mode) {
    const auto t0 = std::chrono::steady_clock::now();
    SpecRun r;
    r.spec.assign(size_t(f.w) * size_t(f.h) * 3, 0.0f);
    Format fmt;
    fmt.mode = mode;
    const Model core(fmt);
    ModelCore golden(core);
    if (model == SpecModel::rtl && !drv) throw std::invalid_argument("shade_specular: the rtl model needs a SpanCore");
    if (model == SpecModel::shader) throw std::invalid_argument("shade_specular: the shader model needs a SpanEndsCore");
    if (model == SpecModel::golden && !drv) drv = &golden;
    if (model != SpecModel::rtl && model != SpecModel::golden) drv = nullptr;
    const uint64_t cycle0 = drv ? drv->cycle() : 0;
    const bool per_channel = rgb == RgbMode::per_channel && (model == SpecModel::rtl || model == SpecModel::golden);
    std::vector<double> val;
    std::vector<uint32_t> px;
    const size_t total = f.spans.size();
    const size_t step = std::max<size_t>(1, total / 200);
    for (size_t k = 0; k < total; ++k) {
        const Span& sp = f.spans[k];
        const Material& m = sc.objects[sp.obj].mat;
        const double strength = sc.light.intensity * m.ks;
        const dvec3 tint = sc.light.color * m.spec_color;
        const size_t row = size_t(sp.y) * size_t(f.w) + size_t(sp.x0);
        ++r.spans;
        r.core_pixels += sp.l + 1;
        if (per_channel) {
            for (int c = 0; c < 3; ++c) {
                const host::SpanSetup s = host::setup_span(core, sp.ends, strength * tint[c], m.n, sp.l, rule);
                if (c == 0) r.counters.add(s.flags);
                px = drv->span(s.regs);
                if (px.size() != size_t(sp.l) + 1) throw std::runtime_error("shade_specular: the core gave " +
                    std::to_string(px.size()) + " pixels for a span of " + std::to_string(sp.l + 1));
                ++r.core_runs;
                for (uint32_t i = 0; i <= sp.l; ++i) {
                    if (f.visible(sp, i)) r.spec[3 * (row + i) + c] = float(core.out_value(px[i]));
                }
            }
        } else {
            const host::SpanSetup s = host::setup_span(core, sp.ends, strength, m.n, sp.l, rule);
            r.counters.add(s.flags);
            val.assign(sp.l + 1, 0.0);
            switch (model) {
                case SpecModel::rtl:
                case SpecModel::golden:
                    px = drv->span(s.regs);
                    if (px.size() != size_t(sp.l) + 1) throw std::runtime_error("shade_specular: the core gave " +
                        std::to_string(px.size()) + " pixels for a span of " + std::to_string(sp.l + 1));
                    ++r.core_runs;
                    for (uint32_t i = 0; i <= sp.l; ++i) val[i] = core.out_value(px[i]);
                    break;
                case SpecModel::ref:
                    for (uint32_t i = 0; i <= sp.l; ++i) {
                        if (f.visible(sp, i)) val[i] = host::brute_force(sp.ends, strength, m.n, sp.l, i);
                    }
                    break;
                case SpecModel::prototype:
                    for (uint32_t i = 0; i <= sp.l; ++i) val[i] = s.c_used * prototype_brdf(m.n, s.zeta0 + i * s.dzeta);
                    break;
                case SpecModel::host:
                    for (uint32_t i = 0; i <= sp.l; ++i) val[i] = s.value(i);
                    break;
                case SpecModel::shader: break;   // refused above
            }
            for (uint32_t i = 0; i <= sp.l; ++i) {
                if (!f.visible(sp, i)) continue;
                for (int c = 0; c < 3; ++c) r.spec[3 * (row + i) + c] = float(val[i] * tint[c]);
            }
        }
        if (progress && (k % step == 0 || k + 1 == total)) progress(k + 1, total);
    }
    if (drv) r.core_cycles = drv->cycle() - cycle0;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
}

Image compose(const Shading& s, const SpecRun& r) {
    Image img(s.w, s.h);
    for (size_t k = 0; k < s.base.size(); ++k) {
        const double v = std::min(1.0, std::max(0.0, double(s.base[k]) + double(r.spec[k])));
        img.rgb[k] = uint8_t(std::lround(v * 255.0));
    }
    return img;
}

}  // namespace render
}  // namespace spec
