// setup_rtl.h - spec_setup and spec_shader through their Verilated models, for specsim, the renderer and the
// benches: the configurations, one span, and batches of spans streamed back to back.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "setup_config.h"

namespace spec {

struct SetupDescriptor {
    SpanRegs regs;
    unsigned flags = 0;
};

// One span through the Verilated spec_setup of the configuration.
SetupDescriptor setup_rtl(SetupConfig c, const SetupInput& in);

// Spans through the Verilated spec_shader, streamed back to back with the sink always ready: each span's
// pixels (raw UQ0.16 words) and flags. Throws std::runtime_error when the shader's output is malformed
// (a misplaced tlast, flags changing inside a span, a missing or extra pixel).
class ShaderRtl {
public:
    virtual ~ShaderRtl() = default;
    struct Span {
        std::vector<uint32_t> pixels;
        unsigned flags = 0;
    };
    virtual std::vector<Span> run(const std::vector<SetupInput>& spans) = 0;
    virtual uint64_t cycles() const = 0;   // clock cycles simulated so far
};
std::unique_ptr<ShaderRtl> make_shader_rtl(SetupConfig c);

}  // namespace spec
