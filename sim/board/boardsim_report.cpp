// boardsim_report.cpp - tables, PNGs and JSON of boardsim (see boardsim_report.h).
#include "boardsim_report.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "board_scene.h"
#include "fileutil.h"

namespace spec {
namespace board {

namespace {

std::string num(double v, int prec) {
    if (std::isinf(v)) return "\"inf\"";
    char b[64];
    std::snprintf(b, sizeof b, "%.*f", prec, v);
    return b;
}

std::string stats_json(const render::ImageStats& s) {
    std::ostringstream o;
    o << "{\"max_abs\": " << s.max_abs << ", \"mean_abs\": " << num(s.mean_abs, 4) << ", \"psnr_db\": "
      << num(s.psnr, 2) << ", \"over_4\": " << s.over_4 << "}";
    return o.str();
}

}  // namespace

void print_run(const RunReport& r) {
    const HarnessResult& h = r.harness;
    std::printf("board-sim %s %s: %d frame(s), %.1f ms simulated in %.1f s (%llu time slots)\n", r.opt.board.c_str(),
                r.mode.name.c_str(), r.opt.frames, double(h.sim_ps) * 1e-9, h.wall_s,
                static_cast<unsigned long long>(h.time_slots));
    std::printf("\nvideo timing (measured at the pins | %s):\n", r.mode.standard.c_str());
    for (const std::string& row : r.timing.rows) std::printf("  %s\n", row.c_str());
    if (h.frame_buffer) {
        const double ms = h.render_clocks_max / h.design_mhz * 1e-3;
        std::printf("\nrendering into the frame buffer: longest frame %d clocks (%.1f ms, %.1f rendered frames/s), "
                    "write-queue overflow %s\n", h.render_clocks_max, ms, 1e3 / ms, h.late ? "SET" : "clear");
        if (h.pin_setup_ps >= 0 && h.pin_hold_ps >= 0)
            std::printf("DVI Pmod pins: data stable at least %.2f ns before and %.2f ns after each rise of the pixel "
                        "clock pin\n", h.pin_setup_ps * 1e-3, h.pin_hold_ps * 1e-3);
    } else {
        std::printf("\nrendering: longest line %d of %d clocks (%.0f %%), late flag %s\n", h.render_clocks_max,
                    h.render_clocks_budget, 100.0 * h.render_clocks_max / std::max(1, h.render_clocks_budget),
                    h.late ? "SET" : "clear");
    }
    if (r.opt.board == "ulx3s") {
        std::printf("TMDS: %llu characters decoded, %llu bad, largest running disparity %d, serializer %s\n",
                    static_cast<unsigned long long>(h.tmds_chars), static_cast<unsigned long long>(h.tmds_bad),
                    h.tmds_max_disparity, h.out_of_step ? "OUT OF STEP" : "in step");
    }
    std::printf("\n| frame | pixels unlike the model | board vs double: max | mean | PSNR | model at 8 bits vs double: max | mean | PSNR |\n");
    std::printf("|---|---|---|---|---|---|---|---|\n");
    for (const FrameReport& f : r.frames) {
        std::printf("| %u | %llu | %d | %.3f | %.1f dB | %d | %.3f | %.1f dB |\n", f.frame,
                    static_cast<unsigned long long>(f.differing), f.vs_ref.max_abs, f.vs_ref.mean_abs, f.vs_ref.psnr,
                    f.model8_vs_ref.max_abs, f.model8_vs_ref.mean_abs, f.model8_vs_ref.psnr);
        if (f.differing) std::printf("  first difference at (%d, %d)\n", f.first_x, f.first_y);
    }
    std::printf("\n%s\n", r.failures.empty() ? "PASS" : "FAIL");
    for (const std::string& s : r.failures) std::printf("  %s\n", s.c_str());
}

void write_run(const RunReport& r) {
    if (r.opt.out_dir.empty()) return;
    const std::string base = r.opt.out_dir + "/" + r.opt.board + "_" + r.mode.name;
    for (const FrameReport& f : r.frames) {
        const std::string tag = base + "_frame" + std::to_string(f.frame);
        render::write_png(tag + ".png", f.board);
        render::write_png(tag + "_ref.png", f.ref);
        render::write_png(tag + "_err16.png", render::error_map(f.board, f.ref, 16.0));
        if (f.differing) render::write_png(tag + "_model.png", f.model);
    }
    std::ostringstream o;
    const HarnessResult& h = r.harness;
    o << "{\n  \"board\": \"" << r.opt.board << "\",\n  \"mode\": \"" << r.mode.name << "\",\n  \"pass\": "
      << (r.failures.empty() ? "true" : "false") << ",\n  \"frames\": [\n";
    for (size_t i = 0; i < r.frames.size(); ++i) {
        const FrameReport& f = r.frames[i];
        o << "    {\"frame\": " << f.frame << ", \"pixels_unlike_model\": " << f.differing
          << ", \"board_vs_double\": " << stats_json(f.vs_ref) << ", \"model8_vs_double\": "
          << stats_json(f.model8_vs_ref) << "}" << (i + 1 < r.frames.size() ? "," : "") << "\n";
    }
    const MeasuredTiming& m = r.measured;
    o << "  ],\n  \"timing\": {\"ok\": " << (r.timing.ok ? "true" : "false") << ", \"h\": [" << m.h_active << ", "
      << m.h_fp << ", " << m.h_sync << ", " << m.h_bp << "], \"v\": [" << m.v_active << ", " << m.v_fp << ", "
      << m.v_sync << ", " << m.v_bp << "], \"pixel_mhz\": " << num(m.pixel_mhz, 5) << ", \"frame_us\": "
      << num(m.frame_us, 3) << ", \"refresh_hz\": " << num(m.refresh_hz, 4) << "},\n"
      << "  \"frame_buffer\": " << (h.frame_buffer ? "true" : "false") << ",\n  \"pll_pixel_mhz\": "
      << num(h.pll_mhz, 4) << ",\n  \"setup_config\": \"" << r.setup_config << "\",\n  \"sim_ms\": " << num(double(h.sim_ps) * 1e-9, 1) << ",\n  \"wall_s\": "
      << num(h.wall_s, 1) << ",\n  \"render_percent\": "
      << num(h.render_clocks_budget ? 100.0 * h.render_clocks_max / h.render_clocks_budget : 0.0, 1)
      << ",\n  \"render_ms\": " << num(h.render_clocks_max / h.design_mhz * 1e-3, 2)
      << ",\n  \"render_fps\": " << num(h.render_clocks_max ? h.design_mhz * 1e6 / h.render_clocks_max : 0.0, 1)
      << ",\n  \"render_clocks_max\": " << h.render_clocks_max << ",\n  \"render_clocks_budget\": "
      << h.render_clocks_budget << ",\n  \"late\": " << (h.late ? "true" : "false") << ",\n  \"tmds_bad\": "
      << h.tmds_bad << ",\n  \"tmds_max_disparity\": " << h.tmds_max_disparity;
    if (h.pin_setup_ps >= 0) o << ",\n  \"pin_setup_ns\": " << num(h.pin_setup_ps * 1e-3, 2);
    if (h.pin_hold_ps >= 0) o << ",\n  \"pin_hold_ns\": " << num(h.pin_hold_ps * 1e-3, 2);
    o << ",\n  \"failures\": [";
    for (size_t i = 0; i < r.failures.size(); ++i) o << (i ? ", " : "") << "\"" << r.failures[i] << "\"";
    o << "]\n}\n";
    const std::string path = base + "_summary.json";
    render::write_atomic(path, [&](const std::string& tmp) {
        std::ofstream f(tmp);
        f << o.str();
        if (!f.good()) throw std::runtime_error("cannot write " + path);
    });
}

void print_split(const SplitOptions& o, const std::vector<SplitRow>& rows) {
    const BoardScene s = make_board_scene(o.mode, 1);
    std::printf("split points per chord against the error (%s, %zu frames, shader %s; levels of 255)\n\n",
                o.mode.c_str(), o.frames.size(), o.shader.c_str());
    std::printf("| K | sub-spans per line (mean, max) |");
    for (const Sphere& sp : s.spheres) std::printf(" n = %u: max, mean |", sp.n);
    std::printf(" max | worst PSNR |\n|---|---|");
    for (size_t i = 0; i < s.spheres.size(); ++i) std::printf("---|");
    std::printf("---|---|\n");
    for (const SplitRow& r : rows) {
        std::printf("| %d | %.1f, %d |", r.k, r.spans_per_line, r.spans_max_line);
        for (size_t i = 0; i < r.max_err.size(); ++i) std::printf(" %d, %.3f |", r.max_err[i], r.mean_err[i]);
        std::printf(" %d | %.1f dB |\n", r.max_all, r.psnr);
    }
    if (o.json.empty()) return;
    std::ostringstream j;
    j << "{\n  \"mode\": \"" << o.mode << "\",\n  \"shader\": \"" << o.shader << "\",\n  \"frames\": " << o.frames.size()
      << ",\n  \"rows\": [\n";
    for (size_t i = 0; i < rows.size(); ++i) {
        const SplitRow& r = rows[i];
        j << "    {\"k\": " << r.k << ", \"spans_per_line\": " << num(r.spans_per_line, 1) << ", \"spans_max_line\": "
          << r.spans_max_line << ", \"max\": " << r.max_all << ", \"psnr_db\": " << num(r.psnr, 1) << ", \"max_by_sphere\": [";
        for (size_t q = 0; q < r.max_err.size(); ++q) j << (q ? ", " : "") << r.max_err[q];
        j << "], \"mean_by_sphere\": [";
        for (size_t q = 0; q < r.mean_err.size(); ++q) j << (q ? ", " : "") << num(r.mean_err[q], 3);
        j << "]}" << (i + 1 < rows.size() ? "," : "") << "\n";
    }
    j << "  ]\n}\n";
    render::write_atomic(o.json, [&](const std::string& tmp) {
        std::ofstream f(tmp);
        f << j.str();
        if (!f.good()) throw std::runtime_error("cannot write " + o.json);
    });
}

}  // namespace board
}  // namespace spec
