// shade_ends.cpp - the specular pass through a core that takes the span's ends (SpanEndsCore: spec_shader).
#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

#include "shade.h"

namespace spec {
namespace render {

SpecRun shade_specular(const Scene& sc, const Frame& f, SpanEndsCore& core, RgbMode rgb, host::GammaRule rule,
                       const Progress& progress, size_t batch) {
    const auto t0 = std::chrono::steady_clock::now();
    SpecRun r;
    r.spec.assign(size_t(f.w) * size_t(f.h) * 3, 0.0f);
    const Model& out = core.pixel_model();
    const uint64_t cycle0 = core.cycle();
    const bool per_channel = rgb == RgbMode::per_channel;
    const size_t total = f.spans.size();
    batch = std::max<size_t>(1, batch);
    std::vector<SpanEndsJob> jobs;
    for (size_t k0 = 0; k0 < total; k0 += batch) {
        const size_t k1 = std::min(total, k0 + batch);
        for (int ch = 0; ch < (per_channel ? 3 : 1); ++ch) {
            jobs.clear();
            for (size_t k = k0; k < k1; ++k) {
                const Span& sp = f.spans[k];
                const Material& m = sc.objects[sp.obj].mat;
                double strength = sc.light.intensity * m.ks;
                if (per_channel) strength *= (sc.light.color * m.spec_color)[ch];
                jobs.push_back({sp.ends, strength, m.n, sp.l, rule});
            }
            const std::vector<SpanEndsResult> res = core.spans(jobs);
            if (res.size() != jobs.size()) {
                throw std::runtime_error("shade_specular: the core gave " + std::to_string(res.size()) +
                                         " spans for " + std::to_string(jobs.size()));
            }
            for (size_t k = k0; k < k1; ++k) {
                const Span& sp = f.spans[k];
                const SpanEndsResult& s = res[k - k0];
                if (s.pixels.size() != size_t(sp.l) + 1) {
                    throw std::runtime_error("shade_specular: the core gave " + std::to_string(s.pixels.size()) +
                                             " pixels for a span of " + std::to_string(sp.l + 1));
                }
                const dvec3 tint = sc.light.color * sc.objects[sp.obj].mat.spec_color;
                const size_t row = size_t(sp.y) * size_t(f.w) + size_t(sp.x0);
                if (ch == 0) {
                    r.counters.add(s.flags & 0x3fu);
                    ++r.spans;
                    r.core_pixels += sp.l + 1;
                }
                ++r.core_runs;
                for (uint32_t i = 0; i <= sp.l; ++i) {
                    if (!f.visible(sp, i)) continue;
                    const double v = out.out_value(s.pixels[i]);
                    if (per_channel) r.spec[3 * (row + i) + ch] = float(v);
                    else
                        for (int q = 0; q < 3; ++q) r.spec[3 * (row + i) + q] = float(v * tint[q]);
                }
            }
        }
        if (progress) progress(k1, total);
    }
    r.core_cycles = core.cycle() - cycle0;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
}

}  // namespace render
}  // namespace spec
