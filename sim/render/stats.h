// stats.h - a rendered image against the reference image, in 8-bit levels.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image.h"

namespace spec {
namespace render {

struct ImageStats {
    int max_abs = 0;              // largest |a - ref| over every pixel and channel, levels of 255
    int worst_x = -1, worst_y = -1;
    double mean_abs = 0;          // mean |a - ref| over the channels of the pixels objects cover
    double psnr = 0;              // dB over the whole image (peak 255); infinity when equal
    uint64_t over_4 = 0;          // pixels with some channel more than 4 levels off
    uint64_t differing = 0;       // pixels with any difference
    uint64_t covered = 0;         // pixels objects cover
};

// a and ref of the same size; covered: 1 per object pixel (the mean is over those).
ImageStats compare(const Image& a, const Image& ref, const std::vector<uint8_t>& covered);

}  // namespace render
}  // namespace spec
