// board_shaders.h - models of the shader passes for board_model's Shader hook.
#pragma once

#include <string>

#include "board_model.h"
#include "setup_format.h"
#include "span_host.h"
#include "spec_model.h"

namespace spec {
namespace board {

// The span's registers from the double-precision host (sim/host, docs/host.md) and the bit-exact core model
// m: what the pipeline would show with an exact setup. Not the RTL's setup (spec_shader has its own,
// fixed-point one); used to measure how much of the error is the split and how much the setup.
Shader host_shader(const Model& m, host::GammaRule rule);

// The RTL's shader pass (boards/common/board_shader.v: spec_shader), bit for bit: spec_setup's model
// (sim/setup/setup_model.h) in the setup format sf with the midpoint gamma rule, then the core's model m on
// its registers. m and the model of sf live as long as the shader.
Shader rtl_shader(const Model& m, const SetupFormat& sf = SetupFormat());

// The setup format a board's RTL is built with (boards/boards.cmake, boards/flow.py): "narrow" on the
// iCEBreaker (4 bits a channel; docs/boards.md), "default" on the ULX3S.
const char* board_setup_config(const std::string& board);

}  // namespace board
}  // namespace spec
