// unit_driver_up5k.cpp - the driver of spec_unit Verilated in the up5k configuration (Vspec_unit_up5k: INTERP = 1,
// ROM 12 of 4 x 256 interpolated words, ROM images from `specrom --config up5k` in the build tree). The tests
// hold it to the bit-exact model like the default configuration (README publishes its synthesis figures).
#include "Vspec_unit_up5k.h"
#include "Vspec_unit_up5k___024root.h"
#include "unit_driver_impl.h"

namespace spec {
template class UnitDriverT<Vspec_unit_up5k>;
}  // namespace spec
