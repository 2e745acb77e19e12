// rom_check_main - runs tb_rom_check for two clocks: exit 0 when the images at the paths it was Verilated with
// pass the RTL's checks; a failing check stops the model ($fatal) with a non-zero exit (tests/config_checks.py).
#include <cstdio>
#include <memory>

#include "Vtb_rom_check.h"
#include "verilated.h"

int main(int argc, char** argv) {
    std::unique_ptr<VerilatedContext> ctx(new VerilatedContext);
    ctx->commandArgs(argc, argv);
    std::unique_ptr<Vtb_rom_check> top(new Vtb_rom_check(ctx.get()));
    for (int i = 0; i < 4; ++i) {
        top->clk = i & 1;
        top->eval();
    }
    top->final();
    std::printf("tb_rom_check: the images were accepted\n");
    return 0;
}
