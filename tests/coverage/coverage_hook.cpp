// coverage_hook.cpp - the coverage build's (SPEC_COVERAGE=ON, make coverage) link-time hook: each Verilated
// model's final() is wrapped (-Wl,--wrap, see coverage.cmake) so that the model's line and toggle counts are
// written to $SPEC_COVERAGE_DIR (default "coverage") before its context goes away. scripts/coverage.py
// merges the files and prints the coverage per RTL file.
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <string>
#include <sys/stat.h>

#include "verilated.h"
#include "verilated_cov.h"

namespace {
void write_counts(void* self) {
    // Every model class derives from VerilatedModel alone: `this` is the base's address.
    VerilatedContext* ctx = static_cast<VerilatedModel*>(self)->contextp();
    static std::atomic<unsigned> serial{0};
    const char* env = std::getenv("SPEC_COVERAGE_DIR");
    const std::string dir = env && *env ? env : "coverage";
    ::mkdir(dir.c_str(), 0777);
    const std::string path = dir + "/cov-" + std::to_string(::getpid()) + "-" + std::to_string(serial++) + ".dat";
    ctx->coveragep()->write(path.c_str());
}
}  // namespace

#define SPEC_COV_WRAP(sym)                           \
    extern "C" void __real_##sym(void* self);        \
    extern "C" void __wrap_##sym(void* self) {       \
        write_counts(self);                          \
        __real_##sym(self);                          \
    }
#include "coverage_models.inc"
