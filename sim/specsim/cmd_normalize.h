// cmd_normalize.h - specsim normalize: companion paper B measured (docs/methods.md). parse (argv -> options),
// compute (sim/methods/normalize_eval.h), report (report_normalize.cpp).
#pragma once

#include <string>
#include <vector>

#include "normalize_eval.h"

namespace spec {

namespace methods_cli {
class DocTables;
}

struct NormalizeOptions {
    int size = 512;
    int runs = 5;           // with --timing: runs of each mode
    bool timing = false;
    methods::NormBounds bounds;
    std::vector<std::string> scenes;  // empty: every built-in and coarse scene
    std::string out_dir, tables;
};
NormalizeOptions parse_normalize(int argc, char** argv);

// The paper's figures recomputed (eq. 1, 2, Fig. 2, 3, the stopping rule); out_dir: fig2.png, fig3.png.
void report_normalize_figures(const methods::NormBounds& b, const std::string& out_dir, methods_cli::DocTables* doc);
void report_normalize_rows(const std::vector<methods::NormRow>& rows, methods_cli::DocTables* doc);
void plot_normalize_cost(const std::vector<methods::NormRow>& rows, const std::string& out_dir);
void report_normalize_timing(const NormalizeOptions& opt);

int cmd_normalize(int argc, char** argv);

}  // namespace spec
