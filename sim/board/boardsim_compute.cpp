// boardsim_compute.cpp - the board simulation against the model and the double-precision reference, and
// the split study (see boardsim_compute.h).
#include "boardsim_compute.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "board_ref.h"
#include "board_shaders.h"
#include "cli.h"
#include "spec_format.h"
#include "spec_model.h"

namespace spec {
namespace board {

namespace {

// A frame (or a mask) with every pixel repeated s x s times (the iCEBreaker's pixel doubling)
Frame upscale(const Frame& f, int s) {
    if (s == 1) return f;
    Frame o;
    o.w = f.w * s, o.h = f.h * s, o.out_bits = f.out_bits;
    o.px.resize(size_t(o.w) * size_t(o.h));
    for (int y = 0; y < o.h; ++y)
        for (int x = 0; x < o.w; ++x) o.px[size_t(y) * size_t(o.w) + size_t(x)] = f.px[size_t(y / s) * size_t(f.w) + size_t(x / s)];
    return o;
}
std::vector<uint8_t> upscale_mask(const std::vector<uint8_t>& m, int w, int s) {
    if (s == 1) return m;
    const int h = int(m.size()) / w;
    std::vector<uint8_t> o(m.size() * size_t(s) * size_t(s));
    for (int y = 0; y < h * s; ++y)
        for (int x = 0; x < w * s; ++x) o[size_t(y) * size_t(w * s) + size_t(x)] = m[size_t(y / s) * size_t(w) + size_t(x / s)];
    return o;
}

// The core's configuration on both boards: the up5k one (interpolated 4 x 256 tables, docs/stream.md)
const Model& core_model() {
    static const Model m(config_format("up5k"));
    return m;
}

}  // namespace

RunReport run_board_sim(const RunOptions& o) {
    RunReport rep;
    rep.opt = o;
    const bool race_test = (o.mode == "128x96-race");
    const BoardScene scene = make_board_scene(race_test ? "128x96" : o.mode, o.split_k);
    // the iCEBreaker, and the ULX3S at 640x480 (and its 128x96 test raster), draw into a frame buffer of half
    // the display's size (board_core_fb), 4 bits a channel; the ULX3S at 1280x720 races the beam, 8 bits
    const bool fb = (o.board == "icebreaker") || (o.mode == "640x480" || o.mode == "128x96");
    const BoardScene fb_scene = fb ? make_board_scene(o.mode == "128x96" ? "64x48" : "320x240", o.split_k) : scene;
    rep.mode = scene.mode;
    rep.out_bits = fb ? 4 : 8;
    rep.setup_config = setup_config_name(board_setup_config(o.board, o.mode));

    HarnessOptions ho;
    ho.board = o.board;
    ho.mode = o.mode;
    ho.frames = o.frames;
    // time for the reset, the blanking before the first frame and the frames, at the slowest pixel clock, x 1.5;
    // with a frame buffer, the rendered frames at 1000 design clocks per shader pass (a span takes about 960,
    // make bench): the iCEBreaker's design clock is its pixel clock, the ULX3S's 640 x 480 twice its pixel clock
    const double frame_ps = double(scene.mode.h_total()) * scene.mode.v_total() / (0.9 * scene.mode.pixel_mhz) * 1e6;
    ho.limit_ps = uint64_t((o.frames + 1.2) * frame_ps * 1.5) + 20000000ull;
    if (fb) {
        uint64_t spans = 0;
        for (int y = 0; y < fb_scene.mode.v_active; ++y) spans += line_spans(fb_scene, y).size();
        const double design_mhz = (o.board == "icebreaker" ? 1.0 : 2.0) * scene.mode.pixel_mhz * 0.9;
        const double render_ps = double(spans) * 2.0 * 1000.0 / (design_mhz * 1e6) * 1e12;
        ho.limit_ps += uint64_t((o.frames + 1) * (render_ps + 2 * frame_ps) * 1.5);
    }
    VideoCapture cap(rep.out_bits);
    rep.harness = run_board(ho, cap);
    // clocks of the design clock per line: twice the pixel clock, except the ULX3S at 1280 x 720
    rep.harness.render_clocks_budget =
        fb ? 0 : scene.mode.h_total() * ((o.board == "ulx3s" && o.mode == "1280x720") ? 1 : 2);
    if (!rep.harness.finished) rep.failures.push_back("the frames were not shown within the time limit");
    if (rep.harness.late) rep.failures.push_back("a line was not rendered in time (late flag)");
    // the DVI Pmod samples its data pins at the rising edge of its pixel clock pin: they must be stable a
    // quarter pixel before and after it (the design gives half a pixel each way)
    if (rep.harness.pin_setup_ps >= 0 || rep.harness.pin_hold_ps >= 0) {
        const double quarter_ps = 0.25e6 / rep.harness.pll_mhz;
        if (rep.harness.pin_setup_ps < quarter_ps || rep.harness.pin_hold_ps < quarter_ps)
            rep.failures.push_back("the Pmod's data pins change within a quarter pixel of its pixel clock's rising edge");
    }
    if (rep.harness.out_of_step) rep.failures.push_back("the TMDS serializer lost step with the pixel clock");
    if (rep.harness.tmds_bad) rep.failures.push_back("TMDS characters that do not decode or do not belong");
    if (rep.harness.nibbles_unequal) rep.failures.push_back("8-bit channels that are not a 4-bit value x 17");
    rep.measured = cap.measure();
    rep.timing = check_timing(rep.measured, scene.mode, rep.harness.pll_mhz);
    if (!rep.timing.ok) rep.failures.push_back("video timing differs from the mode's figures");
    if (!rep.harness.finished) return rep;

    // the frames to compare: racing the beam, every displayed frame k is frame k; with a frame buffer (the
    // iCEBreaker), the displayed frame after rendered frame k is finished shows frame k whole
    std::vector<bool> tags;
    const std::vector<Frame> shown = cap.all_frames(&tags);
    std::vector<Frame> got;
    if (!rep.harness.frame_buffer) {
        for (int f = 0; f < o.frames && f < int(shown.size()); ++f) got.push_back(shown[size_t(f)]);
    } else {
        for (size_t i = 1; i < shown.size() && int(got.size()) < o.frames; ++i) {
            if (tags[i] != tags[i - 1]) got.push_back(shown[i]);
        }
    }
    if (int(got.size()) < o.frames) {
        rep.failures.push_back("fewer than " + std::to_string(o.frames) + " frames to compare were captured");
        return rep;
    }
    const BoardScene& drawn = rep.harness.frame_buffer ? fb_scene : scene;
    const int scale = rep.harness.frame_buffer ? 2 : 1;
    const Shader shader = rtl_shader(core_model(), board_setup_config(o.board, o.mode));
    for (int f = 0; f < o.frames; ++f) {
        FrameReport fr;
        fr.frame = unsigned(f);
        const Frame& g = got[size_t(f)];
        const int h = drawn.mode.v_active;
        const Frame model = upscale(model_frame(drawn, shader, unsigned(f), rep.out_bits, 0, h), scale);
        if (g.w != model.w || g.h != model.h) {
            rep.failures.push_back("frame " + std::to_string(f) + " is " + std::to_string(g.w) + " x " +
                                   std::to_string(g.h));
            continue;
        }
        for (size_t i = 0; i < g.px.size(); ++i) {
            if (g.px[i] != model.px[i]) {
                if (fr.differing == 0) fr.first_x = int(i % size_t(g.w)), fr.first_y = int(i / size_t(g.w));
                ++fr.differing;
            }
        }
        if (fr.differing) rep.failures.push_back("frame " + std::to_string(f) + " differs from the model");
        std::vector<uint8_t> covered;
        const Frame ref = upscale(ref_frame(drawn, unsigned(f), 8, 0, h, &covered), scale);
        covered = upscale_mask(covered, drawn.mode.h_active, scale);
        fr.board = to_image(g);
        fr.model = to_image(model);
        fr.ref = to_image(ref);
        fr.vs_ref = render::compare(fr.board, fr.ref, covered);
        const Frame model8 = (rep.out_bits == 8) ? model : upscale(model_frame(drawn, shader, unsigned(f), 8, 0, h), scale);
        fr.model8_vs_ref = render::compare(to_image(model8), fr.ref, covered);
        rep.frames.push_back(std::move(fr));
    }
    return rep;
}

std::vector<SplitRow> split_study(const SplitOptions& o) {
    std::vector<SplitRow> rows;
    const Model& m = core_model();
    for (int k : o.ks) {
        const BoardScene s = make_board_scene(o.mode, k);
        // rtl: the racing design's setup (ecp5), whose split K the study chooses
        const Shader sh = (o.shader == "rtl") ? rtl_shader(m, SetupConfig::ecp5) : host_shader(m, host::GammaRule::midpoint);
        SplitRow row;
        row.k = k;
        row.max_err.assign(s.spheres.size(), 0);
        row.mean_err.assign(s.spheres.size(), 0);
        std::vector<double> sum(s.spheres.size(), 0);
        std::vector<uint64_t> n(s.spheres.size(), 0);
        row.psnr = 1e9;
        uint64_t lines = 0, spans = 0;
        for (int y = 0; y < s.mode.v_active; ++y) {
            const size_t c = line_spans(s, y).size();
            if (c) ++lines, spans += c;
            row.spans_max_line = std::max(row.spans_max_line, int(c));
        }
        row.spans_per_line = lines ? double(spans) / double(lines) : 0;
        for (unsigned f : o.frames) {
            const Frame a = model_frame(s, sh, f, 8, 0, s.mode.v_active);
            std::vector<uint8_t> cov;
            const Frame r = ref_frame(s, f, 8, 0, s.mode.v_active, &cov);
            for (size_t i = 0; i < a.px.size(); ++i) {
                if (!cov[i]) continue;
                const int x = int(i % size_t(a.w)), y = int(i / size_t(a.w));
                size_t obj = 0;
                for (size_t q = 0; q < s.spheres.size(); ++q) {
                    const Sphere& sp = s.spheres[q];
                    const int64_t dx = 2 * x + 1 - 2 * sp.cx, dy = 2 * y + 1 - 2 * sp.cy;
                    if (dx * dx + dy * dy <= 4 * int64_t(sp.r) * sp.r) obj = q;
                }
                for (int ch = 0; ch < 3; ++ch) {
                    const int e = std::abs(int(a.px[i][size_t(ch)]) - int(r.px[i][size_t(ch)]));
                    row.max_err[obj] = std::max(row.max_err[obj], e);
                    sum[obj] += e;
                    ++n[obj];
                }
            }
            const render::ImageStats st = render::compare(to_image(a), to_image(r), cov);
            row.psnr = std::min(row.psnr, st.psnr);
        }
        for (size_t q = 0; q < s.spheres.size(); ++q) {
            row.mean_err[q] = n[q] ? sum[q] / double(n[q]) : 0;
            row.max_all = std::max(row.max_all, row.max_err[q]);
        }
        rows.push_back(row);
    }
    return rows;
}

}  // namespace board
}  // namespace spec
