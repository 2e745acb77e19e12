// span_ends_core.h - a core that takes a span's ends and does the span's setup itself (spec_shader: spec_setup
// -> spec_stream, sim/setup), as the renderer sees it: beside SpanCore (sim/model/span_core.h), which takes the
// host's register contents. The renderer passes only what it interpolated (N and H at the span's ends), the
// material's strength and exponent, the span's length and the gamma rule; the core quantizes them into its
// input beat. The renderer never builds a Verilated model itself.
#pragma once

#include <cstdint>
#include <vector>

#include "span_host.h"
#include "spec_model.h"

namespace spec {

struct SpanEndsJob {
    host::SpanEnds ends;   // N1, N2, H1, H2 as interpolated (not necessarily unit length)
    double strength = 0;   // Is * ks (times the channel's tint with RgbMode::per_channel)
    unsigned n = 0;        // exponent
    uint32_t l = 0;        // intervals: l + 1 pixels
    host::GammaRule rule = host::GammaRule::patent;
};

struct SpanEndsResult {
    std::vector<uint32_t> pixels;   // l + 1 raw output words
    unsigned flags = 0;             // the span's degenerate-case flags (bits 0-5 are the host's, span_host.h)
};

class SpanEndsCore {
public:
    virtual ~SpanEndsCore() = default;
    // Runs the spans, streamed back to back, and returns each one's pixels and flags, in order.
    virtual std::vector<SpanEndsResult> spans(const std::vector<SpanEndsJob>& jobs) = 0;
    // Clock cycles simulated so far (0 for a core without a clock).
    virtual uint64_t cycle() const = 0;
    // The bit-exact model of the core's pixel stage: the format its output words are read in.
    virtual const Model& pixel_model() const = 0;
};

}  // namespace spec
