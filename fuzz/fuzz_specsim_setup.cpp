// fuzz_specsim_setup - specsim's command line, in process: `specsim setup ...` with any arguments (the golden
// model, the host, rtl and --pixels through the Verilated spec_setup / spec_shader). Promise: exit code 0 or 2,
// nothing thrown past main, no undefined behaviour; --vcd and --out are dropped from the arguments.
// specsim's main.cpp is compiled with main renamed to specsim_main (fuzz/fuzz.cmake).
#include <string>
#include <vector>

#include "fuzz_input.h"

int specsim_main(int argc, char** argv);

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    fuzz::Input in(data, size);
    std::vector<std::string> tok = in.tokens(24);
    std::vector<std::string> args = {"specsim", "setup"};
    for (size_t i = 0; i < tok.size(); ++i) {
        if (tok[i] == "--vcd" || tok[i] == "--out") {
            ++i;   // and its value
            continue;
        }
        args.push_back(tok[i]);
    }
    std::vector<char*> argv;
    for (std::string& s : args) argv.push_back(&s[0]);
    argv.push_back(nullptr);
    const int rc = specsim_main(static_cast<int>(args.size()), argv.data());
    fuzz::check(rc == 0 || rc == 2, "specsim setup exit code " + std::to_string(rc));
    return 0;
}
