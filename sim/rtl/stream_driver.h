// stream_driver.h - drives a Verilated spec_stream through its AXI4-Stream ports (on the harness, harness.h).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "harness.h"
#include "span_core.h"
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

// What run() throws when the core breaks the stream's contract: a pixel more than the spans asked for, or
// m_axis_tlast on the wrong pixel.
struct StreamError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// LANES pixels per beat (spec_stream's LANES), PACK as the core's (docs/stream.md): run() checks each beat's
// m_axis_tkeep and m_axis_tlast against the spans and returns the pixels one by one.
template <class V, int LANES = 1, bool PACK = false>
class StreamDriver {
    static_assert(LANES == 1 || LANES == 2 || LANES == 4, "LANES is 1, 2 or 4");
    static_assert(LANES * spec_params::OUT_W <= 64, "m_axis_tdata must fit 64 bits");

public:
    // Cycles run() keeps the sink ready after the last expected pixel, watching for pixels nobody asked for:
    // more than the core's latency from an accepted descriptor to its first pixel (spec_params::STREAM_LATENCY).
    static constexpr int kDrainCycles = 64;

    StreamDriver() : h_(active_low<V>([](V& v) -> CData& { return v.rst_n; })) {
        idle();
        h_->eval();
        reset();
    }
    V& top() { return h_.top(); }
    Harness<V>& harness() { return h_; }
    uint64_t cycle() const { return h_.cycle(); }
    uint64_t beats() const { return beats_; }  // beats the sink has taken so far
    // Descriptors with every ignored bit set (docs/stream.md: "the bits between the fields are ignored").
    void set_ignored_bits(bool ones) { ignored_ones_ = ones; }

    void reset() { h_.reset(); }
    // One clock; afterwards the outputs show the next cycle.
    void step() { h_.tick(); }

    // Cycles from the descriptor r taken by the idle core (in cycle a) to its first pixel on m_axis (in cycle a +
    // this): the latency spec_params::STREAM_LATENCY names (stalls none; the span is drained afterwards).
    int first_pixel(const SpanRegs& r, int max_cycles = 300) {
        uint32_t w[kDescWords];
        pack_descriptor(r, w);
        V& t = h_.top();
        for (int i = 0; i < kDescWords; ++i) t.s_axis_tdata[i] = w[i];
        t.m_axis_tready = 1;
        t.s_axis_tvalid = 0;
        t.eval();
        for (int i = 0; i < 4 && !t.s_axis_tready; ++i) step();  // tready rises the second cycle after a reset
        t.s_axis_tvalid = 1;
        t.eval();
        if (!t.s_axis_tready) throw StreamError("first_pixel: the core does not take a descriptor");
        step();  // accepted at this edge: cycle a
        t.s_axis_tvalid = 0;
        int at = 1;
        t.eval();
        while (!t.m_axis_tvalid && at < max_cycles) {
            step();
            t.eval();
            ++at;
        }
        for (int i = 0; i < int(r.len) + max_cycles; ++i) step();  // drain
        return at;
    }

    // Runs the spans through, with random stalls on both sides, and returns the pixels in order. After the
    // last expected pixel the sink stays ready for kDrainCycles more cycles: a pixel in that time, or a beat
    // that breaks the rules below, throws StreamError. Each beat: m_axis_tkeep holds slots 0 .. k-1 (k >= 1);
    // with PACK = 0 a beat holds one span's pixels, all slots unless it is the span's last beat, and
    // m_axis_tlast marks the span's last beat; with PACK = 1 m_axis_tlast marks a beat that holds a span's
    // last pixel. StreamPixel::last: the pixel ends its span and its beat has m_axis_tlast. `on_cycle`
    // (optional) is called each cycle before the edge, after the inputs are set.
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
        size_t next = 0, span_of_next_pixel = 0;
        bool offering = false;
        uint64_t c = 0;
        int drained = 0;
        V& t = h_.top();
        while (drained < kDrainCycles) {
            const bool all_out = out.size() >= expect && next >= spans.size();
            if (all_out) ++drained;
            else if (++c > max_cycles) throw std::runtime_error("spec_stream: no progress (deadlock?)");
            // AXI source: once valid is raised it stays until accepted
            if (!offering && next < spans.size() && offer(rng)) offering = true;
            t.s_axis_tvalid = offering;
            if (offering) {
                uint32_t w[kDescWords];
                pack_descriptor(spans[next], w);
                if (ignored_ones_) {  // the bits between the fields, which the core must ignore
                    uint32_t m[kDescWords];
                    ignored_mask(m);
                    for (int i = 0; i < kDescWords; ++i) w[i] |= m[i];
                }
                for (int i = 0; i < kDescWords; ++i) t.s_axis_tdata[i] = w[i];
            }
            t.m_axis_tready = all_out ? 1 : ready(rng);
            t.eval();
            if (on_cycle) on_cycle(t);
            const bool in_fire = t.s_axis_tvalid && t.s_axis_tready;
            const bool out_fire = t.m_axis_tvalid && t.m_axis_tready;
            if (out_fire) take_beat(span_end, expect, span_of_next_pixel, out);
            step();
            if (in_fire) {
                offering = false;
                ++next;
            }
        }
        t.s_axis_tvalid = 0;
        return out;
    }

private:
    // The beat on m_axis (valid and ready in this cycle): checked and appended to `out` pixel by pixel.
    void take_beat(const std::vector<size_t>& span_end, size_t expect, size_t& span_at,
                   std::vector<StreamPixel>& out) {
        V& t = h_.top();
        const uint64_t data = static_cast<uint64_t>(t.m_axis_tdata);
        const unsigned keep = static_cast<unsigned>(t.m_axis_tkeep);
        const bool tlast = t.m_axis_tlast != 0;
        const std::string at = " (beat " + std::to_string(beats_) + ", cycle " + std::to_string(h_.cycle()) + ")";
        int kept = 0;
        while (kept < LANES && ((keep >> kept) & 1u)) ++kept;
        if (kept == 0 || (keep >> kept) != 0) {
            throw StreamError("spec_stream: m_axis_tkeep " + std::to_string(keep) + " is not slots 0 .. k-1" + at);
        }
        bool ends = false;          // the beat holds a span's last pixel
        bool ends_at_last = false;  // ... in its last kept slot
        for (int j = 0; j < kept; ++j) {
            const size_t k = out.size();
            const uint32_t v = static_cast<uint32_t>((data >> (j * spec_params::OUT_W)) &
                                                     ((uint64_t(1) << spec_params::OUT_W) - 1));
            if (k >= expect) {
                throw StreamError("spec_stream: an extra pixel (" + std::to_string(v) + (tlast ? ", tlast" : "") +
                                  ") after the " + std::to_string(expect) + " the spans asked for" + at);
            }
            const bool end = span_end[span_at] == k;
            if (!PACK && j == kept - 1 && tlast != end) {
                throw StreamError("spec_stream: pixel " + std::to_string(k) + " (span " + std::to_string(span_at) +
                                  ") ends a beat with tlast = " + (tlast ? "1" : "0") + at);
            }
            out.push_back({v, tlast && end});
            if (end) {
                ends = true;
                ends_at_last = j == kept - 1;
                ++span_at;
                if (!PACK && j < kept - 1) {
                    throw StreamError("spec_stream: a beat goes on after the last pixel of span " +
                                      std::to_string(span_at - 1) + at);
                }
            }
        }
        if (!PACK && kept < LANES && !ends_at_last) {
            throw StreamError("spec_stream: empty slots in a beat that does not end its span" + at);
        }
        if (PACK && tlast != ends) {
            throw StreamError(std::string("spec_stream: m_axis_tlast ") +
                              (tlast ? "on a beat without" : "missing on a beat with") + " a span's last pixel" + at);
        }
        ++beats_;
    }
    void idle() {
        V& t = h_.top();
        t.s_axis_tvalid = 0;
        t.m_axis_tready = 1;
        for (int i = 0; i < kDescWords; ++i) t.s_axis_tdata[i] = 0;
    }
    Harness<V> h_;
    uint64_t beats_ = 0;
    bool ignored_ones_ = false;
};

// spec_stream as a SpanCore: one span at a time, no stalls (specsim span --model stream, the renderer's tests).
// cycle() counts every clock simulated, the drain after each span (kDrainCycles) included.
template <class V, int LANES = 1, bool PACK = false>
class StreamCore : public SpanCore {
public:
    StreamCore() : rng_(1) {}
    std::vector<uint32_t> span(const SpanRegs& r) override {
        std::vector<uint32_t> px;
        for (const StreamPixel& p : d_.run({r}, Stalls{}, rng_)) px.push_back(p.value);
        return px;
    }
    uint64_t cycle() const override { return d_.cycle(); }

private:
    StreamDriver<V, LANES, PACK> d_;
    std::mt19937_64 rng_;
};

}  // namespace spec
