// board_harness.h - the Verilated board tops run with their primitives' simulation models (PLLs, I/O
// registers, DDR outputs; Verilator --timing), the oscillator driven from here, the output pins watched:
// the iCEBreaker's DVI Pmod pins sampled at each rising edge of its pixel clock pin, the ULX3S's four TMDS
// lanes recovered from the pins (bit times from the clock lane, 10 bits per character) and decoded.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "board_capture.h"

namespace spec {
namespace board {

struct HarnessOptions {
    std::string board;        // icebreaker | ulx3s
    std::string mode;         // 640x480 | 1280x720 (ulx3s) | 128x96 (test raster) | 128x96-race (ulx3s: the
                              // test raster racing the beam, 1280x720's architecture)
    int frames = 2;           // run until this many whole frames have been shown (the iCEBreaker: rendered,
                              // and the displayed frame after each)
    uint64_t limit_ps = 0;    // stop anyway after this much simulated time (0: from the mode, with margin)
};

struct HarnessResult {
    bool finished = false;            // the frames were shown within the time limit
    uint64_t sim_ps = 0;              // simulated time
    uint64_t time_slots = 0;          // model evaluations
    double wall_s = 0;
    double pll_mhz = 0;               // the pixel clock the board's PLL settings promise
    double design_mhz = 0;            // the design clock (the renderer's), from the same settings
    bool late = false;                // board_core's flag (a LED): a line was not rendered in time
    bool out_of_step = false;         // ulx3s: the serializer lost the pixel clock's phase (a LED)
    int render_clocks_max = 0;        // longest line render (racing the beam) or frame render (frame buffer),
                                      // clocks of the design clock
    int render_clocks_budget = 0;     // clocks per line (racing the beam; 0 with a frame buffer)
    bool frame_buffer = false;        // the design draws into a frame buffer (the iCEBreaker)
    // ulx3s: characters that were neither control nor data characters, data characters outside data enable,
    // and the largest running disparity seen on a lane (ones minus zeros since the last control period)
    uint64_t tmds_chars = 0, tmds_bad = 0;
    int tmds_max_disparity = 0;
    uint64_t nibbles_unequal = 0;     // ulx3s frame buffer modes: 8-bit channels that are not 4 bits x 17
    // icebreaker: the least time from a change of the Pmod's data pins to the next rising edge of its pixel
    // clock pin (set-up) and from such an edge to the next change (hold), ps; -1 where not measured
    double pin_setup_ps = -1, pin_hold_ps = -1;
};

// The boards and modes this build has models for ("icebreaker 128x96", ...).
std::vector<std::string> available_models();
// Runs the model; samples go to cap. Throws UsageError if this build has no model for the board and mode.
HarnessResult run_board(const HarnessOptions& o, VideoCapture& cap);

// Implemented per board (harness_icebreaker.cpp, harness_ulx3s.cpp); false if no model for the mode.
bool run_icebreaker(const HarnessOptions& o, VideoCapture& cap, HarnessResult& r);
bool run_ulx3s(const HarnessOptions& o, VideoCapture& cap, HarnessResult& r);
void icebreaker_models(std::vector<std::string>& out);
void ulx3s_models(std::vector<std::string>& out);

}  // namespace board
}  // namespace spec
