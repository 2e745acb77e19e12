// span_core.h - what the renderer, the analysis and specsim need from a core that runs spans, whichever it is:
// the Verilated spec_unit (UnitDriver, sim/rtl), the Verilated spec_stream (StreamCore, sim/rtl) or the
// bit-exact model (ModelCore). The renderer takes one of these; it never builds a Verilated model itself.
#pragma once

#include <cstdint>
#include <vector>

#include "spec_model.h"

namespace spec {

class SpanCore {
public:
    virtual ~SpanCore() = default;
    // Loads registers 1..4 and counter 5 with r, runs the span, returns its l + 1 pixels (raw output words).
    virtual std::vector<uint32_t> span(const SpanRegs& r) = 0;
    // Clock cycles simulated so far (0 for a core without a clock).
    virtual uint64_t cycle() const = 0;
};

// The bit-exact C++ model as a SpanCore (same pixels as the RTL, no clock).
class ModelCore : public SpanCore {
public:
    explicit ModelCore(const Model& m) : m_(m) {}
    std::vector<uint32_t> span(const SpanRegs& r) override { return m_.span(r); }
    uint64_t cycle() const override { return 0; }

private:
    const Model& m_;
};

}  // namespace spec
