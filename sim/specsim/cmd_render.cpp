// cmd_render.cpp - specsim render, render-bench, plots, export-obj: the host side and the renderer (issue 3).
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "cli.h"
#include "setup_render.h"
#include "commands.h"
#include "fileutil.h"
#include "image.h"
#include "mesh.h"
#include "plots.h"
#include "raster.h"
#include "scene.h"
#include "shade.h"
#include "stats.h"
#include "highlight.h"

namespace spec {

const char* const kRenderUsage =
    "  render   a scene rendered by scanline spans, the specular term from the chosen model; PNG output\n"
    "           --scene NAME   default | sphere | torus | teapot (default: default)\n"
    "           --obj FILE     a triangulated OBJ file instead (normals from 'vn', else averaged)\n"
    "           --size N       image N x N pixels, 16..4096 (default 512)\n"
    "           --model M      rtl (Verilated spec_unit, default) | golden (bit-exact model) |\n"
    "                          ref (double, exact Blinn-Phong for the interpolated vectors) |\n"
    "                          prototype (cos^2(sqrt(n/2) zeta), Abbas et al.) | host (host angles, exact cos^n) |\n"
    "                          shader (Verilated spec_shader: span ends in, setup and core in RTL; docs/setup.md)\n"
    "           --shader-config C  pipelined (default) | small: the shader's configuration (--model shader)\n"
    "           --mode M       patent (default) | tuned: ROM 9 of the rtl and golden models (docs/tuned.md)\n"
    "           --out FILE     the rendered PNG (required)\n"
    "           --panel FILE   also render ref and prototype: PNG of ref | model | prototype | error maps\n"
    "           --stats FILE   also render ref, prototype, host: errors against ref as JSON\n"
    "           --amp A        error-map amplification (default 16: 16 levels of error = full scale)\n"
    "           --rgb MODE     once (core run once per span, colour applied on the host; default) |\n"
    "                          per-channel (three runs per span, C per channel)\n"
    "           --host RULE    patent (gamma = angle(H1, H2'), eq. 4; default) | midpoint (gamma fitted to\n"
    "                          N.H at the span's middle too: exact when N.H is a sinusoid, docs/host.md)\n"
    "           --progress / --quiet   progress bar on stderr (default: when stderr is a terminal)\n"
    "           --cull-specular  the chosen model skips triangles where a bound on N.H shows the core would output\n"
    "                          0 (companion paper A; the image is unchanged; docs/methods.md)\n"
    "           light:    --light-dir X,Y,Z (toward the light)  --light-color R,G,B  --light-intensity Is\n"
    "                     --ambient R,G,B\n"
    "           material (every object; an OBJ gets these): --n N (0..1023)  --ks K  --kd K  --ka K\n"
    "                     --color R,G,B  --spec-color R,G,B   (coefficients and channels in [0, 1])\n"
    "           camera:   --eye X,Y,Z  --target X,Y,Z  --up X,Y,Z  --fov DEGREES (vertical)\n"
    "  render-bench  speed of the render: host spans/s, golden and rtl pixels/s (medians, ratios)\n"
    "           --size N (default 256)  --runs R (3..15, default 5)  --scene NAME\n"
    "  plots    the patent's Fig. 5 and Fig. 9 redrawn (gnuplot): --out-dir DIR (fig5.png, fig9.png, .dat)\n"
    "  export-obj  a built-in scene's meshes as one OBJ file: --scene NAME --out FILE.obj\n";

namespace {
using render::dvec3;
using render::InputError;

dvec3 parse_vec3(const std::string& flag, const std::string& s) {
    std::vector<double> v;
    size_t a = 0;
    for (;;) {
        const size_t b = s.find(',', a);
        v.push_back(parse_double(flag, s.substr(a, b == std::string::npos ? std::string::npos : b - a)));
        if (b == std::string::npos) break;
        a = b + 1;
    }
    if (v.size() != 3) throw UsageError(flag + ": expected three comma-separated numbers X,Y,Z, got '" + s + "'");
    return dvec3(v[0], v[1], v[2]);
}

struct RenderArgs {
    std::string scene = "default", obj, out, panel, stats;
    int size = 512;
    render::SpecModel model = render::SpecModel::rtl;
    Mode mode = Mode::patent;
    render::RgbMode rgb = render::RgbMode::once;
    host::GammaRule gamma = host::GammaRule::patent;
    double amp = 16;
    int progress = -1;  // -1: when stderr is a terminal
    bool cull = false;  // --cull-specular
    SetupConfig shader_config = SetupConfig::pipelined;   // --shader-config (--model shader, docs/setup.md)
    // overrides
    bool has_light_dir = false, has_light_color = false, has_intensity = false, has_ambient = false;
    dvec3 light_dir, light_color, ambient;
    double intensity = 1;
    bool has_n = false, has_ks = false, has_kd = false, has_ka = false, has_color = false, has_spec_color = false;
    long long n = 0;
    double ks = 0, kd = 0, ka = 0;
    dvec3 color, spec_color;
    bool has_eye = false, has_target = false, has_up = false, has_fov = false;
    dvec3 eye, target, up;
    double fov = 0;
};

RenderArgs parse_render(int argc, char** argv) {
    RenderArgs r;
    bool have_scene = false;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string f = a.flag();
        if (f == "--scene") { r.scene = a.value(f); have_scene = true; }
        else if (f == "--obj") r.obj = a.value(f);
        else if (f == "--size") r.size = int(parse_int(f, a.value(f), 16, 4096));
        else if (f == "--model") r.model = render::parse_model(a.value(f));
        else if (f == "--mode") {
            const std::string m = a.value(f);
            if (m == "patent") r.mode = Mode::patent;
            else if (m == "tuned") r.mode = Mode::tuned;
            else throw UsageError("--mode: '" + m + "' is not patent or tuned");
        }
        else if (f == "--out") r.out = a.value(f);
        else if (f == "--panel") r.panel = a.value(f);
        else if (f == "--stats") r.stats = a.value(f);
        else if (f == "--amp") {
            r.amp = parse_double(f, a.value(f));
            if (r.amp < 1 || r.amp > 255) throw UsageError("--amp: must be in [1, 255]");
        } else if (f == "--rgb") {
            const std::string m = a.value(f);
            if (m == "once") r.rgb = render::RgbMode::once;
            else if (m == "per-channel") r.rgb = render::RgbMode::per_channel;
            else throw UsageError("--rgb: '" + m + "' is not once or per-channel");
        } else if (f == "--host") {
            const std::string m = a.value(f);
            if (m == "patent") r.gamma = host::GammaRule::patent;
            else if (m == "midpoint") r.gamma = host::GammaRule::midpoint;
            else throw UsageError("--host: '" + m + "' is not patent or midpoint");
        } else if (f == "--progress") r.progress = 1;
        else if (f == "--quiet") r.progress = 0;
        else if (f == "--cull-specular") r.cull = true;
        else if (f == "--shader-config") {
            try {
                r.shader_config = parse_setup_config(a.value(f));
            } catch (const std::invalid_argument& e) {
                throw UsageError(std::string("--shader-config: ") + e.what());
            }
        }
        else if (f == "--light-dir") { r.light_dir = parse_vec3(f, a.value(f)); r.has_light_dir = true; }
        else if (f == "--light-color") { r.light_color = parse_vec3(f, a.value(f)); r.has_light_color = true; }
        else if (f == "--light-intensity") { r.intensity = parse_double(f, a.value(f)); r.has_intensity = true; }
        else if (f == "--ambient") { r.ambient = parse_vec3(f, a.value(f)); r.has_ambient = true; }
        else if (f == "--n") { r.n = parse_int(f, a.value(f), 0, 1023); r.has_n = true; }
        else if (f == "--ks") { r.ks = parse_double(f, a.value(f)); r.has_ks = true; }
        else if (f == "--kd") { r.kd = parse_double(f, a.value(f)); r.has_kd = true; }
        else if (f == "--ka") { r.ka = parse_double(f, a.value(f)); r.has_ka = true; }
        else if (f == "--color") { r.color = parse_vec3(f, a.value(f)); r.has_color = true; }
        else if (f == "--spec-color") { r.spec_color = parse_vec3(f, a.value(f)); r.has_spec_color = true; }
        else if (f == "--eye") { r.eye = parse_vec3(f, a.value(f)); r.has_eye = true; }
        else if (f == "--target") { r.target = parse_vec3(f, a.value(f)); r.has_target = true; }
        else if (f == "--up") { r.up = parse_vec3(f, a.value(f)); r.has_up = true; }
        else if (f == "--fov") { r.fov = parse_double(f, a.value(f)); r.has_fov = true; }
        else throw UsageError("render: unknown option " + f);
    }
    if (have_scene && !r.obj.empty()) throw UsageError("render: --scene and --obj exclude each other");
    if (r.out.empty()) throw UsageError("render: --out FILE.png is required");
    return r;
}

render::Scene build_scene(const RenderArgs& r) {
    render::Material m;
    auto apply = [&](render::Material& x) {
        if (r.has_n) x.n = unsigned(r.n);
        if (r.has_ks) x.ks = r.ks;
        if (r.has_kd) x.kd = r.kd;
        if (r.has_ka) x.ka = r.ka;
        if (r.has_color) x.color = r.color;
        if (r.has_spec_color) x.spec_color = r.spec_color;
    };
    apply(m);
    render::Scene s = r.obj.empty() ? render::make_scene(r.scene) : render::scene_from_obj(r.obj, m);
    if (r.obj.empty()) {
        for (auto& o : s.objects) apply(o.mat);
    }
    if (r.has_light_dir) s.light.dir = r.light_dir;
    if (r.has_light_color) s.light.color = r.light_color;
    if (r.has_intensity) s.light.intensity = r.intensity;
    if (r.has_ambient) s.ambient = r.ambient;
    if (r.has_eye) s.camera.eye = r.eye;
    if (r.has_target) s.camera.target = r.target;
    if (r.has_up) s.camera.up = r.up;
    if (r.has_fov) s.camera.fov_deg = r.fov;
    s.validate();
    return s;
}

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

std::string json_num(double v) {
    if (std::isinf(v)) return "null";
    return fmt("%.6g", v);
}

struct ModelResult {
    render::SpecModel model;
    render::SpecRun run;
    render::Image img;
    render::ImageStats st;
};
}  // namespace

int cmd_render(int argc, char** argv) {
    const RenderArgs ra = parse_render(argc, argv);
    const render::Scene sc = build_scene(ra);
    const bool bar = ra.progress == 1 || (ra.progress == -1 && isatty(2));
    const auto t0 = std::chrono::steady_clock::now();
    const render::Frame frame = render::rasterize(sc, ra.size, ra.size);
    const render::Shading base = render::shade_base(sc, frame);
    const double t_raster = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    std::vector<render::SpecModel> models{ra.model};
    const bool compare = !ra.panel.empty() || !ra.stats.empty();
    if (compare) {
        for (auto m : {render::SpecModel::ref, render::SpecModel::golden, render::SpecModel::prototype,
                       render::SpecModel::host}) {
            if (m == render::SpecModel::golden && ra.model != render::SpecModel::rtl) continue;
            if (std::find(models.begin(), models.end(), m) == models.end()) models.push_back(m);
        }
    }
    std::printf("render: %s, %dx%d, %zu object(s), %llu triangles, %zu spans (%llu hidden spans not sent)\n",
                sc.name.c_str(), ra.size, ra.size, sc.objects.size(), (unsigned long long)frame.triangles,
                frame.spans.size(), (unsigned long long)frame.hidden_spans);
    std::fflush(stdout);
    // --cull-specular (companion paper A, docs/methods.md): the chosen model's specular pass runs on the spans of
    // the triangles whose N.H bound lets the core output anything; diffuse and the comparison models see all
    render::Frame culled;
    if (ra.cull) {
        Format cf;
        cf.mode = ra.mode;
        const methods::CullResult c = methods::cull_spans(sc, frame, Model(cf));
        culled = methods::kept_frame(frame, c);
        std::printf("cull-specular: %llu of %llu triangles, %llu of %llu spans, %llu of %llu core pixels skipped\n",
                    (unsigned long long)c.triangles_culled, (unsigned long long)c.triangles,
                    (unsigned long long)c.spans_culled, (unsigned long long)c.spans,
                    (unsigned long long)c.pixels_culled, (unsigned long long)c.pixels);
        std::fflush(stdout);
    }
    std::vector<ModelResult> res;
    for (auto m : models) {
        ModelResult r;
        r.model = m;
        const render::Frame& spec_frame = ra.cull && m == ra.model ? culled : frame;
        ProgressBar pb(bar && m == ra.model, render::model_name(m));
        const render::Progress prog = [&](size_t d, size_t t) { pb(d, t); };
        r.run = m == render::SpecModel::shader ? shade_shader(sc, spec_frame, ra.shader_config, ra.rgb, ra.gamma, prog)
                                               : render::shade_specular(sc, spec_frame, m, ra.rgb, ra.gamma, prog, ra.mode);
        r.img = render::compose(base, r.run);
        res.push_back(std::move(r));
        if (m == ra.model) render::write_png(ra.out, res.back().img);
    }
    const ModelResult& main = res.front();
    const render::Image* ref = nullptr;
    const render::Image* proto = nullptr;
    for (auto& r : res) {
        if (r.model == render::SpecModel::ref) ref = &r.img;
        if (r.model == render::SpecModel::prototype) proto = &r.img;
    }
    const auto& hc = main.run.counters;
    std::printf("host: %llu spans; degenerate: %llu flat (gamma = 0 or one pixel), %llu nearly opposite normals, "
                "%llu without highlight (C = 0), %llu C saturated, %llu midpoint fits fell back\n",
                (unsigned long long)hc.spans, (unsigned long long)hc.flat, (unsigned long long)hc.opposite,
                (unsigned long long)hc.no_highlight, (unsigned long long)hc.c_saturated,
                (unsigned long long)hc.gamma_fallback);
    std::printf("%s%s: %llu pixels through the model in %.2f s (%.3g pixels/s)", render::model_name(main.model),
                ra.mode == Mode::tuned ? " (tuned mode)" : "",
                (unsigned long long)main.run.core_pixels, main.run.seconds,
                double(main.run.core_pixels) / std::max(1e-9, main.run.seconds));
    if (main.model == render::SpecModel::rtl || main.model == render::SpecModel::shader) {
        std::printf(", %llu clock cycles", (unsigned long long)main.run.core_cycles);
    }
    std::printf("; rasterization and diffuse %.2f s\n", t_raster);
    if (compare) {
        std::printf("\nagainst ref (levels of 255; mean over object pixels; PSNR over the image):\n");
        std::printf("  %-10s %8s %10s %9s %11s %10s\n", "model", "max|err|", "mean|err|", "PSNR dB", "pixels > 4",
                    "differing");
        for (auto& r : res) {
            r.st = render::compare(r.img, *ref, base.covered);
            std::printf("  %-10s %8d %10.4f %9s %11llu %10llu\n", render::model_name(r.model), r.st.max_abs,
                        r.st.mean_abs, std::isinf(r.st.psnr) ? "inf" : fmt("%.2f", r.st.psnr).c_str(),
                        (unsigned long long)r.st.over_4, (unsigned long long)r.st.differing);
        }
        for (auto& r : res) {
            if (r.model == render::SpecModel::golden && main.model == render::SpecModel::rtl) {
                std::printf("  rtl and golden images: %s\n", r.img.rgb == main.img.rgb ? "identical" : "DIFFER");
            }
        }
    }
    if (!ra.panel.empty()) {
        const ModelResult* pm = nullptr;
        const ModelResult* pp = nullptr;
        for (auto& r : res) {
            if (r.model == ra.model) pm = &r;
            if (r.model == render::SpecModel::prototype) pp = &r;
        }
        const render::Image em = render::error_map(pm->img, *ref, ra.amp);
        const render::Image ep = render::error_map(*proto, *ref, ra.amp);
        const std::string amp = fmt("%g", ra.amp);
        const std::string mname =
            std::string(render::model_name(ra.model)) + (ra.mode == Mode::tuned ? " (tuned)" : "");
        std::vector<render::Tile> tiles{
            {ref, "ref", "double precision"},
            {&pm->img, mname, ra.model == render::SpecModel::rtl ? "Verilated spec_unit" : ""},
            {proto, "prototype", "cos^2(sqrt(n/2) d)"},
            {&em, "error of " + mname + " x" + amp, "max " + std::to_string(pm->st.max_abs) + " levels of 255"},
            {&ep, "error of prototype x" + amp, "max " + std::to_string(pp->st.max_abs) + " levels of 255"},
        };
        const render::Image panel = render::make_panel(
            tiles, "UA 71489 specular core: scene " + sc.name + ", " + std::to_string(ra.size) + "x" +
                       std::to_string(ra.size) +
                       (sc.name == "default" ? " (n = 1, 3, 10, 100, 1000: one object per BRDF range)" : ""));
        render::write_png(ra.panel, panel);
    }
    if (!ra.stats.empty()) {
        std::ostringstream j;
        j << "{\n  \"scene\": \"" << sc.name << "\",\n  \"size\": " << ra.size << ",\n  \"model\": \""
          << render::model_name(ra.model) << "\",\n  \"mode\": \"" << mode_name(ra.mode) << "\",\n  \"rgb\": \""
          << (ra.rgb == render::RgbMode::once ? "once" : "per-channel") << "\",\n  \"host_gamma\": \""
          << (ra.gamma == host::GammaRule::patent ? "patent" : "midpoint") << "\",\n";
        j << "  \"triangles\": " << frame.triangles << ",\n  \"spans\": " << frame.spans.size()
          << ",\n  \"hidden_spans\": " << frame.hidden_spans << ",\n";
        j << "  \"host\": {\"spans\": " << hc.spans << ", \"flat\": " << hc.flat << ", \"opposite_normals\": "
          << hc.opposite << ", \"no_highlight\": " << hc.no_highlight << ", \"c_saturated\": " << hc.c_saturated
          << ", \"single_pixel\": " << hc.single_pixel << ", \"gamma_fallback\": " << hc.gamma_fallback
          << "},\n";
        j << "  \"against_ref\": {\n";
        for (size_t i = 0; i < res.size(); ++i) {
            const auto& r = res[i];
            j << "    \"" << render::model_name(r.model) << "\": {\"max_abs\": " << r.st.max_abs
              << ", \"mean_abs\": " << json_num(r.st.mean_abs) << ", \"psnr_db\": " << json_num(r.st.psnr)
              << ", \"pixels_over_4\": " << r.st.over_4 << ", \"pixels_differing\": " << r.st.differing
              << ", \"model_pixels\": " << r.run.core_pixels << ", \"seconds\": " << json_num(r.run.seconds)
              << "}" << (i + 1 < res.size() ? "," : "") << "\n";
        }
        j << "  },\n  \"covered_pixels\": " << (ref ? res.front().st.covered : 0) << "\n}\n";
        render::write_atomic(ra.stats, [&](const std::string& tmp) {
            std::ofstream o(tmp);
            o << j.str();
            o.close();
            if (!o) throw std::runtime_error("cannot write " + ra.stats);
        });
    }
    std::printf("\nimage: %s\n", ra.out.c_str());
    if (!ra.panel.empty()) std::printf("panel: %s\n", ra.panel.c_str());
    if (!ra.stats.empty()) std::printf("statistics: %s\n", ra.stats.c_str());
    return 0;
}

namespace {
double now_s() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t k = v.size() / 2;
    return v.size() % 2 ? v[k] : 0.5 * (v[k - 1] + v[k]);
}

// Runs f repeatedly for at least min_s seconds; returns (work items done) / (seconds).
template <class F>
double rate(F f, double min_s) {
    double done = 0;
    const double t0 = now_s();
    double t = t0;
    do {
        done += f();
        t = now_s();
    } while (t - t0 < min_s);
    return done / (t - t0);
}
}  // namespace

int cmd_render_bench(int argc, char** argv) {
    std::string scene = "default";
    int size = 512, runs = 5;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string f = a.flag();
        if (f == "--size") size = int(parse_int(f, a.value(f), 16, 4096));
        else if (f == "--runs") runs = int(parse_int(f, a.value(f), 3, 15));
        else if (f == "--scene") scene = a.value(f);
        else throw UsageError("render-bench: unknown option " + f);
    }
    render::Scene sc = render::make_scene(scene);
    sc.validate();
    const render::Frame fr = render::rasterize(sc, size, size);
    const Model core;
    uint64_t model_px = 0;
    for (const auto& sp : fr.spans) model_px += sp.l + 1;
    std::printf("render-bench: scene %s, %dx%d, %zu spans, %llu pixels through the model per frame, "
                "%d runs (medians; each run at least 0.3 s)\n",
                scene.c_str(), size, size, fr.spans.size(), (unsigned long long)model_px, runs);
    std::vector<double> host_sps, gold_pps, rtl_pps, rtl_cps, ref_pps, frame_rtl, frame_gold;
    for (int r = 0; r < runs; ++r) {
        host_sps.push_back(rate([&] {
            double acc = 0;
            for (const auto& sp : fr.spans) {
                const auto& m = sc.objects[sp.obj].mat;
                acc += host::setup_span(core, sp.ends, sc.light.intensity * m.ks, m.n, sp.l).c;
            }
            if (acc < 0) std::printf("?");  // keep the work observable
            return double(fr.spans.size());
        }, 0.3));
        render::SpecRun last;
        gold_pps.push_back(rate([&] {
            last = render::shade_specular(sc, fr, render::SpecModel::golden, render::RgbMode::once);
            return double(last.core_pixels);
        }, 0.3));
        uint64_t cycles = 0;
        const double t0 = now_s();
        rtl_pps.push_back(rate([&] {
            last = render::shade_specular(sc, fr, render::SpecModel::rtl, render::RgbMode::once);
            cycles += last.core_cycles;
            return double(last.core_pixels);
        }, 0.3));
        rtl_cps.push_back(double(cycles) / (now_s() - t0));
        ref_pps.push_back(rate([&] {
            last = render::shade_specular(sc, fr, render::SpecModel::ref, render::RgbMode::once);
            return double(last.core_pixels);
        }, 0.3));
        for (auto m : {render::SpecModel::rtl, render::SpecModel::golden}) {
            const double t1 = now_s();
            const render::Frame f2 = render::rasterize(sc, size, size);
            const render::Shading b = render::shade_base(sc, f2);
            const render::Image img = render::compose(b, render::shade_specular(sc, f2, m, render::RgbMode::once));
            (m == render::SpecModel::rtl ? frame_rtl : frame_gold).push_back(now_s() - t1);
        }
    }
    auto line = [](const char* what, const std::vector<double>& v, const char* unit) {
        const auto mm = std::minmax_element(v.begin(), v.end());
        std::printf("  %-34s %12.4g %-10s (runs %.3g .. %.3g)\n", what, median(v), unit, *mm.first, *mm.second);
    };
    line("host: span setup", host_sps, "spans/s");
    line("golden model: specular stage", gold_pps, "pixels/s");
    line("rtl (Verilated spec_unit): specular", rtl_pps, "pixels/s");
    line("rtl: simulated clock", rtl_cps, "cycles/s");
    line("ref (double, per-pixel slerp)", ref_pps, "pixels/s");
    line("whole frame with rtl", frame_rtl, "s");
    line("whole frame with golden", frame_gold, "s");
    const double host_s = double(fr.spans.size()) / median(host_sps), rtl_s = double(model_px) / median(rtl_pps);
    std::printf("  ratios of medians: golden / rtl = %.1f; ref / rtl = %.1f; host setup = %.0f %% of the rtl specular "
                "stage's time; %.2f rtl clock cycles per pixel (2 per pixel + per-span overhead, %.2f pixels a span)\n",
                median(gold_pps) / median(rtl_pps), median(ref_pps) / median(rtl_pps), 100.0 * host_s / rtl_s,
                median(rtl_cps) / median(rtl_pps), double(model_px) / double(fr.spans.size()));
    return 0;
}
int cmd_plots(int argc, char** argv) {
    std::string dir;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string f = a.flag();
        if (f == "--out-dir") dir = a.value(f);
        else throw UsageError("plots: unknown option " + f);
    }
    if (dir.empty()) throw UsageError("plots: --out-dir DIR is required");
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw std::runtime_error("cannot create " + dir + ": " + ec.message());
    std::cout << render::make_plots(dir);
    std::cout << "plots: " << dir << "/fig5.png, " << dir << "/fig9.png (data: fig5.dat, fig9.dat, script fig.gp)\n";
    return 0;
}

int cmd_export_obj(int argc, char** argv) {
    std::string scene, out;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string f = a.flag();
        if (f == "--scene") scene = a.value(f);
        else if (f == "--out") out = a.value(f);
        else throw UsageError("export-obj: unknown option " + f);
    }
    if (scene.empty() || out.empty()) throw UsageError("export-obj: --scene NAME and --out FILE are required");
    const render::Scene s = render::make_scene(scene);
    render::Mesh all;
    for (const auto& o : s.objects) {
        const uint32_t base = uint32_t(all.pos.size());
        all.pos.insert(all.pos.end(), o.mesh.pos.begin(), o.mesh.pos.end());
        all.nrm.insert(all.nrm.end(), o.mesh.nrm.begin(), o.mesh.nrm.end());
        for (auto t : o.mesh.tri) all.tri.push_back({t[0] + base, t[1] + base, t[2] + base});
    }
    render::write_obj(all, out);
    std::printf("%s: %zu vertices, %zu triangles\n", out.c_str(), all.pos.size(), all.tri.size());
    return 0;
}

}  // namespace spec
