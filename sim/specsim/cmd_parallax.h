// cmd_parallax.h - specsim parallax: companion paper C measured (docs/methods.md). parse (argv -> options),
// compute (sim/methods/parallax_eval.h, parallax_rtl.h), report (report_parallax.cpp).
#pragma once

#include <string>
#include <vector>

#include "parallax_eval.h"
#include "parallax_rtl.h"

namespace spec {

extern const char* const kParallaxUsage;

struct ParallaxOptions {
    std::vector<std::string> maps;  // empty: all
    methods::ParallaxSetup setup;
    int cap = 16;                   // the iteration table's cap
    std::vector<int> budgets{1, 2, 3, 4, 6, 8, 12, 16, 24, 32};
    std::string out_dir, tables;
};
ParallaxOptions parse_parallax(int argc, char** argv);

// The report: tables on stdout (and into `doc`), plots and pictures into opt.out_dir.
namespace methods_cli {
class DocTables;
}
void report_parallax_iterations(const std::vector<methods::IterRow>& rows, int cap, methods_cli::DocTables* doc);
void report_parallax_sweep(const methods::Sweep& sw, methods_cli::DocTables* doc);
void report_parallax_rtl(const std::vector<methods::ThroughputCell>& cells, uint64_t fragments, methods_cli::DocTables* doc);
void plot_parallax_sweep(const methods::Sweep& sw, const std::string& out_dir);
void render_parallax_pictures(const std::vector<methods::HeightMap>& maps, const ParallaxOptions& opt);

int cmd_parallax(int argc, char** argv);

}  // namespace spec
