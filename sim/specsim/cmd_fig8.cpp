// cmd_fig8.cpp - specsim fig8: the recomputed Fig. 8 table and q(n), a(n) for the Fig. 10 rule. The numbers
// are the analysis library's (fig8(), fig10_errors(): sim/model/analysis.h); this file parses and prints.
#include <iostream>
#include <string>

#include "analysis.h"
#include "cli.h"
#include "cmd_span.h"
#include "commands.h"

namespace spec {

const char* const kFig8Usage =
    "  fig8     the recomputed Fig. 8 table and q(n), a(n) for the Fig. 10 rule (--all: every n)\n"
    "           --mode tuned: the same with the minimax scale (docs/tuned.md); --mode pow: pow mode has no\n"
    "           tables k: its approximation's errors per BRDF range (docs/pow.md)\n";

namespace {
struct Fig8Options {
    bool all = false;
    Mode mode = Mode::patent;
};

Fig8Options parse_fig8(int argc, char** argv) {
    Fig8Options o;
    Args a(argc, argv, 2);
    while (!a.done()) {
        std::string fl = a.flag();
        if (fl == "--all") o.all = true;
        else if (fl == "--mode") o.mode = parse_mode_flag(fl, a.value(fl));
        else throw UsageError("fig8: unknown option " + fl);
    }
    return o;
}
}  // namespace

int cmd_fig8(int argc, char** argv) {
    const Fig8Options o = parse_fig8(argc, argv);
    std::cout << fig8_report(o.all, o.mode);
    return 0;
}

}  // namespace spec
