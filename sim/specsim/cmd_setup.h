// cmd_setup.h - specsim setup: one span's end vectors through spec_setup (parse -> compute -> report).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "setup_model.h"
#include "setup_rtl.h"

namespace spec {

struct SetupOptions {
    SetupInput in;                        // the quantized beat
    std::string model = "rtl";            // rtl | golden | host
    SetupConfig config = SetupConfig::ecp5;
    bool pixels = false;                  // --pixels: the span's pixels through the whole shader
};

// argv[2..]; throws UsageError (one line) on anything missing, unknown or out of range: a vector component that
// is not finite or does not fit Q1.14, a zero vector, n, l or the strength outside their formats.
SetupOptions parse_setup(int argc, char** argv);

// What the command prints, computed: the descriptor (codes for rtl and golden, the host's double values for
// host), the flags and, with --pixels, the pixels (raw words, or the host's doubles).
struct SetupReport {
    bool host = false;
    SpanRegs regs;                 // rtl, golden
    double c = 0, zeta0 = 0, dzeta = 0;   // host: c_used and the angles in radians
    unsigned flags = 0;
    std::vector<uint32_t> pixels;  // rtl, golden
    std::vector<double> values;    // host
};
SetupReport setup_compute(const SetupOptions& o);
std::string setup_csv(const SetupOptions& o, const SetupReport& r);

}  // namespace spec
