// render_report.cpp - specsim render: what it prints and writes (PNG, panel, statistics JSON), and the
// command itself: parse_render -> build_scene -> render_compute -> this.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "cmd_render.h"
#include "commands.h"
#include "fileutil.h"
#include "image.h"
#include "setup_render.h"
#include "unit_driver.h"

namespace spec {

namespace {
// On a terminal: one line redrawn (\r) as the spans go through. Into a file or a pipe: a line at every
// quarter, so that logs stay readable.
class ProgressBar {
public:
    ProgressBar(bool on, std::string what) : on_(on), tty_(isatty(2)), what_(std::move(what)) {}
    void operator()(size_t done, size_t total) {
        if (!on_ || total == 0) return;
        const int pct = int(100.0 * double(done) / double(total));
        if (!tty_ && pct / 25 == last_ / 25 && done != total) return;
        if (!tty_ && done == total && last_ == 100) return;
        last_ = pct;
        const int width = 40;
        const int fill = int(double(done) / double(total) * width);
        std::string bar(size_t(fill), '#');
        bar += std::string(size_t(width - fill), '.');
        std::fprintf(stderr, "%s  %-9s [%s] %3d%%  %zu/%zu spans%s", tty_ ? "\r" : "", what_.c_str(), bar.c_str(),
                     pct, done, total, tty_ && done != total ? "" : "\n");
        std::fflush(stderr);
    }

private:
    bool on_, tty_;
    int last_ = -1;
    std::string what_;
};

std::string fmt(const char* f, double v) {
    char b[64];
    std::snprintf(b, sizeof b, f, v);
    return b;
}

void print_summary(const RenderOptions& ra, const render::Scene& sc, const RenderResult& res) {
    const render::Frame& frame = res.frame;
    std::printf("render: %s, %dx%d, %zu object(s), %llu triangles, %zu spans (%llu hidden spans not sent)\n",
                sc.name.c_str(), ra.size, ra.size, sc.objects.size(), (unsigned long long)frame.triangles,
                frame.spans.size(), (unsigned long long)frame.hidden_spans);
    if (sc.obj.loaded) {
        const render::ObjStats& o = sc.obj;
        std::printf("obj: %llu faces (%llu polygons triangulated), %llu triangles, %llu of no area left out; "
                    "normals computed for %llu vertices (%llu without vn, %llu zero-length, %llu not finite)\n",
                    (unsigned long long)o.faces, (unsigned long long)o.polygons, (unsigned long long)o.triangles,
                    (unsigned long long)o.degenerate, (unsigned long long)o.normals_computed(),
                    (unsigned long long)o.normals_missing, (unsigned long long)o.normals_zero,
                    (unsigned long long)o.normals_not_finite);
    }
    if (res.culled) {
        const methods::CullResult& c = res.cull;
        std::printf("cull-specular: %llu of %llu triangles, %llu of %llu spans, %llu of %llu core pixels skipped\n",
                    (unsigned long long)c.triangles_culled, (unsigned long long)c.triangles,
                    (unsigned long long)c.spans_culled, (unsigned long long)c.spans,
                    (unsigned long long)c.pixels_culled, (unsigned long long)c.pixels);
    }
    const ModelResult& main = res.results.front();
    const auto& hc = main.run.counters;
    std::printf("host: %llu spans; degenerate: %llu flat (gamma = 0 or one pixel), %llu nearly opposite normals, "
                "%llu without highlight (C = 0), %llu C saturated, %llu midpoint fits fell back\n",
                (unsigned long long)hc.spans, (unsigned long long)hc.flat, (unsigned long long)hc.opposite,
                (unsigned long long)hc.no_highlight, (unsigned long long)hc.c_saturated,
                (unsigned long long)hc.gamma_fallback);
    std::printf("%s%s: %llu pixels through the model in %.2f s (%.3g pixels/s)", render::model_name(main.model),
                ra.mode == Mode::tuned ? " (tuned mode)" : ra.mode == Mode::pow ? " (pow mode)" : "",
                (unsigned long long)main.run.core_pixels,
                main.run.seconds, double(main.run.core_pixels) / std::max(1e-9, main.run.seconds));
    if (main.model == render::SpecModel::rtl || main.model == render::SpecModel::shader) std::printf(", %llu clock cycles", (unsigned long long)main.run.core_cycles);
    std::printf("; rasterization and diffuse %.2f s\n", res.t_raster);
    if (!res.compared) return;
    std::printf("\nagainst ref (levels of 255; mean over object pixels; PSNR over the image):\n");
    std::printf("  %-10s %8s %10s %9s %11s %10s\n", "model", "max|err|", "mean|err|", "PSNR dB", "pixels > 4",
                "differing");
    for (const ModelResult& r : res.results) {
        std::printf("  %-10s %8d %10.4f %9s %11llu %10llu\n", r.name(), r.st.max_abs,
                    r.st.mean_abs, std::isinf(r.st.psnr) ? "inf" : fmt("%.2f", r.st.psnr).c_str(),
                    (unsigned long long)r.st.over_4, (unsigned long long)r.st.differing);
    }
    const ModelResult* gold = res.find(render::SpecModel::golden);
    if (gold && main.model == render::SpecModel::rtl) {
        std::printf("  rtl and golden images: %s\n", gold->img.rgb == main.img.rgb ? "identical" : "DIFFER");
    }
}

void write_panel(const RenderOptions& ra, const render::Scene& sc, const RenderResult& res) {
    const ModelResult* pm = res.find(ra.model);
    const ModelResult* pp = res.find(render::SpecModel::prototype);
    const ModelResult* pw = res.find_pow();   // the pow column (absent when the chosen mode is pow)
    const render::Image& ref = res.find(render::SpecModel::ref)->img;
    const render::Image em = render::error_map(pm->img, ref, ra.amp);
    const render::Image ep = render::error_map(pp->img, ref, ra.amp);
    const render::Image ew = pw ? render::error_map(pw->img, ref, ra.amp) : render::Image();
    const std::string amp = fmt("%g", ra.amp);
    const std::string mname = std::string(render::model_name(ra.model)) +
                              (ra.mode == Mode::tuned ? " (tuned)" : ra.mode == Mode::pow ? " (pow)" : "");
    std::vector<render::Tile> tiles{
        {&ref, "ref", "double precision"},
        {&pm->img, mname, ra.model == render::SpecModel::rtl      ? "Verilated spec_unit"
                          : ra.model == render::SpecModel::shader ? "Verilated spec_shader"
                                                                  : ""},
    };
    if (pw) tiles.push_back({&pw->img, "pow", "exp2(n log2 cos), bit-exact"});
    tiles.push_back({&pp->img, "prototype", "cos^2(sqrt(n/2) d)"});
    tiles.push_back({&em, "error of " + mname + " x" + amp, "max " + std::to_string(pm->st.max_abs) + " levels of 255"});
    if (pw) tiles.push_back({&ew, "error of pow x" + amp, "max " + std::to_string(pw->st.max_abs) + " levels of 255"});
    tiles.push_back({&ep, "error of prototype x" + amp, "max " + std::to_string(pp->st.max_abs) + " levels of 255"});
    const render::Image panel = render::make_panel(
        tiles, "UA 71489 specular core: scene " + sc.name + ", " + std::to_string(ra.size) + "x" +
                   std::to_string(ra.size) +
                   (sc.name == "default" ? " (n = 1, 3, 10, 100, 1000: one object per BRDF range)" : ""));
    render::write_png(ra.panel, panel);
}
}  // namespace

int cmd_render(int argc, char** argv) {
    const RenderOptions ra = parse_render(argc, argv);
    const render::Scene sc = build_scene(ra);
    const bool bar = ra.progress == 1 || (ra.progress == -1 && isatty(2));
    std::vector<std::unique_ptr<ProgressBar>> bars;
    const RenderResult res = render_compute(
        ra, sc, [](Mode m) { return make_unit_driver(m); },
        [&](render::SpecModel m) -> render::Progress {
            if (!bar || m != ra.model) return {};
            bars.emplace_back(new ProgressBar(true, render::model_name(m)));
            ProgressBar* pb = bars.back().get();
            return [pb](size_t d, size_t t) { (*pb)(d, t); };
        },
        [](SetupConfig c) { return make_shader_core(c); });
    print_summary(ra, sc, res);
    render::write_png(ra.out, res.results.front().img);
    if (!ra.panel.empty()) write_panel(ra, sc, res);
    if (!ra.stats.empty()) {
        const std::string j = render_stats_json(ra, sc, res);
        render::write_atomic(ra.stats, [&](const std::string& tmp) {
            std::ofstream o(tmp);
            o << j;
            o.close();
            if (!o) throw InputError("cannot write " + ra.stats);
        });
    }
    std::printf("\nimage: %s\n", ra.out.c_str());
    if (!ra.panel.empty()) std::printf("panel: %s\n", ra.panel.c_str());
    if (!ra.stats.empty()) std::printf("statistics: %s\n", ra.stats.c_str());
    return 0;
}

}  // namespace spec
