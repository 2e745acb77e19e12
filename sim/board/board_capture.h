// board_capture.h - what a monitor would see: the pixel stream at a board's output pins (one sample per pixel
// clock), cut into frames, and its raster measured against the video standard (docs/boards.md,
// "What the board-sim checks").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "board_model.h"
#include "board_scene.h"

namespace spec {
namespace board {

struct PixelSample {
    uint64_t t_ps = 0;        // time of the sampling clock edge
    uint8_t rgb[3] = {0, 0, 0};
    bool hs = false, vs = false, de = false;   // pin levels
    bool tag = false;         // a status pin sampled with the pixel (the iCEBreaker: its rendered-frame LED)
};

// The raster measured from the samples: every line and every frame must show the same figures.
struct MeasuredTiming {
    int h_active = 0, h_fp = 0, h_sync = 0, h_bp = 0, h_total = 0;
    int v_active = 0, v_fp = 0, v_sync = 0, v_bp = 0, v_total = 0;
    bool h_pos = false, v_pos = false;   // sync polarity: the level that lasts shorter
    double pixel_mhz = 0;                // from the sample times
    double frame_us = 0;                 // vsync leading edge to the next
    double refresh_hz = 0;
    std::vector<std::string> problems;   // inconsistencies (a line unlike the others, ...)
};

class VideoCapture {
public:
    explicit VideoCapture(int out_bits) : out_bits_(out_bits) {}
    void push(const PixelSample& s);
    // Changes of the vsync pin seen (two per pulse: n frames are whole once 2n + 1 have been seen).
    int vsync_changes() const { return vs_edges_; }
    // Frames 0 .. n-1 (the active lines after each vsync, in order) as out_bits-per-channel frames.
    // Throws std::runtime_error when the samples do not hold n whole frames.
    std::vector<Frame> frames(int n) const;
    // Every whole frame captured, and the tag of each frame's first active pixel.
    std::vector<Frame> all_frames(std::vector<bool>* tags) const;
    MeasuredTiming measure() const;
    size_t samples() const { return s_.size(); }

private:
    int out_bits_;
    std::vector<PixelSample> s_;
    int vs_edges_ = 0;
    bool vs_prev_ = false, vs_init_ = false;
};

// The measured raster against the mode's figures: one line per quantity, "ok" or the difference.
struct TimingCheck {
    bool ok = true;
    std::vector<std::string> rows;   // "h_active 640 640 ok" ...
};
TimingCheck check_timing(const MeasuredTiming& m, const VideoMode& mode, double pll_mhz);

}  // namespace board
}  // namespace spec
