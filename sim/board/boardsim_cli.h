// boardsim_cli.h - boardsim's commands and their options (parse: argv -> options; bad input throws
// spec::UsageError with a one-line message).
#pragma once

#include <string>
#include <vector>

namespace spec {
namespace board {

struct GenOptions {
    std::string out_dir;
    std::vector<int> ks{8, 16, 32};
};

struct RunOptions {
    std::string board;             // icebreaker | ulx3s
    std::string mode;              // default: 640x480
    int frames = 2;                // 1..16
    int split_k = 0;               // the board's: icebreaker 8, ulx3s 32
    std::string out_dir;           // PNGs and summary.json here ("" = none)
    bool quiet = false;
};

struct SplitOptions {
    std::string mode = "640x480";
    std::vector<int> ks{1, 4, 8, 16, 32};
    std::vector<unsigned> frames{0, 32, 64, 96, 128, 160, 192, 224};
    std::string shader = "host";   // host (double-precision setup, bit-exact core) | rtl (the RTL's pass)
    std::string json;              // also write the table as JSON here
};

const char* usage();
GenOptions parse_gen(int argc, char** argv);
RunOptions parse_run(int argc, char** argv);
SplitOptions parse_split(int argc, char** argv);

}  // namespace board
}  // namespace spec
