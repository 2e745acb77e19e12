// unit_driver_impl.h - UnitDriverT's members; included by unit_driver.cpp (Vspec_unit) and
// unit_driver_tuned.cpp (Vspec_unit_tuned), each with its model's headers, and instantiated there.
#pragma once

#include <stdexcept>

#include "unit_driver.h"
#include "verilated.h"
#include "verilated_vcd_c.h"

namespace spec {

template <class V>
UnitDriverT<V>::UnitDriverT(const std::string& vcd_path) : ctx_(new VerilatedContext) {
    // Verilator 5.006 registers and erases a model's scopes in the thread's current context: make it ours
    // around construction and destruction (several models share a thread in the tests).
    Verilated::threadContextp(ctx_.get());
    ctx_->traceEverOn(!vcd_path.empty());
    top_.reset(new V(ctx_.get(), "spec_unit"));
    idle_inputs();
    top_->clk = 0;
    top_->eval();
    if (!vcd_path.empty()) {
        vcd_.reset(new VerilatedVcdC);
        top_->trace(vcd_.get(), 99);
        vcd_->open(vcd_path.c_str());
        if (!vcd_->isOpen()) throw std::runtime_error("cannot write " + vcd_path);
        vcd_->dump(time_);
    }
    init();
}

template <class V>
UnitDriverT<V>::~UnitDriverT() {
    Verilated::threadContextp(ctx_.get());
    if (vcd_) vcd_->close();
    top_->final();
    vcd_.reset();
    top_.reset();
}

template <class V>
void UnitDriverT<V>::idle_inputs() {
    top_->init_n = 1;
    top_->start = 0;
    top_->c_we = 0;
    top_->dzeta_we = 0;
    top_->zeta0_we = 0;
    top_->n_we = 0;
    top_->len_load_n = 1;
}

template <class V>
void UnitDriverT<V>::step() {
    top_->clk = 1;
    top_->eval();
    time_ += 5;
    if (vcd_) vcd_->dump(time_);
    idle_inputs();
    top_->clk = 0;
    top_->eval();
    time_ += 5;
    if (vcd_) vcd_->dump(time_);
    ++cycle_;
    if (observer) observer(cycle_, signals());
}

template <class V>
void UnitDriverT<V>::init() {
    top_->init_n = 0;
    step();
}

template <class V>
void UnitDriverT<V>::write(const SpanRegs& r) {
    top_->c_i = r.c;
    top_->c_we = 1;
    top_->dzeta_i = static_cast<uint32_t>(r.dzeta);
    top_->dzeta_we = 1;
    top_->zeta0_i = static_cast<uint32_t>(r.zeta0);
    top_->zeta0_we = 1;
    top_->n_i = r.n;
    top_->n_we = 1;
    top_->len_i = r.len;
    top_->len_load_n = 0;
    step();
}

template <class V>
std::vector<uint32_t> UnitDriverT<V>::run(uint64_t max_cycles) {
    if (max_cycles == 0) max_cycles = 2 * (uint64_t(1) << 17) + 64;
    std::vector<uint32_t> px;
    top_->start = 1;
    step();
    for (uint64_t c = 0; top_->busy_o; ++c) {
        if (c > max_cycles) throw std::runtime_error("spec_unit: busy_o did not fall");
        if (top_->valid_o) px.push_back(top_->intensity_o);
        step();
    }
    return px;
}

template <class V>
CtrlSignals UnitDriverT<V>::signals() const {
    const auto* r = top_->rootp;
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
    s.busy = top_->busy_o;
    s.valid = top_->valid_o;
    s.s29 = top_->valid_o;
    s.intensity = top_->intensity_o;
    return s;
}

}  // namespace spec
