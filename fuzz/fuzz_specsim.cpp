// fuzz_specsim - specsim's command line, in process: `specsim span ...` with any arguments (all four
// models, rtl and stream through the Verilated cores). Promise: exit code 0 or 2, nothing thrown past main,
// no undefined behaviour; --vcd and --out are dropped from the arguments (no files written).
// specsim's main.cpp is compiled with main renamed to specsim_main (fuzz/fuzz.cmake).
#include <string>
#include <vector>

#include "fuzz_input.h"

int specsim_main(int argc, char** argv);

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    fuzz::Input in(data, size);
    std::vector<std::string> tok = in.tokens(24);
    std::vector<std::string> args = {"specsim", "span"};
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
    fuzz::check(rc == 0 || rc == 2, "specsim span exit code " + std::to_string(rc));
    return 0;
}
