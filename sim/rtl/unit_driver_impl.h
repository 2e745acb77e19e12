// unit_driver_impl.h - UnitDriverT's members; included by unit_driver.cpp (Vspec_unit) and
// unit_driver_tuned.cpp (Vspec_unit_tuned), each with its model's headers, and instantiated there.
#pragma once

#include <stdexcept>

#include "harness.h"
#include "unit_driver.h"

namespace spec {

template <class V>
UnitDriverT<V>::UnitDriverT(const std::string& vcd_path)
    : h_(new Harness<V>(active_low<V>([](V& v) -> CData& { return v.init_n; }), "spec_unit")) {
    idle_inputs();
    h_->top().eval();
    if (!vcd_path.empty()) opentrace(vcd_path);
    init();
}

template <class V>
UnitDriverT<V>::~UnitDriverT() = default;

template <class V>
V& UnitDriverT<V>::top() {
    return h_->top();
}

template <class V>
uint64_t UnitDriverT<V>::cycle() const {
    return h_->cycle();
}

template <class V>
void UnitDriverT<V>::opentrace(const std::string& vcd_path) {
    h_->opentrace(vcd_path);
}

template <class V>
void UnitDriverT<V>::idle_inputs() {
    V& t = h_->top();
    t.init_n = 1;
    t.start = 0;
    t.c_we = 0;
    t.dzeta_we = 0;
    t.zeta0_we = 0;
    t.n_we = 0;
    t.len_load_n = 1;
}

template <class V>
void UnitDriverT<V>::step() {
    h_->rise();
    idle_inputs();
    h_->fall();
    if (observer) observer(h_->cycle(), signals());
}

template <class V>
void UnitDriverT<V>::init() {
    h_->top().init_n = 0;
    step();
}

template <class V>
void UnitDriverT<V>::write(const SpanRegs& r) {
    V& t = h_->top();
    t.c_i = r.c;
    t.c_we = 1;
    t.dzeta_i = static_cast<uint32_t>(r.dzeta);
    t.dzeta_we = 1;
    t.zeta0_i = static_cast<uint32_t>(r.zeta0);
    t.zeta0_we = 1;
    t.n_i = r.n;
    t.n_we = 1;
    t.len_i = r.len;
    t.len_load_n = 0;
    step();
}

template <class V>
std::vector<uint32_t> UnitDriverT<V>::run(uint64_t max_cycles) {
    if (max_cycles == 0) max_cycles = 2 * (uint64_t(1) << 17) + 64;
    V& t = h_->top();
    std::vector<uint32_t> px;
    t.start = 1;
    step();
    for (uint64_t c = 0; t.busy_o; ++c) {
        if (c > max_cycles) throw std::runtime_error("spec_unit: busy_o did not fall");
        if (t.valid_o) px.push_back(t.intensity_o);
        step();
    }
    return px;
}

template <class V>
std::vector<int> UnitDriverT<V>::valid_cycles(const SpanRegs& r, int max_cycles) {
    write(r);
    V& t = h_->top();
    t.start = 1;
    step();
    std::vector<int> at;
    for (int c = 1; t.busy_o && c <= max_cycles; ++c) {
        if (t.valid_o) at.push_back(c);
        step();
    }
    return at;
}

template <class V>
CtrlSignals UnitDriverT<V>::signals() const {
    const V& t = h_->top();
    const auto* r = t.rootp;
    CtrlSignals s;
    s.s28 = r->spec_unit__DOT__sig28;
    s.s34 = r->spec_unit__DOT__sig34;
    s.s35_n = r->spec_unit__DOT__sig35;
    s.s36 = r->spec_unit__DOT__sig36;
    s.s37 = r->spec_unit__DOT__sig37;
    s.d30 = r->spec_unit__DOT__d30;
    s.d31 = r->spec_unit__DOT__d31;
    s.d32 = r->spec_unit__DOT__d32;
    s.d33 = r->spec_unit__DOT__d33;
    s.busy = t.busy_o;
    s.valid = t.valid_o;
    s.s29 = t.valid_o;
    s.intensity = t.intensity_o;
    return s;
}

}  // namespace spec
