// unit_driver_tuned.cpp - UnitDriverTuned: the driver of spec_unit Verilated in tuned mode (Vspec_unit_tuned,
// DECODER_ROM = 1, ROM images from `specrom --mode tuned` in the build tree).
#include "Vspec_unit_tuned.h"
#include "Vspec_unit_tuned___024root.h"
#include "unit_driver_impl.h"

namespace spec {
template class UnitDriverT<Vspec_unit_tuned>;

}  // namespace spec
