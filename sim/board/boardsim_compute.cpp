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

// The core's configuration on both boards: the up5k one (interpolated 4 x 256 tables, docs/stream.md)
const Model& core_model() {
    static const Model m(config_format("up5k"));
    return m;
}

}  // namespace

RunReport run_board_sim(const RunOptions& o) {
    RunReport rep;
    rep.opt = o;
    const BoardScene scene = make_board_scene(o.mode, o.split_k);
    rep.mode = scene.mode;
    rep.out_bits = (o.board == "icebreaker") ? 4 : 8;

    HarnessOptions ho;
    ho.board = o.board;
    ho.mode = o.mode;
    ho.frames = o.frames;
    // time for the reset, the blanking before the first frame and the frames, at the slowest pixel clock, x 1.5
    const double frame_ps = double(scene.mode.h_total()) * scene.mode.v_total() / (0.9 * scene.mode.pixel_mhz) * 1e6;
    ho.limit_ps = uint64_t((o.frames + 1.2) * frame_ps * 1.5) + 20000000ull;
    VideoCapture cap(rep.out_bits);
    rep.harness = run_board(ho, cap);
    // clocks of the design clock per line: twice the pixel clock, except the ULX3S at 1280 x 720
    rep.harness.render_clocks_budget = scene.mode.h_total() * ((o.board == "ulx3s" && o.mode == "1280x720") ? 1 : 2);
    if (!rep.harness.finished) rep.failures.push_back("the frames were not shown within the time limit");
    if (rep.harness.late) rep.failures.push_back("a line was not rendered in time (late flag)");
    if (rep.harness.out_of_step) rep.failures.push_back("the TMDS serializer lost step with the pixel clock");
    if (rep.harness.tmds_bad) rep.failures.push_back("TMDS characters that do not decode or do not belong");
    rep.measured = cap.measure();
    rep.timing = check_timing(rep.measured, scene.mode, rep.harness.pll_mhz);
    if (!rep.timing.ok) rep.failures.push_back("video timing differs from the mode's figures");
    if (!rep.harness.finished) return rep;

    const std::vector<Frame> got = cap.frames(o.frames);
    const Shader shader = rtl_shader(core_model());
    for (int f = 0; f < o.frames; ++f) {
        FrameReport fr;
        fr.frame = unsigned(f);
        const Frame& g = got[size_t(f)];
        const Frame model = model_frame(scene, shader, unsigned(f), rep.out_bits, 0, scene.mode.v_active);
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
        const Frame ref = ref_frame(scene, unsigned(f), 8, 0, scene.mode.v_active, &covered);
        fr.board = to_image(g);
        fr.model = to_image(model);
        fr.ref = to_image(ref);
        fr.vs_ref = render::compare(fr.board, fr.ref, covered);
        const Frame model8 = (rep.out_bits == 8) ? model : model_frame(scene, shader, unsigned(f), 8, 0, scene.mode.v_active);
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
        const Shader sh = (o.shader == "rtl") ? rtl_shader(m) : host_shader(m, host::GammaRule::midpoint);
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
