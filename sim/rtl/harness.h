// harness.h - the one Verilated-harness template under every driver and testbench (ZipCPU's testb.h,
// jamieiles/80x86's clock driver): the model in its own VerilatedContext, the clock (tick), the reset
// (reset) and an optional waveform (opentrace). UnitDriver, StreamDriver and the module tests build on it.
//
//   Harness<Vspec_counter> h(active_high<Vspec_counter>([](Vspec_counter& v) -> CData& { return v.rst; }));
//   h.reset();                 // the reset port active for one clock, then inactive
//   h->load_n = 0; h.tick();   // inputs set, one clock: rising edge, falling edge
//   h.opentrace("c.vcd");      // from now on every edge is dumped (models Verilated with TRACE only)
//
// Verilator 5.006 registers and erases a model's scopes in the thread's *current* context, so the harness
// makes its context current around construction and destruction: several models can share a thread.
// A model without a clk port (a combinational block) gets the context handling and eval() only.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "verilated.h"
#include "verilated_vcd_c.h"

namespace spec {

namespace harness_detail {
template <class T, class = void>
struct has_clk : std::false_type {};
template <class T>
struct has_clk<T, std::void_t<decltype(std::declval<T&>().clk)>> : std::true_type {};
// Verilated with --trace (CMake's verilate(... TRACE)): the model has trace(VerilatedVcdC*, int).
template <class T, class = void>
struct has_trace : std::false_type {};
template <class T>
struct has_trace<T, std::void_t<decltype(std::declval<T&>().trace(std::declval<VerilatedVcdC*>(), 0))>>
    : std::true_type {};
}  // namespace harness_detail

// The model's reset port and its active level. `port` returns a reference to the input (Verilator ports are
// references, so a lambda stands where a pointer to member cannot).
template <class V>
struct ResetPort {
    CData& (*port)(V&) = nullptr;
    bool active_low = false;
};
template <class V>
ResetPort<V> active_low(CData& (*port)(V&)) { return ResetPort<V>{port, true}; }
template <class V>
ResetPort<V> active_high(CData& (*port)(V&)) { return ResetPort<V>{port, false}; }

template <class V>
class Harness {
public:
    static constexpr bool kClocked = harness_detail::has_clk<V>::value;
    static constexpr bool kTraceable = harness_detail::has_trace<V>::value;

    // The model is built with its reset port inactive and the clock low, then evaluated once. No reset is
    // applied here: call reset() (the drivers do, in their constructors).
    explicit Harness(ResetPort<V> rst = {}, const char* name = "TOP")
        : ctx_(make_current(new VerilatedContext)), top_(new V(ctx_.get(), name)), rst_(rst) {
        if (rst_.port) rst_.port(*top_) = rst_.active_low ? 1 : 0;
        if constexpr (kClocked) top_->clk = 0;
        top_->eval();
    }
    ~Harness() {
        Verilated::threadContextp(ctx_.get());
        closetrace();
        top_->final();
        top_.reset();
    }
    Harness(const Harness&) = delete;
    Harness& operator=(const Harness&) = delete;

    V& top() { return *top_; }
    const V& top() const { return *top_; }
    V* operator->() { return top_.get(); }
    VerilatedContext& context() { return *ctx_; }
    // Clocks completed (rising edges) since construction.
    uint64_t cycle() const { return cycle_; }

    // The two halves of a clock, for drivers that change inputs between the edges. rise(): clk 1, eval (the
    // registers take the inputs as set now), dump. fall(): clk 0, eval, dump; the outputs show the next cycle.
    void rise() {
        static_assert(kClocked, "rise(): the model has no clk port");
        top_->clk = 1;
        top_->eval();
        time_ += 5;
        if (dump_) dump_(time_);
    }
    void fall() {
        top_->clk = 0;
        top_->eval();
        time_ += 5;
        if (dump_) dump_(time_);
        ++cycle_;
    }
    // One clock: the inputs as set now are sampled at the rising edge.
    void tick() {
        rise();
        fall();
    }
    void ticks(uint64_t n) {
        for (uint64_t i = 0; i < n; ++i) tick();
    }
    // The reset port active for `cycles` clocks, then inactive (evaluated, so that outputs are current).
    void reset(int cycles = 1) {
        if (!rst_.port) throw std::logic_error("Harness::reset: the model was given no reset port");
        rst_.port(*top_) = rst_.active_low ? 0 : 1;
        for (int i = 0; i < cycles; ++i) tick();
        rst_.port(*top_) = rst_.active_low ? 1 : 0;
        top_->eval();
    }

    // A VCD of everything that follows (one timestep = half a clock, 5 units). Throws std::runtime_error when
    // the file cannot be written and std::logic_error when the model was Verilated without TRACE.
    void opentrace(const std::string& path) {
        if constexpr (kTraceable) {
            closetrace();
            ctx_->traceEverOn(true);
            auto vcd = std::make_shared<VerilatedVcdC>();
            top_->trace(vcd.get(), 99);
            vcd->open(path.c_str());
            if (!vcd->isOpen()) throw std::runtime_error("cannot write " + path);
            vcd->dump(time_);
            dump_ = [vcd](uint64_t t) { vcd->dump(t); };
            close_ = [vcd] { vcd->close(); };
        } else {
            throw std::logic_error("opentrace(" + path + "): the model was Verilated without TRACE");
        }
    }
    void closetrace() {
        if (close_) close_();
        dump_ = nullptr;
        close_ = nullptr;
    }
    bool tracing() const { return static_cast<bool>(dump_); }

private:
    static VerilatedContext* make_current(VerilatedContext* c) {
        Verilated::threadContextp(c);
        return c;
    }
    std::unique_ptr<VerilatedContext> ctx_;  // destroyed after the model
    std::unique_ptr<V> top_;
    ResetPort<V> rst_;
    uint64_t cycle_ = 0;
    uint64_t time_ = 0;
    // type-erased so that a model Verilated without TRACE never references the VCD writer's code
    std::function<void(uint64_t)> dump_;
    std::function<void()> close_;
};

}  // namespace spec
