// board_shaders.h - models of the shader passes for board_model's Shader hook.
#pragma once

#include <string>

#include "board_model.h"
#include "setup_config.h"
#include "span_host.h"
#include "spec_model.h"

namespace spec {
namespace board {

// The span's registers from the double-precision host (sim/host, docs/host.md) and the bit-exact core model
// m: what the pipeline would show with an exact setup. Not the RTL's setup (spec_shader has its own,
// fixed-point one); used to measure how much of the error is the split and how much the setup.
Shader host_shader(const Model& m, host::GammaRule rule);

// The span-ends beat boards/common/board_shader.v makes of a shader pass: N1, N2, the light vector as H1 and H2,
// the midpoint gamma rule.
SetupInput shade_beat(const ShadeIn& in);

// The RTL's shader pass (boards/common/board_shader.v: spec_shader), bit for bit: the setup model of
// configuration c (sim/setup/setup_config.h) on shade_beat, then the core's model m on its registers. m must
// live as long as the shader.
Shader rtl_shader(const Model& m, SetupConfig c);

// The setup configuration a board design is built with (boards/boards.cmake, boards/flow.py): up5k where the
// design draws into a frame buffer (the iCEBreaker; the ULX3S at 640 x 480 and its 128 x 96 test raster: the
// multiplier setup does not fit beside the buffer, docs/boards.md), ecp5 where it races the beam (the ULX3S at
// 1280 x 720 and its 128x96-race test raster).
SetupConfig board_setup_config(const std::string& board, const std::string& mode);

// The beats a board's shader gets for frame f of scene s, in the order the design sends them (the diffuse and
// the specular pass of each sub-span, line by line).
std::vector<SetupInput> board_beats(const BoardScene& s, unsigned f);

}  // namespace board
}  // namespace spec
