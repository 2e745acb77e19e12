// board_harness.cpp - which board model runs (see board_harness.h).
#include "board_harness.h"

#include "cli.h"

namespace spec {
namespace board {

std::vector<std::string> available_models() {
    std::vector<std::string> m;
    icebreaker_models(m);
    ulx3s_models(m);
    return m;
}

HarnessResult run_board(const HarnessOptions& o, VideoCapture& cap) {
    HarnessResult r;
    const bool ran = (o.board == "icebreaker") ? run_icebreaker(o, cap, r)
                     : (o.board == "ulx3s")    ? run_ulx3s(o, cap, r)
                                               : false;
    if (!ran) {
        throw UsageError("no model of '" + o.board + " " + o.mode + "' in this build (boardsim models; " +
                         "make board-sim builds them all)");
    }
    return r;
}

}  // namespace board
}  // namespace spec
