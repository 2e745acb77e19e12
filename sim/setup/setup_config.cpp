#include "setup_config.h"

#include <stdexcept>

namespace spec {

const char* setup_config_name(SetupConfig c) { return c == SetupConfig::up5k ? "up5k" : "ecp5"; }

SetupConfig parse_setup_config(const std::string& s) {
    if (s == "ecp5") return SetupConfig::ecp5;
    if (s == "up5k") return SetupConfig::up5k;
    throw std::invalid_argument("unknown configuration '" + s + "' (ecp5, up5k)");
}

Format shader_core_format(SetupConfig c) { return config_format(c == SetupConfig::up5k ? "up5k" : "default"); }

CheckOptions setup_config_check(SetupConfig c) {
    CheckOptions o;
    if (c == SetupConfig::up5k) {
        o.setup_share = 0.02;
        o.eps = 1.0 / (1 << 13);
    }
    return o;
}

ConfigSetupModel::ConfigSetupModel(SetupConfig c) : c_(c), sf_(setup_format_config("ecp5")) {
    if (c == SetupConfig::ecp5) {
        mul_ = std::make_unique<SetupModel>(sf_, Format());
    } else {
        const SmallSetupFormat ss;
        if (ss.vec_w != sf_.vec_w || ss.vec_frac != sf_.vec_frac || ss.str_w != sf_.str_w || ss.str_frac != sf_.str_frac)
            throw std::logic_error("the setups' beat formats differ");
        small_ = std::make_unique<SmallSetupModel>(ss, Format());
    }
}

SetupResult ConfigSetupModel::run(const SetupInput& in) const { return mul_ ? mul_->run(in) : small_->run(in); }

}  // namespace spec
