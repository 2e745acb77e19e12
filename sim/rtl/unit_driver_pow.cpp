// unit_driver_pow.cpp - UnitDriverPow: the driver of spec_unit Verilated in pow mode (Vspec_unit_pow, POW = 1,
// ROM images from `specrom --mode pow` in the build tree, docs/pow.md), and make_unit_driver for every mode.
#include "Vspec_unit_pow.h"
#include "Vspec_unit_pow___024root.h"
#include "unit_driver_impl.h"

namespace spec {
template class UnitDriverT<Vspec_unit_pow>;

std::unique_ptr<SpanCore> make_unit_driver(Mode mode, const std::string& vcd_path) {
    if (mode == Mode::tuned) return std::unique_ptr<SpanCore>(new UnitDriverTuned(vcd_path));
    if (mode == Mode::pow) return std::unique_ptr<SpanCore>(new UnitDriverPow(vcd_path));
    return std::unique_ptr<SpanCore>(new UnitDriver(vcd_path));
}
}  // namespace spec
