// cmd_bench.h - specsim bench-stream and stream-diagram: spec_stream's clock cycles per pixel, simulation
// speed, and its AXI4-Stream timing drawn from a simulation (parse -> compute -> report).
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "spec_model.h"
#include "stream_driver.h"

namespace spec {

// The workload of bench-stream: spans around the highlight of a random n (within four epicentres), lengths
// 0..max_len; the same for every simulator.
std::vector<SpanRegs> bench_workload(std::mt19937_64& rng, const Model& m, size_t count, uint32_t max_len);

// Clock cycles per pixel of the Verilated spec_stream on the spans with the given stalls, and of spec_unit
// (span by span through its control block). Exact counts, independent of the machine.
double stream_cycles_per_pixel(const std::vector<SpanRegs>& spans, const Stalls& st, uint64_t seed = 7);
double unit_cycles_per_pixel(const std::vector<SpanRegs>& spans);

// Three spans (l = 2, 0, 1) through spec_stream with the sink stalled in cycles 24-25, one entry per clock:
// rows s_axis_tvalid, s_axis_tready, descriptor in, m_axis_tvalid, m_axis_tready, m_axis_tlast, pixel out.
struct StreamTrace {
    std::vector<SpanRegs> spans;
    std::vector<std::vector<bool>> rows;
    std::vector<uint32_t> pixels;
    int stall0 = 0;  // the sink stalls in cycles stall0 and stall0 + 1
};
StreamTrace stream_trace();

// bench-lanes: spec_stream with LANES = 1, 2, 4 (PACK = 0, 1) on the spans a scene gives at w x h, no stalls.
struct LanesFigure {
    std::string name;   // l1, l2, l2p, l4, l4p
    int lanes = 1;
    bool pack = false;
    uint64_t cycles = 0, beats = 0;
    double ppc = 0;     // pixels per clock
};
struct LanesRow {
    int w = 0, h = 0;
    uint64_t spans = 0, pixels = 0;
    std::vector<LanesFigure> figures;
};
// The spans the renderer sends to the core for the scene at w x h (registers as quantized for the core).
std::vector<SpanRegs> scene_spans(const std::string& scene, int w, int h);
LanesRow bench_lanes_row(const std::vector<SpanRegs>& spans, int w, int h);
// The text diagram (docs/stream-timing.txt).
std::string stream_diagram(const StreamTrace& t);

}  // namespace spec
