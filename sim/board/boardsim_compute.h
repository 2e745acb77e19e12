// boardsim_compute.h - what boardsim's commands compute (library functions the tests call too).
#pragma once

#include <string>
#include <vector>

#include "board_capture.h"
#include "board_harness.h"
#include "board_model.h"
#include "boardsim_cli.h"
#include "image.h"
#include "stats.h"

namespace spec {
namespace board {

struct FrameReport {
    unsigned frame = 0;
    uint64_t differing = 0;          // pixels unlike the C++ model's (0: bit for bit)
    int first_x = -1, first_y = -1;  // the first of them
    render::ImageStats vs_ref;       // the board's frame (8 bits a channel) against double precision
    render::ImageStats model8_vs_ref;  // the model at 8 bits a channel against double precision (icebreaker:
                                       // the pipeline before the Pmod's 4 bits; ulx3s: the same as vs_ref)
    render::Image board, model, ref;   // 8-bit images of the three
};

struct RunReport {
    RunOptions opt;
    VideoMode mode;
    int out_bits = 8;
    std::string setup_config;   // the setup configuration of the board's RTL and of its model (board_setup_config)
    HarnessResult harness;
    MeasuredTiming measured;
    TimingCheck timing;
    std::vector<FrameReport> frames;
    std::vector<std::string> failures;   // empty: every check passed
};

RunReport run_board_sim(const RunOptions& o);

struct SplitRow {
    int k = 0;
    double spans_per_line = 0;     // sub-spans per chord-carrying line, mean over the frame's lines
    int spans_max_line = 0;        // most sub-spans on one line
    std::vector<int> max_err;      // per sphere: largest channel error against double precision, levels
    std::vector<double> mean_err;  // per sphere: mean over its pixels and channels
    int max_all = 0;
    double psnr = 0;               // worst over the frames
};
std::vector<SplitRow> split_study(const SplitOptions& o);

}  // namespace board
}  // namespace spec
