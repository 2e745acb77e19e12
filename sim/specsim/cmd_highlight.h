// cmd_highlight.h - specsim highlight: companion paper A measured (docs/methods.md). parse (argv -> options),
// compute (sim/methods/highlight_eval.h), report (report_highlight.cpp).
#pragma once

#include <string>
#include <vector>

#include "highlight_eval.h"

namespace spec {

namespace methods_cli {
class DocTables;
}

struct HighlightOptions {
    int size = 512;
    render::SpecModel model = render::SpecModel::rtl;
    std::vector<std::string> scenes;  // empty: every built-in and coarse scene
    unsigned coarse_n = 1000;         // extra rows: the coarse scenes with every exponent n (0: none)
    uint64_t samples = 200000;
    std::string out_dir, tables;
};
HighlightOptions parse_highlight(int argc, char** argv);

void report_highlight_scenes(const std::vector<methods::SceneEval>& ev, bool rtl, methods_cli::DocTables* doc);
void report_highlight_synthetic(const std::vector<methods::SyntheticRow>& rows, const std::vector<methods::OpRow>& ops,
                                methods_cli::DocTables* doc);
void write_highlight_picture(const methods::SceneEval& ev, const std::string& out_dir);

int cmd_highlight(int argc, char** argv);

}  // namespace spec
