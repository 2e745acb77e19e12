// methods_usage.cpp - specsim --help's lines for the companion papers' commands.
#include "commands.h"
#include "methods_usage.h"

namespace spec {

const char* const kMethodsUsage = SPEC_HIGHLIGHT_USAGE SPEC_NORMALIZE_USAGE SPEC_PARALLAX_USAGE;

}  // namespace spec
