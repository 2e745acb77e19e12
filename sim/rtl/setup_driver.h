// setup_driver.h - the span-ends beat of spec_setup / spec_shader (docs/setup.md) packed in C++, and a
// driver for the Verilated spec_setup_pipe (the fully pipelined arithmetic, no handshake).
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <random>
#include <memory>
#include <stdexcept>
#include <vector>

#include "setup_model.h"
#include "verilated.h"

namespace spec {

// The 256-bit span-ends beat as eight 32-bit words (word k = bits [32k +: 32]).
inline void pack_setup_beat(const SetupInput& in, uint32_t w[8]) {
    uint16_t c[12];
    const int32_t* v[4] = {in.n1, in.n2, in.h1, in.h2};
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 3; ++k) c[3 * i + k] = static_cast<uint16_t>(v[i][k]);
    for (int i = 0; i < 6; ++i) w[i] = uint32_t(c[2 * i]) | (uint32_t(c[2 * i + 1]) << 16);
    w[6] = (in.strength & 0xffffu) | ((in.n & 0x3ffu) << 16);
    w[7] = (in.l & 0xffffu) | (in.midpoint ? (1u << 16) : 0u);
}

// The descriptor spec_setup writes (spec_stream's layout) back into register contents.
inline SpanRegs unpack_descriptor(const uint32_t w[4]) {
    SpanRegs r;
    r.c = w[0] & 0xffffu;
    r.n = (w[0] >> 16) & 0x3ffu;
    r.len = w[1] & 0xffffu;
    r.zeta0 = static_cast<int32_t>(w[2]);
    r.dzeta = static_cast<int32_t>(w[3]);
    return r;
}

struct SetupOut {
    SpanRegs regs;
    unsigned flags;
    uint32_t raw_hi = 0;   // the descriptor's reserved bits (must be 0)
};

// Drives Vspec_setup_pipe: one span per call of push (or a bubble), outputs collected in order.
template <class V>
class SetupPipeDriver {
public:
    SetupPipeDriver() : ctx_(make_current(new VerilatedContext)), top_(new V(ctx_.get())) {
        top_->clk = 0;
        top_->rst = 1;
        top_->in_valid = 0;
        top_->eval();
        step();
        top_->rst = 0;
    }
    ~SetupPipeDriver() {
        Verilated::threadContextp(ctx_.get());
        top_->final();
        top_.reset();
    }
    V& top() { return *top_; }
    // One clock with the span (or none) at the input.
    void push(const SetupInput* in) {
        top_->in_valid = in != nullptr;
        if (in) {
            uint32_t w[8];
            pack_setup_beat(*in, w);
            for (int i = 0; i < 6; ++i) top_->in_vec[i] = w[i];
            top_->in_str = w[6] & 0xffffu;
            top_->in_n = (w[6] >> 16) & 0x3ffu;
            top_->in_l = w[7] & 0xffffu;
            top_->in_rule = (w[7] >> 16) & 1u;
        }
        step();
    }
    std::vector<SetupOut>& out() { return out_; }

private:
    void step() {
        top_->clk = 1;
        top_->eval();
        top_->clk = 0;
        top_->eval();
        if (top_->out_valid) {
            SetupOut o;
            o.regs.c = top_->out_c;
            o.regs.n = top_->out_n;
            o.regs.len = top_->out_l;
            o.regs.zeta0 = static_cast<int32_t>(top_->out_zeta0);
            o.regs.dzeta = static_cast<int32_t>(top_->out_dzeta);
            o.flags = top_->out_flags;
            out_.push_back(o);
        }
    }
    static VerilatedContext* make_current(VerilatedContext* c) {
        Verilated::threadContextp(c);
        return c;
    }
    std::unique_ptr<VerilatedContext> ctx_;
    std::unique_ptr<V> top_;
    std::vector<SetupOut> out_;
};

// Drives a Verilated spec_setup (either configuration) through its AXI4-Stream ports with random stalls on
// both sides (per-cycle probabilities that the source offers a beat and that the sink is ready).
template <class V>
class SetupStreamDriver {
public:
    SetupStreamDriver() : ctx_(make_current(new VerilatedContext)), top_(new V(ctx_.get())) {
        top_->clk = 0;
        top_->s_axis_tvalid = 0;
        top_->m_axis_tready = 1;
        top_->rst_n = 1;
        top_->eval();
        reset();
    }
    ~SetupStreamDriver() {
        Verilated::threadContextp(ctx_.get());
        top_->final();
        top_.reset();
    }
    V& top() { return *top_; }
    uint64_t cycle() const { return cycle_; }
    void reset() {
        top_->rst_n = 0;
        step();
        top_->rst_n = 1;
    }
    void step() {
        top_->clk = 1;
        top_->eval();
        top_->clk = 0;
        top_->eval();
        ++cycle_;
    }
    // Sends the spans (offer / ready: probabilities per cycle) and returns the descriptors in order.
    // `on_cycle` is called each cycle after the inputs are set, before the clock edge.
    std::vector<SetupOut> run(const std::vector<SetupInput>& spans, double offer_p, double ready_p, std::mt19937_64& rng,
                              uint64_t max_cycles = 0, const std::function<void(V&)>& on_cycle = {}) {
        if (max_cycles == 0) max_cycles = 20000 + spans.size() * 4000;
        std::bernoulli_distribution offer(offer_p), ready(ready_p);
        std::vector<SetupOut> out;
        size_t next = 0;
        bool offering = false;
        for (uint64_t c = 0; out.size() < spans.size(); ++c) {
            if (c > max_cycles) throw std::runtime_error("spec_setup: no progress (deadlock?)");
            if (!offering && next < spans.size() && offer(rng)) offering = true;
            top_->s_axis_tvalid = offering;
            if (offering) {
                uint32_t w[8];
                pack_setup_beat(spans[next], w);
                for (int i = 0; i < 8; ++i) top_->s_axis_tdata[i] = w[i];
            }
            top_->m_axis_tready = ready(rng);
            top_->eval();
            if (on_cycle) on_cycle(*top_);
            const bool in_fire = top_->s_axis_tvalid && top_->s_axis_tready;
            if (top_->m_axis_tvalid && top_->m_axis_tready) {
                uint32_t w[4];
                for (int i = 0; i < 4; ++i) w[i] = top_->m_axis_tdata[i];
                out.push_back({unpack_descriptor(w), static_cast<unsigned>(top_->m_axis_tuser)});
                out.back().raw_hi = w[0] >> 26 | (w[1] & 0xffff0000u);
            }
            step();
            if (in_fire) {
                offering = false;
                ++next;
            }
        }
        top_->s_axis_tvalid = 0;
        return out;
    }

private:
    static VerilatedContext* make_current(VerilatedContext* c) {
        Verilated::threadContextp(c);
        return c;
    }
    std::unique_ptr<VerilatedContext> ctx_;
    std::unique_ptr<V> top_;
    uint64_t cycle_ = 0;
};

}  // namespace spec
