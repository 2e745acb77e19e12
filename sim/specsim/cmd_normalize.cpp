// cmd_normalize.cpp - specsim normalize: options, and the run (compute, then report).
#include "cmd_normalize.h"

#include <cstdio>

#include "cli.h"
#include "image.h"
#include "methods_usage.h"
#include "methods_util.h"
#include "raster.h"
#include "scenes.h"
#include "stats.h"

namespace spec {

const char* const kNormalizeUsage = SPEC_NORMALIZE_USAGE;

NormalizeOptions parse_normalize(int argc, char** argv) {
    NormalizeOptions o;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string f = a.flag();
        if (f == "--size") {
            o.size = int(parse_int(f, a.value(f), 16, 4096));
        } else if (f == "--runs") {
            o.runs = int(parse_int(f, a.value(f), 3, 15));
        } else if (f == "--timing") {
            o.timing = true;
        } else if (f == "--diffuse-bound" || f == "--specular-bound") {
            const double v = parse_double(f, a.value(f));
            if (!(v > 0 && v < 0.5)) throw UsageError(f + ": must be in (0, 0.5)");
            (f == "--diffuse-bound" ? o.bounds.diffuse : o.bounds.specular) = v;
        } else if (f == "--extend") {
            const std::string e = a.value(f);
            if (e == "paper") o.bounds.slerp_extension = false;
            else if (e == "slerp") o.bounds.slerp_extension = true;
            else throw UsageError("--extend: '" + e + "' is not paper or slerp");
        } else if (f == "--scene") {
            const std::string s = a.value(f);
            bool known = false;
            for (const auto& n : methods::methods_scene_names()) known = known || n == s;
            if (!known) throw UsageError("--scene: unknown scene '" + s + "'");
            o.scenes.push_back(s);
        } else if (f == "--out-dir") {
            o.out_dir = a.value(f);
        } else if (f == "--tables") {
            o.tables = a.value(f);
        } else {
            throw UsageError("normalize: unknown option " + f);
        }
    }
    if (o.scenes.empty()) o.scenes = methods::methods_scene_names();
    return o;
}

int cmd_normalize(int argc, char** argv) {
    if (methods_cli::wants_help(argc, argv, kNormalizeUsage)) return 0;
    const NormalizeOptions opt = parse_normalize(argc, argv);
    if (!opt.out_dir.empty()) methods_cli::make_dir(opt.out_dir);
    methods_cli::DocTables doc;
    std::printf("Companion paper B (seeds/003): adaptive normalization of normal vectors\n\n");
    report_normalize_figures(opt.bounds, opt.out_dir, &doc);
    std::vector<methods::NormRow> rows;
    for (const auto& name : opt.scenes) {
        const render::Scene sc = methods::methods_scene(name);
        const std::vector<methods::NormRow> r = methods::evaluate_normalize(name, sc, opt.size, opt.bounds);
        rows.insert(rows.end(), r.begin(), r.end());
        if (!opt.out_dir.empty()) {
            const render::Frame fr = render::rasterize(sc, opt.size, opt.size);
            const methods::PhongRun full = methods::shade_phong(sc, fr, methods::NormMode::full, opt.bounds);
            const methods::PhongRun adap = methods::shade_phong(sc, fr, methods::NormMode::adaptive, opt.bounds);
            const render::Image em = render::error_map(adap.img, full.img, 16);
            const render::Image panel = render::make_panel(
                {{&full.img, "full normalization", "classic Phong"},
                 {&adap.img, "adaptive", methods_cli::strf("bounds %.3g / %.3g", opt.bounds.diffuse, opt.bounds.specular)},
                 {&em, "difference x16", methods_cli::strf("max %d levels of 255", r.back().image_max)}},
                "Companion paper B: adaptive normalization, scene " + name);
            render::write_png(opt.out_dir + "/panel_" + name + ".png", panel);
        }
    }
    std::printf("2. The Phong path (N and H interpolated along each span, Blinn-Phong per pixel, no core) at %dx%d,\n"
                "   every way of making the vectors unit (bounds of adaptive: diffuse %.2g, specular %.2g; span\n"
                "   extended to 2^k %s):\n\n",
                opt.size, opt.size, opt.bounds.diffuse, opt.bounds.specular,
                opt.bounds.slerp_extension ? "on the great circle (--extend slerp)" : "by the paper's linear extrapolation");
    report_normalize_rows(rows, &doc);
    if (!opt.out_dir.empty()) plot_normalize_cost(rows, opt.out_dir);
    if (opt.timing) report_normalize_timing(opt);
    doc.write(opt.tables);
    return 0;
}

}  // namespace spec
