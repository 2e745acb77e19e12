// harness_icebreaker.cpp - the Verilated iCEBreaker top: 12 MHz in, the DVI Pmod's pins sampled at each
// rising edge of its pixel clock pin (dvi_clk), which is what the Pmod's TFP410 does, with the green LED (it
// changes with every rendered frame) as each sample's tag. It runs until `frames` frames have been rendered
// and the displayed frame after the last of them is whole.
#include <chrono>
#include <memory>

#include "board_harness.h"
#include "verilated.h"
#include "Vicebreaker_top_test.h"
#include "Vicebreaker_top_test___024root.h"
#ifdef BOARDSIM_FULL
#include "Vicebreaker_top.h"
#include "Vicebreaker_top___024root.h"
#endif

namespace spec {
namespace board {

namespace {

template <class V>
void run(V& top, VerilatedContext& ctx, const HarnessOptions& o, VideoCapture& cap, HarnessResult& r) {
    const auto t0 = std::chrono::steady_clock::now();
    top.CLK = 0;
    top.BTN_N = 1;
    top.eval();
    uint64_t k = 0;          // oscillator half periods: 12 MHz, edge k at k * 10^6 / 24 ps
    bool clk_prev = false;
    int toggles = 0, stop_changes = -1;
    bool led_prev = !top.LEDG_N;
    uint64_t stop_at = 0;
    // the data pins' last change and the last sampling edge (set-up and hold at the pins)
    auto pins = [&] {
        return (uint32_t(top.dvi_r) << 11) | (uint32_t(top.dvi_g) << 7) | (uint32_t(top.dvi_b) << 3) |
               (uint32_t(top.dvi_hs) << 2) | (uint32_t(top.dvi_vs) << 1) | uint32_t(top.dvi_de);
    };
    uint32_t pins_prev = pins();
    uint64_t t_change = 0, t_sample = 0;
    bool changed = false, sampled = false;
    while (ctx.time() < o.limit_ps) {
        const uint64_t tn = ((k + 1) * 1000000ull) / 24ull;
        uint64_t t = tn;
        if (top.eventsPending()) t = std::min<uint64_t>(t, top.nextTimeSlot());
        ctx.time(t);
        if (t == tn) {
            top.CLK = !top.CLK;
            ++k;
        }
        top.eval();
        ++r.time_slots;
        const uint32_t p = pins();
        if (p != pins_prev) {
            if (sampled && (r.pin_hold_ps < 0 || double(t - t_sample) < r.pin_hold_ps)) r.pin_hold_ps = double(t - t_sample);
            t_change = t;
            changed = true;
            pins_prev = p;
        }
        if (top.dvi_clk && !clk_prev) {
            if (changed && (r.pin_setup_ps < 0 || double(t - t_change) < r.pin_setup_ps)) r.pin_setup_ps = double(t - t_change);
            t_sample = t;
            sampled = true;
            PixelSample s;
            s.t_ps = t;
            s.rgb[0] = top.dvi_r;
            s.rgb[1] = top.dvi_g;
            s.rgb[2] = top.dvi_b;
            s.hs = top.dvi_hs;
            s.vs = top.dvi_vs;
            s.de = top.dvi_de;
            s.tag = !top.LEDG_N;
            cap.push(s);
            if (s.tag != led_prev && ++toggles == o.frames) stop_changes = cap.vsync_changes() + 5;
            led_prev = s.tag;
            if (stop_at == 0 && stop_changes >= 0 && cap.vsync_changes() >= stop_changes) stop_at = cap.samples() + 4000;
            if (stop_at != 0 && cap.samples() >= stop_at) {
                r.finished = true;
                break;
            }
        }
        clk_prev = top.dvi_clk;
    }
    r.sim_ps = ctx.time();
    r.late = !top.LEDR_N;
    r.render_clocks_max = int(top.rootp->icebreaker_top__DOT__u_core__DOT__frame_clocks_max);
    r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    top.final();
}

}  // namespace

void icebreaker_models(std::vector<std::string>& out) {
    out.push_back("icebreaker 128x96");
#ifdef BOARDSIM_FULL
    out.push_back("icebreaker 640x480");
#endif
}

bool run_icebreaker(const HarnessOptions& o, VideoCapture& cap, HarnessResult& r) {
    r.pll_mhz = 12.0 * 67.0 / 32.0;   // icebreaker_prims.v: 25.125 MHz, a pixel every clock
    r.design_mhz = r.pll_mhz;
    r.frame_buffer = true;
    // Verilator registers a model's scopes in the thread's current context: set it around construction
    auto ctx = std::make_unique<VerilatedContext>();
    Verilated::threadContextp(ctx.get());
    if (o.mode == "128x96") {
        Vicebreaker_top_test top(ctx.get());
        run(top, *ctx, o, cap, r);
        return true;
    }
#ifdef BOARDSIM_FULL
    if (o.mode == "640x480") {
        Vicebreaker_top top(ctx.get());
        run(top, *ctx, o, cap, r);
        return true;
    }
#endif
    return false;
}

}  // namespace board
}  // namespace spec
