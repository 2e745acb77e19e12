// cmd_highlight.cpp - specsim highlight: options, and the run (compute, then report).
#include "cmd_highlight.h"

#include <cstdio>
#include <memory>

#include "cli.h"
#include "methods_usage.h"
#include "methods_util.h"
#include "scenes.h"
#include "unit_driver.h"

namespace spec {

const char* const kHighlightUsage = SPEC_HIGHLIGHT_USAGE;

HighlightOptions parse_highlight(int argc, char** argv) {
    HighlightOptions o;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string f = a.flag();
        if (f == "--size") {
            o.size = int(parse_int(f, a.value(f), 16, 4096));
        } else if (f == "--model") {
            const std::string m = a.value(f);
            if (m != "rtl" && m != "golden") throw UsageError("--model: must be rtl or golden");
            o.model = m == "rtl" ? render::SpecModel::rtl : render::SpecModel::golden;
        } else if (f == "--scene") {
            const std::string s = a.value(f);
            bool known = false;
            for (const auto& n : methods::methods_scene_names()) known = known || n == s;
            if (!known) throw UsageError("--scene: unknown scene '" + s + "'");
            o.scenes.push_back(s);
        } else if (f == "--coarse-n") {
            o.coarse_n = unsigned(parse_int(f, a.value(f), 0, 1023));
        } else if (f == "--samples") {
            o.samples = uint64_t(parse_int(f, a.value(f), 1000, 10000000));
        } else if (f == "--out-dir") {
            o.out_dir = a.value(f);
        } else if (f == "--tables") {
            o.tables = a.value(f);
        } else {
            throw UsageError("highlight: unknown option " + f);
        }
    }
    if (o.scenes.empty()) o.scenes = methods::methods_scene_names();
    return o;
}

int cmd_highlight(int argc, char** argv) {
    if (methods_cli::wants_help(argc, argv, kHighlightUsage)) return 0;
    const HighlightOptions opt = parse_highlight(argc, argv);
    if (!opt.out_dir.empty()) methods_cli::make_dir(opt.out_dir);
    // the renderer takes its core (sim/model/span_core.h): the Verilated spec_unit for --model rtl
    const std::unique_ptr<SpanCore> unit = opt.model == render::SpecModel::rtl ? make_unit_driver(Mode::patent) : nullptr;
    std::printf("Companion paper A (seeds/004): the highlight-in-triangle test and the --cull-specular bound. Scenes\n"
                "at %dx%d through the %s core.\n\n",
                opt.size, opt.size, opt.model == render::SpecModel::rtl ? "Verilated (rtl)" : "bit-exact (golden)");
    std::vector<methods::SceneEval> ev;
    for (const auto& name : opt.scenes) {
        ev.push_back(methods::evaluate_scene(name, methods::methods_scene(name), opt.size, opt.model, unit.get()));
        if (!opt.out_dir.empty()) write_highlight_picture(ev.back(), opt.out_dir);
        ev.back().image = render::Image();
    }
    if (opt.coarse_n > 0) {
        for (const auto& name : opt.scenes) {
            bool coarse = false;
            for (const auto& c : methods::coarse_scene_names()) coarse = coarse || c == name;
            if (!coarse) continue;
            render::Scene sc = methods::methods_scene(name);
            methods::set_exponent(&sc, opt.coarse_n);
            ev.push_back(methods::evaluate_scene(name + " n=" + std::to_string(opt.coarse_n), sc, opt.size, opt.model,
                                                 unit.get()));
            ev.back().image = render::Image();
        }
    }
    methods_cli::DocTables doc;
    report_highlight_scenes(ev, opt.model == render::SpecModel::rtl, &doc);
    report_highlight_synthetic(methods::synthetic_rows(opt.samples, {1, 3, 10, 30}),
                               methods::op_counts(std::min<uint64_t>(opt.samples, 20000)), &doc);
    doc.write(opt.tables);
    return 0;
}

}  // namespace spec
