// rom_check_main - runs tb_rom_check for two clocks on the one Verilated harness (sim/rtl/harness.h): exit 0
// when the images at the paths it was Verilated with pass the RTL's checks; a failing check stops the model
// ($fatal) with a non-zero exit (tests/config_checks.py).
#include <cstdio>

#include "Vtb_rom_check.h"
#include "harness.h"

int main(int argc, char** argv) {
    spec::Harness<Vtb_rom_check> h;   // the checks run in the model's initial blocks, at its first eval
    h.context().commandArgs(argc, argv);
    h.ticks(2);
    std::printf("tb_rom_check: the images were accepted\n");
    return 0;
}
