// board_model.h - the bit-exact C++ model of the reference designs' pipeline (boards/common/), line by line:
// the span finder (sphere_spans.v), the light (light_gen.v), the shader passes (spec_shader), the colour
// (compose.v) and the line buffer with its shared end pixels. The board-sim compares the Verilated board
// tops with it bit for bit.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "board_quant.h"
#include "board_scene.h"

namespace spec {
namespace board {

// floor(sqrt(x)), exact
uint64_t isqrt(uint64_t x);

// One sub-span from sphere_spans.v: pixels x0 .. x0 + l of sphere obj, with the sphere's normal at both
// ends as (x, y, z) in half-pixel units times 2^zf (|n| = 2r 2^zf up to the root's rounding).
struct SubSpan {
    unsigned obj = 0;
    int x0 = 0;
    unsigned l = 0;
    std::array<int32_t, 3> n1{}, n2{};
};
// The sub-spans of scanline y, in the order sphere_spans.v sends them.
std::vector<SubSpan> line_spans(const BoardScene& s, int y);

// light_gen.v: L and H of frame f (Q1.14).
struct LightQ {
    std::array<int32_t, 3> l{}, h{};
};
LightQ light_q(const Quant& q, unsigned frame);
// light_gen.v's table (LIGHT_FILE, 256 words): word i (0..64) = the quarter wave's word i times sin E, word
// 128 + i times sin(E/2), each as light_q rounds it (half up, / 2^14); the other words 0.
std::vector<uint32_t> light_table(const Quant& q);

// compose.v: a pixel's channels at out_bits from its diffuse and specular terms (UQ0.16).
std::array<uint32_t, 3> compose(const ObjQuant& o, uint32_t dif, uint32_t spc, int out_bits);
// The background at out_bits per channel, as the line buffer clears to it.
std::array<uint32_t, 3> background(const Quant& q, int out_bits);

// A span through the shader: end normals as sphere_spans.v gives them, one light vector for both ends
// (H for the specular pass, L for the diffuse pass, Q1.14), exponent, strength (UQ1.15, spec_shader's), l
// intervals; returns the l + 1 pixels (UQ0.16).
struct ShadeIn {
    std::array<int32_t, 3> n1{}, n2{};
    std::array<int32_t, 3> light{};
    unsigned n = 0;
    uint32_t strength = 0;
    unsigned l = 0;
    int zf = 5;
};
using Shader = std::function<std::vector<uint32_t>(const ShadeIn&)>;

// A frame: rgb per pixel at out_bits per channel, row-major.
struct Frame {
    int w = 0, h = 0, out_bits = 8;
    std::vector<std::array<uint32_t, 3>> px;
};
// Lines y0 .. y1 - 1 of frame f (the rest background). Every sub-span's two passes go through shader.
Frame model_frame(const BoardScene& s, const Shader& shader, unsigned f, int out_bits, int y0, int y1);

}  // namespace board
}  // namespace spec
