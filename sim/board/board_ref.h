// board_ref.h - the reference designs' scene in double precision (docs/boards.md, "Accuracy"): per pixel
// the exact sphere normal, Lambert and Blinn-Phong with exact cos^n, the light of frame f unquantized.
#pragma once

#include <vector>

#include "board_model.h"
#include "board_scene.h"
#include "image.h"

namespace spec {
namespace board {

// Lines y0 .. y1 - 1 (the rest background) rounded to out_bits per channel, and a coverage mask
// (1 where a sphere is). Coverage is the hardware's: pixel centre inside the circle (exact in integers).
Frame ref_frame(const BoardScene& s, unsigned f, int out_bits, int y0, int y1, std::vector<uint8_t>* covered);

// A frame at out_bits as an 8-bit image (each channel scaled to 0..255: v * 255 / (2^out_bits - 1),
// rounded; 4 bits: v * 17).
render::Image to_image(const Frame& f);

}  // namespace board
}  // namespace spec
