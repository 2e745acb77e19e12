// board_quant.h - the scene's constants as the RTL holds them (docs/boards.md, "Formats").
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "board_scene.h"

namespace spec {
namespace board {

struct ObjQuant {
    uint32_t ka = 0;        // UQ0.16 (compose)
    uint32_t cd[3] = {};    // UQ1.8, 256 = 1.0 (compose)
    uint32_t kd = 0;        // diffuse strength kd Is, UQ1.15 (spec_shader's Is*ks field, the diffuse pass)
    uint32_t ks = 0;        // specular strength ks Is, UQ1.15 (the specular pass)
    unsigned n = 0;
};

struct Quant {
    std::vector<ObjQuant> obj;
    std::vector<uint32_t> quarter_sin;   // 65 words, round(16384 sin(pi i / 128))
    int32_t sin_e = 0, cos_e = 0;        // Q1.14 of the light's elevation from the viewing axis
    int32_t sin_half_e = 0, cos_half_e = 0;
    uint32_t bg8[3] = {};                // background, 8 bits per channel
};

inline uint32_t q16(double v) {   // round(v 2^16), at most 65535
    const double r = std::floor(v * 65536.0 + 0.5);
    return r >= 65535.0 ? 65535u : r <= 0 ? 0u : uint32_t(r);
}
inline int32_t q14(double v) { return int32_t(std::lround(v * 16384.0)); }
inline uint32_t q15(double v) { return uint32_t(std::lround(v * 32768.0)); }   // UQ1.15, v in [0, 2)

Quant quantize(const BoardScene& s);

}  // namespace board
}  // namespace spec
