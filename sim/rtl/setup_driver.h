// setup_driver.h - the span-ends beat of spec_setup / spec_shader (docs/setup.md) packed in C++, and drivers for
// the Verilated spec_setup, spec_setup_small and spec_shader (AXI4-Stream, random stalls), all on the one
// Verilated-harness template (harness.h).
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <random>
#include <memory>
#include <stdexcept>
#include <vector>

#include "harness.h"
#include "setup_model.h"
#include "setup_params.h"
#include "spec_params.h"
#include "verilated.h"

namespace spec {

// Bits [lsb +: width] of a little-endian array of 32-bit words.
inline void put_bits(uint32_t* w, int lsb, int width, uint64_t v) {
    for (int b = 0; b < width; ++b) {
        const int pos = lsb + b;
        if ((v >> b) & 1) w[pos / 32] |= 1u << (pos % 32);
        else w[pos / 32] &= ~(1u << (pos % 32));
    }
}
inline uint64_t get_bits(const uint32_t* w, int lsb, int width) {
    uint64_t v = 0;
    for (int b = 0; b < width; ++b) v |= uint64_t((w[(lsb + b) / 32] >> ((lsb + b) % 32)) & 1) << b;
    return v;
}

// The span-ends beat (docs/setup.md; offsets from rom/setup_params.h) as BEAT_W / 32 words.
inline void pack_setup_beat(const SetupInput& in, uint32_t w[setup_params::BEAT_W / 32]) {
    for (int i = 0; i < setup_params::BEAT_W / 32; ++i) w[i] = 0;
    const int32_t* v[4] = {in.n1, in.n2, in.h1, in.h2};
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 3; ++k)
            put_bits(w, setup_params::BEAT_VEC_LSB + 16 * (3 * i + k), setup_params::VEC_W, static_cast<uint32_t>(v[i][k]));
    put_bits(w, setup_params::BEAT_STR_LSB, setup_params::STR_W, in.strength);
    put_bits(w, setup_params::BEAT_N_LSB, spec_params::N_W, in.n);
    put_bits(w, setup_params::BEAT_L_LSB, spec_params::L_W, in.l);
    put_bits(w, setup_params::BEAT_RULE_BIT, 1, in.midpoint ? 1 : 0);
}

// spec_stream's descriptor (offsets from rom/spec_params.h) back into register contents.
inline SpanRegs unpack_descriptor(const uint32_t w[spec_params::DESC_W / 32]) {
    SpanRegs r;
    r.c = static_cast<uint32_t>(get_bits(w, spec_params::DESC_C_LSB, spec_params::C_W));
    r.n = static_cast<uint32_t>(get_bits(w, spec_params::DESC_N_LSB, spec_params::N_W));
    r.len = static_cast<uint32_t>(get_bits(w, spec_params::DESC_L_LSB, spec_params::L_W));
    r.zeta0 = static_cast<int32_t>(get_bits(w, spec_params::DESC_ZETA0_LSB, spec_params::ANG_W));
    r.dzeta = static_cast<int32_t>(get_bits(w, spec_params::DESC_DZETA_LSB, spec_params::ANG_W));
    return r;
}
// The descriptor's bits outside its fields (spec_setup writes 0 there).
inline bool descriptor_reserved_zero(const uint32_t w[spec_params::DESC_W / 32]) {
    uint32_t m[spec_params::DESC_W / 32] = {};
    for (int i = 0; i < spec_params::DESC_W / 32; ++i) m[i] = w[i];
    put_bits(m, spec_params::DESC_C_LSB, spec_params::C_W, 0);
    put_bits(m, spec_params::DESC_N_LSB, spec_params::N_W, 0);
    put_bits(m, spec_params::DESC_L_LSB, spec_params::L_W, 0);
    put_bits(m, spec_params::DESC_ZETA0_LSB, spec_params::ANG_W, 0);
    put_bits(m, spec_params::DESC_DZETA_LSB, spec_params::ANG_W, 0);
    for (int i = 0; i < spec_params::DESC_W / 32; ++i)
        if (m[i]) return false;
    return true;
}

struct SetupOut {
    SpanRegs regs;
    unsigned flags;
    bool reserved_zero = true;   // the descriptor's bits outside its fields are 0
};

// Drives a Verilated spec_setup or spec_setup_small through its AXI4-Stream ports with random stalls on
// both sides (per-cycle probabilities that the source offers a beat and that the sink is ready).
template <class V>
class SetupStreamDriver {
public:
    SetupStreamDriver() : h_(active_low<V>([](V& v) -> CData& { return v.rst_n; })) {
        h_->s_axis_tvalid = 0;
        h_->m_axis_tready = 1;
        reset();
    }
    V& top() { return h_.top(); }
    Harness<V>& harness() { return h_; }   // e.g. opentrace for a waveform
    uint64_t cycle() const { return h_.cycle(); }
    // rst_n low for one clock
    void reset() { h_.reset(); }
    void step() { h_.tick(); }
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
                uint32_t w[setup_params::BEAT_W / 32];
                pack_setup_beat(spans[next], w);
                for (int i = 0; i < setup_params::BEAT_W / 32; ++i) top_->s_axis_tdata[i] = w[i];
            }
            top_->m_axis_tready = ready(rng);
            top_->eval();
            if (on_cycle) on_cycle(*top_);
            const bool in_fire = top_->s_axis_tvalid && top_->s_axis_tready;
            if (top_->m_axis_tvalid && top_->m_axis_tready) {
                uint32_t w[spec_params::DESC_W / 32];
                for (int i = 0; i < spec_params::DESC_W / 32; ++i) w[i] = top_->m_axis_tdata[i];
                out.push_back({unpack_descriptor(w), static_cast<unsigned>(top_->m_axis_tuser)});
                out.back().reserved_zero = descriptor_reserved_zero(w);
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
    Harness<V> h_;
    V* const top_ = &h_.top();
};

// A pixel out of spec_shader.
struct ShaderPixel {
    uint32_t value;
    bool last;
    unsigned flags;
};

// Drives a Verilated spec_shader (either configuration): span ends in, pixels out, random stalls on both sides.
template <class V>
class ShaderDriver {
public:
    ShaderDriver() : h_(active_low<V>([](V& v) -> CData& { return v.rst_n; })) {
        h_->s_axis_tvalid = 0;
        h_->m_axis_tready = 1;
        reset();
    }
    V& top() { return h_.top(); }
    Harness<V>& harness() { return h_; }   // e.g. opentrace for a waveform
    uint64_t cycle() const { return h_.cycle(); }
    // rst_n low for one clock
    void reset() { h_.reset(); }
    void step() { h_.tick(); }
    // Sends the spans and returns every pixel in order (sum of l + 1). `on_cycle`: called each cycle after the
    // inputs are set, before the edge.
    std::vector<ShaderPixel> run(const std::vector<SetupInput>& spans, double offer_p, double ready_p,
                                 std::mt19937_64& rng, uint64_t max_cycles = 0,
                                 const std::function<void(V&)>& on_cycle = {}) {
        size_t expect = 0;
        for (const auto& s : spans) expect += size_t(s.l & 0xffffu) + 1;
        if (max_cycles == 0) max_cycles = 20000 + spans.size() * 4000 + expect * 64;
        std::bernoulli_distribution offer(offer_p), ready(ready_p);
        std::vector<ShaderPixel> out;
        out.reserve(expect);
        size_t next = 0;
        bool offering = false;
        for (uint64_t c = 0; out.size() < expect || next < spans.size(); ++c) {
            if (c > max_cycles) throw std::runtime_error("spec_shader: no progress (deadlock?)");
            if (!offering && next < spans.size() && offer(rng)) offering = true;
            const bool ready_now = ready(rng);
            if (clock(offering ? &spans[next] : nullptr, ready_now, out, on_cycle)) {
                offering = false;
                ++next;
            }
            if (out.size() > expect) throw std::runtime_error("spec_shader: a pixel nobody asked for");
        }
        top_->s_axis_tvalid = 0;
        return out;
    }
    // One clock: offers `span` (nullptr: s_axis_tvalid 0) with m_axis_tready = `ready`, appends the pixel handed
    // over (if any) to `out`. `on_cycle`: called after the inputs are set, before the edge. True when the span
    // was taken.
    bool clock(const SetupInput* span, bool ready, std::vector<ShaderPixel>& out,
               const std::function<void(V&)>& on_cycle = {}) {
        top_->s_axis_tvalid = span != nullptr;
        if (span) {
            uint32_t w[setup_params::BEAT_W / 32];
            pack_setup_beat(*span, w);
            for (int i = 0; i < setup_params::BEAT_W / 32; ++i) top_->s_axis_tdata[i] = w[i];
        }
        top_->m_axis_tready = ready;
        top_->eval();
        if (on_cycle) on_cycle(*top_);
        const bool taken = top_->s_axis_tvalid && top_->s_axis_tready;
        if (top_->m_axis_tvalid && top_->m_axis_tready)
            out.push_back({top_->m_axis_tdata, top_->m_axis_tlast != 0, static_cast<unsigned>(top_->m_axis_tuser)});
        step();
        return taken;
    }

private:
    Harness<V> h_;
    V* const top_ = &h_.top();
};

}  // namespace spec
