// setup_rtl.h - spec_setup and spec_shader through their Verilated models, for specsim, the renderer and the
// benches: the configurations, one span, and batches of spans streamed back to back.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "setup_model.h"
#include "spec_format.h"

namespace spec {

// The shader's configurations (docs/setup.md): the setup's architecture and spec_stream's configuration.
enum class SetupConfig {
    pipelined,   // spec_setup fully pipelined (a new span every clock), spec_stream's default configuration
    small,       // spec_setup one span at a time (the UP5K), spec_stream's up5k configuration
};
const char* setup_config_name(SetupConfig c);
// Throws std::invalid_argument (one line) for anything but "pipelined" or "small".
SetupConfig parse_setup_config(const std::string& s);
// spec_stream's format in the configuration (the core's bit-exact model for its pixels).
Format shader_core_format(SetupConfig c);

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
