// cmd_demo.h - specsim demo: the patent's Fig. 11/12 span traced signal by signal through the Verilated
// spec_unit, and representative spans beside the double-precision reference (parse -> compute -> report).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "span_core.h"
#include "spec_model.h"

namespace spec {

// The Fig. 11 run: l = 3, n = 10, C = 0.75, zeta0 = -0.15, dzeta = 0.1. rows: start 26, flip-flop 39 (28),
// strobe 37, select 36, count 34, borrow 35, busy_o, valid_o; one entry per clock, entry 0 = the cycle Start
// is high, three idle clocks after busy_o falls. vcd: also write a waveform (InputError if it cannot).
struct Fig11Run {
    SpanRegs regs;
    std::vector<std::vector<bool>> rows;   // 8 rows
    std::vector<uint32_t> pixels;
};
Fig11Run fig11_run(const std::string& vcd = "");
// The text timing diagram of the run (docs/fig11-timing.txt).
std::string fig11_diagram(const Fig11Run& r);

// One pixel of a representative span: n = 1, 3, 10, 100, 1000, C = 0.9, nine pixels from -1.5 to +1.5
// epicentres.
struct DemoPixel {
    unsigned n;
    size_t i;
    double angle, out, ref;
    bool in_epicentre;
};
std::vector<DemoPixel> representative_spans(SpanCore& core);
std::string representative_report(const std::vector<DemoPixel>& px);

}  // namespace spec
