// setup_config.h - the shader's two configurations (docs/setup.md) and the bit-exact model of each one's setup.
// A configuration is the setup's architecture and format, spec_stream's tables and the back end together:
//   ecp5  spec_setup, the multiplier setup (rom/gen/setup_format.h, "ecp5"), with spec_stream in its default
//         configuration: a span every II clocks (rom/setup_params.vh)
//   up5k  spec_setup_small, the small CORDIC setup (rom/gen/setup_small_format.h), with spec_stream_seq and
//         spec_stream's up5k tables: one span at a time, for the iCE40 UP5K, where the multiplier setup does not fit
#pragma once

#include <memory>
#include <string>

#include "setup_eval.h"
#include "setup_model.h"
#include "setup_small_model.h"
#include "spec_format.h"

namespace spec {

enum class SetupConfig { ecp5, up5k };
const char* setup_config_name(SetupConfig c);
// Throws std::invalid_argument (one line) for anything but "ecp5" or "up5k".
SetupConfig parse_setup_config(const std::string& s);
// spec_stream's format in the configuration (the core's bit-exact model for its pixels).
Format shader_core_format(SetupConfig c);
// The accuracy check of the configuration (sim/setup/setup_eval.h): ecp5 issue 13's (the setup's share of the
// bound 0.2 % of C, backward error 2^-20 rad for ill-conditioned spans); up5k what its 20-bit CORDIC coordinates
// support: 2 % of C, backward error 2^-13 rad (two codes of the Q1.14 input) (docs/setup.md, "Accuracy").
CheckOptions setup_config_check(SetupConfig c);

// The configuration's setup, bit for bit: SetupModel (ecp5) or SmallSetupModel (up5k). Both write the default
// core format's descriptor (rom/spec_params.vh) and read the same beat (format(): vec_w, vec_frac, str_w,
// str_frac).
class ConfigSetupModel {
public:
    explicit ConfigSetupModel(SetupConfig c);
    SetupConfig config() const { return c_; }
    SetupResult run(const SetupInput& in) const;
    const SetupFormat& format() const { return sf_; }
    const SetupModel* multiplier() const { return mul_.get(); }   // null in up5k
    const SmallSetupModel* small() const { return small_.get(); } // null in ecp5

private:
    SetupConfig c_;
    SetupFormat sf_;
    std::unique_ptr<SetupModel> mul_;
    std::unique_ptr<SmallSetupModel> small_;
};

}  // namespace spec
