// unit_driver.cpp - UnitDriver: the driver of the patent's Verilated spec_unit (Vspec_unit).
#include "Vspec_unit.h"
#include "Vspec_unit___024root.h"
#include "unit_driver_impl.h"

namespace spec {
template class UnitDriverT<Vspec_unit>;
}  // namespace spec
