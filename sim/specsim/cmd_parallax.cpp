// cmd_parallax.cpp - specsim parallax: options, and the run (compute, then report).
#include "cmd_parallax.h"

#include <cstdio>
#include <stdexcept>

#include "cli.h"
#include "methods_usage.h"
#include "methods_util.h"

namespace spec {

const char* const kParallaxUsage = SPEC_PARALLAX_USAGE;

ParallaxOptions parse_parallax(int argc, char** argv) {
    ParallaxOptions o;
    double threshold = -1;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string f = a.flag();
        if (f == "--map") {
            const std::string n = a.value(f);
            bool known = false;
            for (const auto& k : methods::heightmap_names()) known = known || k == n;
            if (!known) throw UsageError("--map: unknown height map '" + n + "' (one of waves, bumps, bricks, rocks)");
            o.maps.push_back(n);
        } else if (f == "--map-size") {
            o.setup.map_size = int(parse_int(f, a.value(f), 16, 2048));
            if (o.setup.map_size & (o.setup.map_size - 1)) throw UsageError("--map-size: must be a power of two");
        } else if (f == "--depth") {
            o.setup.depth = parse_double(f, a.value(f));
            if (!(o.setup.depth > 0 && o.setup.depth <= 0.5)) throw UsageError("--depth: must be in (0, 0.5]");
        } else if (f == "--threshold") {
            threshold = parse_double(f, a.value(f));
            if (!(threshold > 0 && threshold < 1)) throw UsageError("--threshold: must be in (0, 1)");
        } else if (f == "--max-iter") {
            o.cap = int(parse_int(f, a.value(f), 1, 63));
        } else if (f == "--budgets") {
            o.budgets.clear();
            const std::string v = a.value(f);
            size_t pos = 0;
            for (;;) {
                const size_t c = v.find(',', pos);
                const int b = int(parse_int(f, v.substr(pos, c == std::string::npos ? std::string::npos : c - pos), 1, 256));
                if (!o.budgets.empty() && b <= o.budgets.back()) throw UsageError("--budgets: must be increasing");
                o.budgets.push_back(b);
                if (c == std::string::npos) break;
                pos = c + 1;
            }
            if (o.budgets.size() > 16) throw UsageError("--budgets: at most 16");
        } else if (f == "--grid") {
            o.setup.grid = int(parse_int(f, a.value(f), 2, 256));
        } else if (f == "--out-dir") {
            o.out_dir = a.value(f);
        } else if (f == "--tables") {
            o.tables = a.value(f);
        } else {
            throw UsageError("parallax: unknown option " + f);
        }
    }
    if (o.maps.empty()) o.maps = methods::heightmap_names();
    o.setup.threshold = threshold > 0 ? threshold : o.setup.depth / 512;
    return o;
}

int cmd_parallax(int argc, char** argv) {
    if (methods_cli::wants_help(argc, argv, kParallaxUsage)) return 0;
    const ParallaxOptions opt = parse_parallax(argc, argv);
    if (!opt.out_dir.empty()) methods_cli::make_dir(opt.out_dir);
    std::vector<methods::HeightMap> maps;
    for (const auto& n : opt.maps) maps.push_back(methods::make_heightmap(n, opt.setup.map_size));
    const auto& s = opt.setup;
    std::printf("Companion paper C (seeds/002): iterative parallax mapping. Height maps %dx%d (bilinear, repeating),\n"
                "relief depth s = %g texture units (%.1f texels), threshold |d| <= %.3g; per elevation %d azimuths x\n"
                "%dx%d fragments. Errors: |(u', v') - exact| in texels, the exact intersection being the one nearest\n"
                "the viewer.\n\n",
                s.map_size, s.map_size, s.depth, s.depth * s.map_size, s.thr(), s.azimuths, s.grid, s.grid);
    methods_cli::DocTables doc;
    const std::vector<methods::IterRow> rows =
        methods::iteration_rows(maps, opt.setup, {80, 60, 45, 30, 20, 10}, opt.cap);
    report_parallax_iterations(rows, opt.cap, &doc);
    const methods::Sweep sw = methods::run_sweep(maps, opt.setup, {30, 15}, opt.budgets, methods::pm_compared());
    report_parallax_sweep(sw, &doc);
    {
        // rtl/parallax_iter.v: the fragments of the first map at 30 degrees from the slab's top, the cap and
        // threshold above, through the Verilated unit
        const methods::StepFormat fmt;
        const methods::FixedParallax fp = methods::make_fixed(maps[0], s.depth, fmt);
        std::vector<methods::IterJob> jobs;
        for (const methods::Fragment& f : methods::fragments(maps[0], s, 30)) {
            jobs.push_back(methods::job_for(fmt, s.depth, f.u0, f.v0, f.V.u, f.V.v, f.V.h, true,
                                            uint64_t(methods::to_fixed(s.thr(), fmt.f)), uint32_t(opt.cap)));
        }
        const methods::HeightFetch fetch = [&](int64_t u, int64_t v) { return fp.lookup(u, v); };
        report_parallax_rtl(methods::iter_throughput(jobs, fetch, {1, 2, 4, 8, 16}), jobs.size(), &doc);
    }
    if (!opt.out_dir.empty()) {
        plot_parallax_sweep(sw, opt.out_dir);
        render_parallax_pictures(maps, opt);
    }
    doc.write(opt.tables);
    return 0;
}

}  // namespace spec
