// stream_driver.h - drives a Verilated spec_stream through its AXI4-Stream ports.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "spec_model.h"
#include "spec_params.h"
#include "verilated.h"

namespace spec {

// The descriptor layout of spec_stream (rtl/spec_stream.v) as the generator writes it (rom/spec_params.h),
// DESC_W bits as 32-bit words (the Verilated s_axis_tdata).
constexpr int kDescWords = spec_params::DESC_W / 32;
static_assert(spec_params::DESC_W % 32 == 0, "the descriptor is a whole number of 32-bit words");

// Puts the low `width` bits of v into w at bit lsb.
inline void put_field(uint32_t* w, int lsb, int width, uint64_t v) {
    for (int b = 0; b < width; ++b) {
        const int bit = lsb + b;
        const uint32_t m = 1u << (bit % 32);
        if ((v >> b) & 1u) w[bit / 32] |= m;
        else w[bit / 32] &= ~m;
    }
}

inline void pack_descriptor(const SpanRegs& r, uint32_t w[kDescWords]) {
    for (int i = 0; i < kDescWords; ++i) w[i] = 0;
    using namespace spec_params;
    put_field(w, DESC_C_LSB, C_W, r.c);
    put_field(w, DESC_N_LSB, N_W, r.n);
    put_field(w, DESC_L_LSB, L_W, r.len);
    put_field(w, DESC_ZETA0_LSB, ANG_W, static_cast<uint64_t>(r.zeta0));
    put_field(w, DESC_DZETA_LSB, ANG_W, static_cast<uint64_t>(r.dzeta));
}

// The descriptor's bits outside its fields (which the core ignores), as a mask per word.
inline void ignored_mask(uint32_t w[kDescWords]) {
    SpanRegs ones;
    ones.c = ~0u;
    ones.n = ~0u;
    ones.len = ~0u;
    ones.zeta0 = -1;
    ones.dzeta = -1;
    pack_descriptor(ones, w);
    for (int i = 0; i < kDescWords; ++i) w[i] = ~w[i];
}

struct StreamPixel {
    uint32_t value;
    bool last;
};

// Per-cycle probability (0..1) that the source offers a descriptor and that the sink is ready.
struct Stalls {
    double in_valid = 1.0;
    double out_ready = 1.0;
};

template <class V>
class StreamDriver {
public:
    // Verilator 5.006 registers and erases a model's scopes in the *thread's* current context, so it is
    // set to this model's context around construction and destruction (several models share a thread).
    StreamDriver() : ctx_(make_current(new VerilatedContext)), top_(new V(ctx_.get())) {
        idle();
        top_->clk = 0;
        top_->eval();
        reset();
    }
    ~StreamDriver() {
        Verilated::threadContextp(ctx_.get());
        top_->final();
        top_.reset();
    }
    V& top() { return *top_; }
    uint64_t cycle() const { return cycle_; }
    // Descriptors with every ignored bit set (docs/stream.md: "the bits between the fields are ignored").
    void set_ignored_bits(bool ones) { ignored_ones_ = ones; }

    void reset() {
        top_->rst_n = 0;
        step();
        top_->rst_n = 1;
    }
    // One clock; afterwards the outputs show the next cycle.
    void step() {
        top_->clk = 1;
        top_->eval();
        top_->clk = 0;
        top_->eval();
        ++cycle_;
    }
    // Runs the spans through, with random stalls on both sides, and returns the pixels in order.
    // `on_cycle` (optional) is called each cycle before the edge, after inputs are set.
    std::vector<StreamPixel> run(const std::vector<SpanRegs>& spans, const Stalls& st, std::mt19937_64& rng,
                                 uint64_t max_cycles = 0, const std::function<void(V&)>& on_cycle = {}) {
        size_t expect = 0;
        for (const auto& s : spans) expect += size_t(s.len) + 1;
        if (max_cycles == 0) max_cycles = 64 + expect * 64;
        std::bernoulli_distribution offer(st.in_valid), ready(st.out_ready);
        std::vector<StreamPixel> out;
        out.reserve(expect);
        size_t next = 0;
        bool offering = false;
        uint64_t c = 0;
        while (out.size() < expect || next < spans.size()) {
            if (++c > max_cycles) throw std::runtime_error("spec_stream: no progress (deadlock?)");
            // AXI source: once valid is raised it stays until accepted
            if (!offering && next < spans.size() && offer(rng)) offering = true;
            top_->s_axis_tvalid = offering;
            if (offering) {
                uint32_t w[kDescWords];
                pack_descriptor(spans[next], w);
                if (ignored_ones_) {  // the bits between the fields, which the core must ignore
                    uint32_t m[kDescWords];
                    ignored_mask(m);
                    for (int i = 0; i < kDescWords; ++i) w[i] |= m[i];
                }
                for (int i = 0; i < kDescWords; ++i) top_->s_axis_tdata[i] = w[i];
            }
            top_->m_axis_tready = ready(rng);
            top_->eval();
            if (on_cycle) on_cycle(*top_);
            const bool in_fire = top_->s_axis_tvalid && top_->s_axis_tready;
            const bool out_fire = top_->m_axis_tvalid && top_->m_axis_tready;
            if (out_fire) out.push_back({top_->m_axis_tdata, top_->m_axis_tlast != 0});
            step();
            if (in_fire) {
                offering = false;
                ++next;
            }
        }
        return out;
    }

private:
    static VerilatedContext* make_current(VerilatedContext* c) {
        Verilated::threadContextp(c);
        return c;
    }
    void idle() {
        top_->rst_n = 1;
        top_->s_axis_tvalid = 0;
        top_->m_axis_tready = 1;
        for (int i = 0; i < kDescWords; ++i) top_->s_axis_tdata[i] = 0;
    }
    std::unique_ptr<VerilatedContext> ctx_;  // heap-allocated, destroyed after the model
    std::unique_ptr<V> top_;
    uint64_t cycle_ = 0;
    bool ignored_ones_ = false;
};

}  // namespace spec
