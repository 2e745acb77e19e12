// parallax_rtl.cpp - the Verilated rtl/parallax_iter.v against a memory model (parallax_rtl.h).
#include "parallax_rtl.h"

#include <deque>
#include <memory>
#include <random>
#include <stdexcept>

#include "Vparallax_iter.h"
#include "Vparallax_iter_s1.h"
#include "Vparallax_iter_s16.h"
#include "harness.h"

namespace spec {
namespace methods {

namespace {
uint64_t bits(int64_t x, int w) { return uint64_t(x) & ((uint64_t(1) << w) - 1); }
int64_t sext(uint64_t x, int w) {
    x &= (uint64_t(1) << w) - 1;
    return (x >> (w - 1)) ? int64_t(x) - (int64_t(1) << w) : int64_t(x);
}

template <class V>
IterRunResult run(const std::vector<IterJob>& jobs, const HeightFetch& fetch, const IterRunConfig& cfg, int slots) {
    const StepFormat fmt;
    constexpr int kTagW = 16;
    // the one Verilated harness (sim/rtl/harness.h): own context, clock, reset
    Harness<V> h(active_high<V>([](V& v) -> CData& { return v.rst; }));
    V* const d = &h.top();
    auto tick = [&] { h.tick(); };
    d->s_valid = 0;
    d->req_ready = 0;
    d->rsp_valid = 0;
    d->m_ready = 0;
    h.reset(2);

    std::mt19937_64 rng(cfg.seed);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    std::uniform_int_distribution<int> lat(std::max(1, cfg.latency_min), std::max(cfg.latency_min, cfg.latency_max));
    struct Pending {
        uint64_t due;
        uint32_t id;
        int64_t h;
    };
    std::deque<Pending> mem;
    IterRunResult r;
    r.hits.resize(jobs.size());
    r.seen.assign(jobs.size(), 0);
    std::vector<int> by_tag(size_t(1) << kTagW, -1);
    size_t next = 0, done = 0;
    uint64_t cyc = 0;
    const uint64_t limit = 1000 + 64ull * (jobs.size() + 1) * uint64_t(cfg.latency_max + 8) * 70;
    bool req_hold = false, out_hold = false;
    uint64_t req_u = 0, req_v = 0, req_id = 0, m_u = 0, m_v = 0, m_tag = 0;
    std::vector<int> outstanding(size_t(slots), 0);
    while (done < jobs.size()) {
        if (++cyc > limit) {
            r.timed_out = true;
            break;
        }
        // inputs for this cycle
        const bool offer = next < jobs.size() && !(cfg.p_in_gap > 0 && u01(rng) < cfg.p_in_gap);
        d->s_valid = offer;
        if (offer) {
            const IterJob& j = jobs[next];
            d->s_u = uint32_t(bits(j.u, fmt.uv_w));
            d->s_v = uint32_t(bits(j.v, fmt.uv_w));
            d->s_hv0 = uint16_t(bits(j.hv0, fmt.h_w));
            d->s_vu = uint16_t(bits(j.vu, fmt.v_w));
            d->s_vv = uint16_t(bits(j.vv, fmt.v_w));
            d->s_vh = uint16_t(bits(j.vh, fmt.v_w));
            d->s_threshold = uint16_t(bits(int64_t(j.threshold), fmt.h_w));
            d->s_max_iter = uint8_t(bits(j.max_iter, fmt.iter_w));
            d->s_tag = uint16_t(next & ((1u << kTagW) - 1));
        }
        d->req_ready = !(cfg.p_req_stall > 0 && u01(rng) < cfg.p_req_stall);
        d->m_ready = !(cfg.p_out_stall > 0 && u01(rng) < cfg.p_out_stall);
        // a response that is due
        d->rsp_valid = 0;
        size_t pick = mem.size();
        for (size_t k = 0; k < mem.size(); ++k) {
            if (mem[k].due > cyc) continue;
            if (pick == mem.size()) pick = k;
            if (!cfg.in_order && u01(rng) < 0.5) pick = k;
            if (cfg.in_order) break;
        }
        if (pick < mem.size()) {
            d->rsp_valid = 1;
            d->rsp_id = mem[pick].id;
            d->rsp_h = uint16_t(bits(mem[pick].h, fmt.h_w));
            --outstanding[mem[pick].id];
            mem.erase(mem.begin() + long(pick));
        } else if (cfg.p_bogus_rsp > 0 && u01(rng) < cfg.p_bogus_rsp) {
            // a response for a slot with nothing outstanding: must change nothing
            for (int s = 0; s < slots; ++s) {
                if (outstanding[size_t(s)] == 0 && !(req_hold && int(req_id) == s)) {
                    d->rsp_valid = 1;
                    d->rsp_id = uint32_t(s);
                    d->rsp_h = uint16_t(rng());
                    break;
                }
            }
        }
        d->eval();
        // the output registers must hold still while stalled
        if (req_hold && (!d->req_valid || d->req_u != req_u || d->req_v != req_v || d->req_id != req_id)) r.stable = false;
        if (out_hold && (!d->m_valid || d->m_u != m_u || d->m_v != m_v || d->m_tag != m_tag)) r.stable = false;
        const bool s_fire = offer && d->s_ready;
        const bool req_fire = d->req_valid && d->req_ready;
        const bool m_fire = d->m_valid && d->m_ready;
        if (req_fire) {
            Pending p;
            p.due = cyc + uint64_t(lat(rng));
            p.id = uint32_t(d->req_id);
            if (p.id >= uint32_t(slots)) throw std::logic_error("parallax_iter: request from a slot it does not have");
            p.h = fetch(sext(d->req_u, fmt.uv_w), sext(d->req_v, fmt.uv_w));
            ++outstanding[p.id];
            mem.push_back(p);
            ++r.requests;
        }
        req_hold = d->req_valid && !d->req_ready;
        req_u = d->req_u, req_v = d->req_v, req_id = d->req_id;
        if (m_fire) {
            const int j = by_tag[d->m_tag];
            if (j < 0) throw std::logic_error("parallax_iter: a result with a tag that is not in flight");
            r.hits[size_t(j)].u = sext(d->m_u, fmt.uv_w);
            r.hits[size_t(j)].v = sext(d->m_v, fmt.uv_w);
            r.hits[size_t(j)].iterations = int(d->m_iters);
            r.hits[size_t(j)].converged = d->m_converged;
            r.steps += d->m_iters;
            ++r.seen[size_t(j)];
            by_tag[d->m_tag] = -1;
            ++done;
        }
        out_hold = d->m_valid && !d->m_ready;
        m_u = d->m_u, m_v = d->m_v, m_tag = d->m_tag;
        if (s_fire) {
            by_tag[next & ((1u << kTagW) - 1)] = int(next);
            ++next;
        }
        tick();
    }
    r.cycles = cyc;
    return r;   // the harness runs final() and drops the context
}
}  // namespace

int iter_slots(IterBuild b) { return b == IterBuild::slots1 ? 1 : b == IterBuild::slots4 ? 4 : 16; }

IterRunResult run_parallax_iter(IterBuild b, const std::vector<IterJob>& jobs, const HeightFetch& fetch,
                                const IterRunConfig& cfg) {
    switch (b) {
        case IterBuild::slots1: return run<Vparallax_iter_s1>(jobs, fetch, cfg, 1);
        case IterBuild::slots4: return run<Vparallax_iter>(jobs, fetch, cfg, 4);
        default: return run<Vparallax_iter_s16>(jobs, fetch, cfg, 16);
    }
}

std::vector<ThroughputCell> iter_throughput(const std::vector<IterJob>& jobs, const HeightFetch& fetch,
                                            const std::vector<int>& latencies) {
    const StepFormat fmt;
    std::vector<ThroughputCell> out;
    for (int lat : latencies) {
        for (IterBuild b : {IterBuild::slots1, IterBuild::slots4, IterBuild::slots16}) {
            IterRunConfig cfg;
            cfg.latency_min = cfg.latency_max = lat;
            const IterRunResult r = run_parallax_iter(b, jobs, fetch, cfg);
            ThroughputCell c;
            c.build = b;
            c.latency = lat;
            c.steps = r.steps;
            c.cycles = r.cycles;
            for (size_t k = 0; k < jobs.size(); ++k) {
                const FixedHit m = iterate_fixed(fmt, jobs[k], fetch);
                const FixedHit& h = r.hits[k];
                c.mismatches += r.seen[k] != 1 || h.u != m.u || h.v != m.v || h.iterations != m.iterations ||
                                h.converged != m.converged;
            }
            if (r.timed_out) c.mismatches = jobs.size();
            out.push_back(c);
        }
    }
    return out;
}

}  // namespace methods
}  // namespace spec
