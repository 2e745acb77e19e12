// harness_ulx3s.cpp - the Verilated ULX3S top: 25 MHz in, the GPDI pins turned back into pixels the way a
// DVI receiver does it: the clock lane's rising edges mark the characters (the serializer sends 0000011111,
// five ones first), the data lanes are sampled in the middle of each of the 10 bit times between two edges,
// and each character is decoded (control characters carry hsync and vsync on the blue lane, data characters
// the colour; the syncs keep their last value through data periods). The frame buffer modes (640x480, 128x96)
// send 4 bits a channel as 8 (x 17): both nibbles must agree, the samples keep 4 bits; led[7] changes with
// every rendered frame and tags the samples.
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <memory>

#include "board_harness.h"
#include "tmds.h"
#include "verilated.h"
#include "Vulx3s_top_test.h"
#include "Vulx3s_top_test___024root.h"
#include "Vulx3s_top_race.h"
#include "Vulx3s_top_race___024root.h"
#ifdef BOARDSIM_FULL
#include "Vulx3s_top.h"
#include "Vulx3s_top___024root.h"
#include "Vulx3s_top_720.h"
#include "Vulx3s_top_720___024root.h"
#endif

namespace spec {
namespace board {

namespace {

// One lane's pin: its level at the last clock-lane rising edge and its changes since.
struct Lane {
    bool at_edge = false;
    std::vector<std::pair<uint64_t, bool>> changes;
    bool level(uint64_t t) const {
        bool v = at_edge;
        for (const auto& c : changes) {
            if (c.first <= t) v = c.second;
        }
        return v;
    }
};

template <class V, class Clocks>
void run(V& top, VerilatedContext& ctx, const HarnessOptions& o, VideoCapture& cap, HarnessResult& r,
         Clocks render_clocks) {
    const bool fb = r.frame_buffer;
    int toggles = 0, stop_changes = -1;
    bool led_prev = false, led_init = false;
    const auto t0 = std::chrono::steady_clock::now();
    top.clk_25mhz = 0;
    top.btn = 1;                 // btn[0] (power button, low while pressed) released
    top.eval();
    uint64_t k = 0;              // oscillator half periods of 20 000 ps
    Lane lane[3];
    bool prev[4] = {false, false, false, false};
    uint64_t last_rise = 0;
    bool have_rise = false;
    int disparity[3] = {0, 0, 0};
    bool hs = false, vs = false;
    const int want_changes = 2 * o.frames + 1;
    uint64_t stop_at = 0;
    while (ctx.time() < o.limit_ps) {
        const uint64_t tn = (k + 1) * 20000ull;
        uint64_t t = tn;
        if (top.eventsPending()) t = std::min<uint64_t>(t, top.nextTimeSlot());
        ctx.time(t);
        if (t == tn) {
            top.clk_25mhz = !top.clk_25mhz;
            ++k;
        }
        top.eval();
        ++r.time_slots;
        const unsigned pins = top.gpdi_dp;
        for (int i = 0; i < 3; ++i) {
            const bool v = (pins >> i) & 1u;
            if (v != prev[i]) lane[i].changes.emplace_back(t, v);
            prev[i] = v;
        }
        const bool ck = (pins >> 3) & 1u;
        if (ck && !prev[3]) {
            if (have_rise) {
                // the character between the last two rising edges: sample mid-bit
                const double tb = double(t - last_rise) / 10.0;
                uint32_t q[3] = {0, 0, 0};
                for (int i = 0; i < 3; ++i) {
                    for (int b = 0; b < 10; ++b) {
                        const uint64_t ts = last_rise + uint64_t((b + 0.5) * tb);
                        q[i] |= uint32_t(lane[i].level(ts)) << b;
                    }
                }
                const TmdsChar cb = tmds_decode(q[0]), cg = tmds_decode(q[1]), cr = tmds_decode(q[2]);
                PixelSample s;
                s.t_ps = last_rise;
                s.de = !cb.is_control;
                // the syncs hold their last control value through data periods (as a receiver's outputs do)
                if (cb.is_control) {
                    hs = (cb.c & 1u) != 0;
                    vs = (cb.c & 2u) != 0;
                }
                s.hs = hs;
                s.vs = vs;
                ++r.tmds_chars;
                const TmdsChar* c3[3] = {&cb, &cg, &cr};
                for (int i = 0; i < 3; ++i) {
                    const TmdsChar& c = *c3[i];
                    // data characters on all lanes together, control characters 00 on green and red
                    if (c.is_control != !s.de || !c.valid || (i > 0 && c.is_control && c.c != 0)) ++r.tmds_bad;
                    if (c.is_control) {
                        disparity[i] = 0;
                    } else {
                        disparity[i] += 2 * __builtin_popcount(q[i]) - 10;
                        r.tmds_max_disparity = std::max(r.tmds_max_disparity, std::abs(disparity[i]));
                    }
                }
                s.rgb[0] = cr.d;
                s.rgb[1] = cg.d;
                s.rgb[2] = cb.d;
                if (fb) {
                    for (int i = 0; i < 3; ++i) {
                        if (s.de && (s.rgb[i] >> 4) != (s.rgb[i] & 15u)) ++r.nibbles_unequal;
                        s.rgb[i] = uint8_t(s.rgb[i] >> 4);
                    }
                    s.tag = ((top.led >> 7) & 1u) != 0;
                    if (!led_init) led_prev = s.tag, led_init = true;
                    if (s.tag != led_prev && ++toggles == o.frames) stop_changes = cap.vsync_changes() + 5;
                    led_prev = s.tag;
                }
                cap.push(s);
                const int need = fb ? stop_changes : want_changes;
                if (stop_at == 0 && need >= 0 && cap.vsync_changes() >= need) stop_at = cap.samples() + 4000;
                if (stop_at != 0 && cap.samples() >= stop_at) {
                    r.finished = true;
                    break;
                }
            }
            for (int i = 0; i < 3; ++i) {
                lane[i].at_edge = lane[i].level(t);
                lane[i].changes.clear();
            }
            last_rise = t;
            have_rise = true;
        }
        prev[3] = ck;
    }
    r.sim_ps = ctx.time();
    r.late = (top.led & 1u) != 0;
    r.out_of_step = (top.led & 2u) != 0;
    r.render_clocks_max = render_clocks(top);
    r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    top.final();
}

}  // namespace

void ulx3s_models(std::vector<std::string>& out) {
    out.push_back("ulx3s 128x96");
    out.push_back("ulx3s 128x96-race");
#ifdef BOARDSIM_FULL
    out.push_back("ulx3s 640x480");
    out.push_back("ulx3s 1280x720");
#endif
}

bool run_ulx3s(const HarnessOptions& o, VideoCapture& cap, HarnessResult& r) {
    // ulx3s_prims.v: 25 MHz x 5 / 1 / 20 x 4 = 25 MHz; 720p: 25 x 104 / 7 x 2 / 10 = 74.2857 MHz
    r.pll_mhz = (o.mode == "1280x720") ? 25.0 * 104.0 / 7.0 * 2.0 / 10.0 : 25.0;
    r.design_mhz = (o.mode == "1280x720") ? r.pll_mhz : 2.0 * r.pll_mhz;   // 640 x 480: a pixel every other clock
    // 640x480 and the 128x96 test raster: the frame buffer design (board_core_fb); 1280x720 and 128x96-race:
    // racing the beam (board_core)
    r.frame_buffer = (o.mode == "640x480" || o.mode == "128x96");
    auto ctx = std::make_unique<VerilatedContext>();
    Verilated::threadContextp(ctx.get());
    if (o.mode == "128x96") {
        Vulx3s_top_test top(ctx.get());
        run(top, *ctx, o, cap, r, [](Vulx3s_top_test& t) {
            return int(t.rootp->ulx3s_top__DOT__g_fb__DOT__u_core__DOT__frame_clocks_max);
        });
        return true;
    }
    if (o.mode == "128x96-race") {
        Vulx3s_top_race top(ctx.get());
        run(top, *ctx, o, cap, r, [](Vulx3s_top_race& t) {
            return int(t.rootp->ulx3s_top__DOT__g_race__DOT__u_core__DOT__render_clocks_max);
        });
        return true;
    }
#ifdef BOARDSIM_FULL
    if (o.mode == "640x480") {
        Vulx3s_top top(ctx.get());
        run(top, *ctx, o, cap, r, [](Vulx3s_top& t) {
            return int(t.rootp->ulx3s_top__DOT__g_fb__DOT__u_core__DOT__frame_clocks_max);
        });
        return true;
    }
    if (o.mode == "1280x720") {
        Vulx3s_top_720 top(ctx.get());
        run(top, *ctx, o, cap, r, [](Vulx3s_top_720& t) {
            return int(t.rootp->ulx3s_top__DOT__g_race__DOT__u_core__DOT__render_clocks_max);
        });
        return true;
    }
#endif
    return false;
}

}  // namespace board
}  // namespace spec
