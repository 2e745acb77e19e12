#include "setup_rtl.h"

#include <random>
#include <stdexcept>

#include "Vspec_setup.h"
#include "Vspec_setup_small.h"
#include "Vspec_shader.h"
#include "Vspec_shader_up5k.h"
#include "setup_driver.h"

namespace spec {

namespace {
template <class V>
SetupDescriptor setup_one(const SetupInput& in) {
    SetupStreamDriver<V> d;
    std::mt19937_64 rng(1);
    const std::vector<SetupOut> out = d.run({in}, 1.0, 1.0, rng);
    if (out.size() != 1) throw std::runtime_error("spec_setup gave " + std::to_string(out.size()) + " descriptors for one span");
    return {out[0].regs, out[0].flags};
}

template <class V>
class ShaderRtlImpl : public ShaderRtl {
public:
    std::vector<Span> run(const std::vector<SetupInput>& spans) override {
        std::mt19937_64 rng(1);
        const std::vector<ShaderPixel> px = d_.run(spans, 1.0, 1.0, rng);
        std::vector<Span> out(spans.size());
        size_t k = 0;
        for (size_t s = 0; s < spans.size(); ++s) {
            const uint32_t len = spans[s].l & 0xffffu;
            out[s].pixels.reserve(size_t(len) + 1);
            for (uint32_t i = 0; i <= len; ++i, ++k) {
                if (k >= px.size()) throw std::runtime_error("spec_shader: missing pixels");
                if (px[k].last != (i == len)) throw std::runtime_error("spec_shader: tlast misplaced in span " + std::to_string(s));
                if (i == 0) out[s].flags = px[k].flags;
                else if (px[k].flags != out[s].flags) throw std::runtime_error("spec_shader: tuser changed inside a span");
                out[s].pixels.push_back(px[k].value);
            }
        }
        if (k != px.size()) throw std::runtime_error("spec_shader: extra pixels");
        return out;
    }
    uint64_t cycles() const override { return d_.cycle(); }

private:
    ShaderDriver<V> d_;
};
}  // namespace

SetupDescriptor setup_rtl(SetupConfig c, const SetupInput& in) {
    return c == SetupConfig::up5k ? setup_one<Vspec_setup_small>(in) : setup_one<Vspec_setup>(in);
}

std::unique_ptr<ShaderRtl> make_shader_rtl(SetupConfig c) {
    if (c == SetupConfig::up5k) return std::make_unique<ShaderRtlImpl<Vspec_shader_up5k>>();
    return std::make_unique<ShaderRtlImpl<Vspec_shader>>();
}

}  // namespace spec
