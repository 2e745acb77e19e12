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

// LANES pixels per beat (spec_stream's LANES), PACK as the core's (docs/stream.md): run() checks the
// beats' m_axis_tkeep and m_axis_tlast against the spans and returns the pixels one by one.
template <class V, int LANES = 1, bool PACK = false>
class StreamDriver {
    static_assert(LANES == 1 || LANES == 2 || LANES == 4, "LANES is 1, 2 or 4");
    static_assert(LANES * spec_params::OUT_W <= 64, "m_axis_tdata must fit 64 bits");

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
    uint64_t beats() const { return beats_; }   // beats taken by the sink so far
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
    // Each beat is checked: m_axis_tkeep holds slots 0 .. k-1 (k >= 1); with PACK = 0 a beat holds one span's
    // pixels, all slots unless it is the span's last beat, and m_axis_tlast marks the span's last beat; with
    // PACK = 1 m_axis_tlast marks a beat that holds a span's last pixel. A violation throws
    // std::runtime_error. StreamPixel::last is m_axis_tlast on the beat's last kept slot (PACK = 0) or that
    // the beat has tlast and the pixel ends its span (PACK = 1).
    // `on_cycle` (optional) is called each cycle before the edge, after inputs are set.
    std::vector<StreamPixel> run(const std::vector<SpanRegs>& spans, const Stalls& st, std::mt19937_64& rng,
                                 uint64_t max_cycles = 0, const std::function<void(V&)>& on_cycle = {}) {
        size_t expect = 0;
        std::vector<size_t> span_end;  // index of each span's last pixel
        for (const auto& s : spans) {
            expect += size_t(s.len) + 1;
            span_end.push_back(expect - 1);
        }
        if (max_cycles == 0) max_cycles = 64 + expect * 64;
        std::bernoulli_distribution offer(st.in_valid), ready(st.out_ready);
        std::vector<StreamPixel> out;
        out.reserve(expect);
        size_t next = 0, span_at = 0;   // the span of the next pixel out
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
            if (out_fire) take_beat(span_end, span_at, out);
            step();
            if (in_fire) {
                offering = false;
                ++next;
            }
        }
        return out;
    }

private:
    // The beat on m_axis (valid and ready in this cycle): checked and appended to `out` pixel by pixel.
    void take_beat(const std::vector<size_t>& span_end, size_t& span_at, std::vector<StreamPixel>& out) {
        const uint64_t data = static_cast<uint64_t>(top_->m_axis_tdata);
        const unsigned keep = static_cast<unsigned>(top_->m_axis_tkeep);
        const bool tlast = top_->m_axis_tlast != 0;
        const std::string at = " (beat " + std::to_string(beats_) + ", cycle " + std::to_string(cycle_) + ")";
        int kept = 0;
        while (kept < LANES && ((keep >> kept) & 1u)) ++kept;
        if (kept == 0 || (keep >> kept) != 0) {
            throw std::runtime_error("spec_stream: m_axis_tkeep " + std::to_string(keep) +
                                     " is not slots 0 .. k-1" + at);
        }
        bool ends = false;            // the beat holds a span's last pixel
        bool ends_at_last = false;    // ... in its last kept slot
        for (int j = 0; j < kept; ++j) {
            const size_t k = out.size();
            if (span_at >= span_end.size()) throw std::runtime_error("spec_stream: a pixel nobody asked for" + at);
            const bool end = span_end[span_at] == k;
            const uint32_t v = static_cast<uint32_t>((data >> (j * spec_params::OUT_W)) &
                                                     ((uint64_t(1) << spec_params::OUT_W) - 1));
            out.push_back({v, PACK ? (tlast && end) : (tlast && j == kept - 1)});
            if (end) {
                ends = true;
                ends_at_last = j == kept - 1;
                ++span_at;
                if (!PACK && j < kept - 1) {
                    throw std::runtime_error("spec_stream: a beat goes on after a span's last pixel" + at);
                }
            }
        }
        if (!PACK && kept < LANES && !ends_at_last) {
            throw std::runtime_error("spec_stream: empty slots in a beat that does not end its span" + at);
        }
        if (PACK && tlast != ends) {
            throw std::runtime_error(std::string("spec_stream: m_axis_tlast ") + (tlast ? "on a beat without" : "missing on a beat with") +
                                     " a span's last pixel" + at);
        }
        ++beats_;
    }
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
    uint64_t beats_ = 0;
    bool ignored_ones_ = false;
};

}  // namespace spec
