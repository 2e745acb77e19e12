// unit_driver.h - drives a Verilated spec_unit through its ports, as an external device would.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "span_core.h"
#include "spec_model.h"

class Vspec_unit;
class Vspec_unit_tuned;
class Vspec_unit_pow;

namespace spec {
template <class V>
class Harness;
}

namespace spec {

// The control signals of Fig. 11, read from inside the core each cycle (public signals).
struct CtrlSignals {
    bool s28, s29, s34, s35_n, s36, s37;
    bool d30, d31, d32, d33;
    bool busy, valid;
    uint32_t intensity;
};

// V: the Verilated spec_unit class (Vspec_unit: the patent's default; Vspec_unit_tuned: tuned mode;
// Vspec_unit_pow: pow mode). Instantiated in unit_driver.cpp, unit_driver_tuned.cpp and unit_driver_pow.cpp.
template <class V>
class UnitDriverT : public SpanCore {
public:
    // vcd_path: write a waveform of everything that follows (empty: none).
    explicit UnitDriverT(const std::string& vcd_path = "");
    ~UnitDriverT() override;
    UnitDriverT(const UnitDriverT&) = delete;
    UnitDriverT& operator=(const UnitDriverT&) = delete;

    V& top();
    // The harness under the driver (clock, init_n, waveform).
    Harness<V>& harness() { return *h_; }
    // A waveform of everything that follows (the model is Verilated with TRACE).
    void opentrace(const std::string& vcd_path);
    // One clock: the inputs as set now are sampled at the rising edge; afterwards the outputs show the
    // next cycle. Every input is returned to its idle value (strobes 0, init_n 1, len_load_n 1) after it.
    void step();
    void steps(int n) { for (int i = 0; i < n; ++i) step(); }
    // init_n low for one clock.
    void init();
    // Writes registers 1..4 and loads counter 5 in one clock (all strobes together).
    void write(const SpanRegs& r);
    // Pulses Start and collects the pixels until busy_o falls (at most max_cycles clocks).
    // Throws std::runtime_error on a timeout.
    std::vector<uint32_t> run(uint64_t max_cycles = 0);
    // write() then run().
    std::vector<uint32_t> span(const SpanRegs& r) override { write(r); return run(); }
    // write() and a Start, then the cycles (counted from Start's edge, 1 = the cycle after it) in which valid_o is
    // 1, until busy_o falls (at most max_cycles): the core's latencies as a test sees them.
    std::vector<int> valid_cycles(const SpanRegs& r, int max_cycles = 1000);

    CtrlSignals signals() const;
    uint64_t cycle() const override;
    // Called after every step() with the signals of the new cycle.
    std::function<void(uint64_t cycle, const CtrlSignals&)> observer;

private:
    void idle_inputs();
    std::unique_ptr<Harness<V>> h_;  // the model, its clock, init_n and the waveform (harness.h)
};

using UnitDriver = UnitDriverT<Vspec_unit>;              // the patent's configuration (rom/)
using UnitDriverTuned = UnitDriverT<Vspec_unit_tuned>;   // tuned mode (docs/tuned.md; build-tree ROM images)
using UnitDriverPow = UnitDriverT<Vspec_unit_pow>;       // pow mode (docs/pow.md; build-tree ROM images)
extern template class UnitDriverT<Vspec_unit>;          // instantiated in unit_driver.cpp
extern template class UnitDriverT<Vspec_unit_tuned>;    // unit_driver_tuned.cpp
extern template class UnitDriverT<Vspec_unit_pow>;      // and unit_driver_pow.cpp

// The Verilated spec_unit of the given mode (defined with the pow model, unit_driver_pow.cpp).
std::unique_ptr<SpanCore> make_unit_driver(Mode mode, const std::string& vcd_path = "");

}  // namespace spec
