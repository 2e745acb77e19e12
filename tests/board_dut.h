// board_dut.h - a Verilated module under test with one clock (boards/ unit tests).
// Verilator 5.006 registers a model's scopes in the thread's current context: make it this model's
// around construction and destruction.
#pragma once

#include <memory>

#include "verilated.h"

template <class V>
struct BoardDut {
    std::unique_ptr<VerilatedContext> ctx{current(new VerilatedContext)};
    std::unique_ptr<V> v{new V(ctx.get())};
    static VerilatedContext* current(VerilatedContext* c) {
        Verilated::threadContextp(c);
        return c;
    }
    BoardDut() {
        v->clk = 0;
        v->eval();
    }
    ~BoardDut() {
        Verilated::threadContextp(ctx.get());
        v->final();
        v.reset();
    }
    // inputs set before the call are seen at this rising edge; outputs show the next cycle afterwards
    void tick() {
        v->clk = 1;
        v->eval();
        v->clk = 0;
        v->eval();
    }
    V* operator->() { return v.get(); }
};
