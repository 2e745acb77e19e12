// parallax_rtl.h - rtl/parallax_iter.v run by Verilator against a memory model: the results of a list of
// fragments and the clock cycles they took (the tests, and the throughput table of `specsim parallax`).
#pragma once

#include <cstdint>
#include <vector>

#include "parallax_fixed.h"

namespace spec {
namespace methods {

// The memory behind the request/response ports, and the traffic on the other two ports.
struct IterRunConfig {
    int latency_min = 1, latency_max = 1;  // cycles from a request's handshake to its response (>= 1)
    bool in_order = true;      // false: of the responses due, a random one goes first
    double p_req_stall = 0;    // per cycle: req_ready low
    double p_out_stall = 0;    // per cycle: m_ready low
    double p_in_gap = 0;       // per cycle: s_valid low although a fragment is waiting
    uint64_t seed = 1;
    // protocol noise the unit must ignore: per cycle, a response for a slot that has nothing outstanding
    double p_bogus_rsp = 0;
};
struct IterRunResult {
    std::vector<FixedHit> hits;     // per job, in the jobs' order
    std::vector<int> seen;          // per job: how many results carried its tag (must be 1)
    uint64_t cycles = 0;            // from the first fragment offered to the last result taken
    uint64_t requests = 0;          // fetch requests handed to the memory
    uint64_t steps = 0;             // sum of the results' iteration counts
    bool timed_out = false;
    bool stable = true;             // req_* and m_* held still while valid and not ready
};

// The Verilated builds of rtl/parallax_iter.v: SLOTS = 1, 4 (the default) and 16, each with TAG_W = 16 and the
// default formats (StepFormat).
enum class IterBuild { slots1, slots4, slots16 };
int iter_slots(IterBuild b);
IterRunResult run_parallax_iter(IterBuild b, const std::vector<IterJob>& jobs, const HeightFetch& fetch,
                                const IterRunConfig& cfg);

// Throughput of the Verilated unit: the fragments of `jobs` through each build at each fixed memory latency
// (in order, no stalls); steps per clock, and whether every result equals iterate_fixed's.
struct ThroughputCell {
    IterBuild build = IterBuild::slots4;
    int latency = 1;
    uint64_t steps = 0, cycles = 0;
    uint64_t mismatches = 0;
};
std::vector<ThroughputCell> iter_throughput(const std::vector<IterJob>& jobs, const HeightFetch& fetch,
                                            const std::vector<int>& latencies);

}  // namespace methods
}  // namespace spec
