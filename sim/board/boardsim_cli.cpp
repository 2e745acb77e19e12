// boardsim_cli.cpp - argv -> options for boardsim's commands (see boardsim_cli.h).
#include "boardsim_cli.h"

#include <filesystem>

#include "board_scene.h"
#include "cli.h"

namespace spec {
namespace board {

const char* usage() {
    return "usage: boardsim <command> [options]   (docs/boards.md)\n"
           "\n"
           "  run     a board's Verilated top level, with its PLL / I/O / DDR simulation models, for whole frames;\n"
           "          frames from the pins (TMDS decoded on the ulx3s) compared bit for bit with the C++ model of\n"
           "          the pipeline and against a double-precision rendering; video timing against the standard.\n"
           "          Exit 0 when every check passes, 1 when one fails.\n"
           "          --board icebreaker|ulx3s  --mode 640x480|1280x720 (ulx3s)|128x96 (test raster; default 640x480)\n"
           "                  |128x96-race (ulx3s: the test raster racing the beam, as 1280x720 does)\n"
           "          --frames N (1..16, default 2)  --out-dir DIR (frame PNGs, error maps, summary.json)  --quiet\n"
           "  split   how much splitting spans at K points per chord helps: the largest error per sphere against\n"
           "          double precision, and the sub-spans per line, for each K\n"
           "          --mode M  --k K,K,... (1..64, default 1,4,8,16,32)  --shader host|rtl (default host)\n"
           "          --json FILE  the table as JSON too\n"
           "  gen     the tables the RTL reads (boards/common/gen/): --out-dir DIR [--k K,K,...]\n"
           "  models  the board models this build has\n";
}

namespace {

std::vector<int> parse_ks(const std::string& flag, const std::string& v) {
    std::vector<int> ks;
    size_t pos = 0;
    while (true) {
        const size_t comma = v.find(',', pos);
        ks.push_back(int(parse_int(flag, v.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos),
                                   1, 64)));
        if (comma == std::string::npos) break;
        pos = comma + 1;
    }
    return ks;
}

}  // namespace

GenOptions parse_gen(int argc, char** argv) {
    GenOptions o;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string f = a.flag();
        if (f == "--out-dir") o.out_dir = a.value(f);
        else if (f == "--k") o.ks = parse_ks(f, a.value(f));
        else throw UsageError("gen: unknown option " + f);
    }
    if (o.out_dir.empty()) throw UsageError("gen: --out-dir is required");
    if (!std::filesystem::is_directory(o.out_dir)) throw UsageError("gen: --out-dir '" + o.out_dir + "' is not a directory");
    return o;
}

RunOptions parse_run(int argc, char** argv) {
    RunOptions o;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string f = a.flag();
        if (f == "--board") o.board = a.value(f);
        else if (f == "--mode") o.mode = a.value(f);
        else if (f == "--frames") o.frames = int(parse_int(f, a.value(f), 1, 16));
        else if (f == "--out-dir") o.out_dir = a.value(f);
        else if (f == "--quiet") o.quiet = true;
        else throw UsageError("run: unknown option " + f);
    }
    if (o.board != "icebreaker" && o.board != "ulx3s") {
        throw UsageError("run: --board must be icebreaker or ulx3s" + (o.board.empty() ? std::string() : ", not '" + o.board + "'"));
    }
    if (o.mode.empty()) o.mode = "640x480";
    if (!o.out_dir.empty() && !std::filesystem::is_directory(o.out_dir)) {
        throw UsageError("run: --out-dir '" + o.out_dir + "' is not a directory");
    }
    const bool race_test = (o.mode == "128x96-race");
    if (race_test && o.board != "ulx3s") throw UsageError("run: 128x96-race is a ulx3s mode");
    video_mode(race_test ? "128x96" : o.mode);   // throws for an unknown mode
    if (o.board == "icebreaker" && o.mode == "1280x720") throw UsageError("run: the icebreaker design has no 1280x720 mode");
    // every design splits chords at 8 points: racing the beam (the ULX3S at 1280x720 and 128x96-race) too, where
    // the multiplier setup's II and latency leave room in a line's clocks for 8's sub-spans (docs/boards.md)
    o.split_k = 8;
    return o;
}

SplitOptions parse_split(int argc, char** argv) {
    SplitOptions o;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string f = a.flag();
        if (f == "--mode") o.mode = a.value(f);
        else if (f == "--k") o.ks = parse_ks(f, a.value(f));
        else if (f == "--shader") o.shader = a.value(f);
        else if (f == "--json") o.json = a.value(f);
        else throw UsageError("split: unknown option " + f);
    }
    video_mode(o.mode);
    if (o.shader != "host" && o.shader != "rtl") throw UsageError("split: --shader must be host or rtl");
    return o;
}

}  // namespace board
}  // namespace spec
