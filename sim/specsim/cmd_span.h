// cmd_span.h - specsim span: one span through the core (parse -> compute -> report).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "spec_model.h"

namespace spec {

struct SpanOptions {
    SpanRegs regs;                     // the registers' contents (quantized)
    double c = 0, zeta0 = 0, dzeta = 0;   // the decimal values given
    std::string model = "rtl";         // rtl | stream | golden | ref
    std::string vcd;                   // --vcd (rtl only)
    int lanes = 1;                     // --lanes (stream only): spec_stream's LANES, 1, 2 or 4
    bool pack = false;                 // --pack (stream, --lanes 4 only): PACK = 1
    Mode mode = Mode::patent;
};

// argv[2..]: throws UsageError on anything out of range, unknown or missing.
SpanOptions parse_span(int argc, char** argv);

// rtl (Verilated spec_unit), stream (Verilated spec_stream), golden (bit-exact model): the l + 1 output words.
// Throws InputError when the waveform cannot be written, std::runtime_error when a core gives a wrong count.
std::vector<uint32_t> span_pixels(const SpanOptions& o);
// ref: C * max(0, cos(zeta0 + i * dzeta))^n in double precision, i = 0..l, from the decimal values.
std::vector<double> span_reference(const SpanOptions& o);

// The CSV `specsim span` prints: "i,value", then one row per pixel (UQ0.OUT_W as a decimal with OUT_W digits;
// the reference with 16).
std::string span_csv(const Format& f, const std::vector<uint32_t>& pixels);
std::string span_csv(const std::vector<double>& reference);

// Parse messages that name a flag: --mode's value.
Mode parse_mode_flag(const std::string& flag, const std::string& value);

}  // namespace spec
