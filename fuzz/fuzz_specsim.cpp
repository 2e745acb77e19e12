// fuzz_specsim - specsim's command line, in process: `specsim span ...` with any arguments (all four
// models, rtl and stream through the Verilated cores). Promises:
//   - valid input (parse_span accepts it, or --help is asked) exits 0; bad input (parse_span throws
//     UsageError) exits 2; nothing else, so an internal error (exit 3) or a crash fails;
//   - parse_span throws nothing but UsageError (anything else escapes and aborts);
//   - on valid input the cores agree: --model rtl and --model stream give the pixels --model golden gives
//     (span_pixels, the compute step behind the CSV specsim prints).
// --vcd and --out are dropped from the arguments (no files written). specsim's main.cpp is compiled with main
// renamed to specsim_main (fuzz/fuzz.cmake).
#include <exception>
#include <string>
#include <vector>

#include "cli.h"
#include "cmd_span.h"
#include "fuzz_input.h"

int specsim_main(int argc, char** argv);

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    fuzz::Input in(data, size);
    std::vector<std::string> tok = in.tokens(24);
    std::vector<std::string> args = {"specsim", "span"};
    bool help = false;
    for (size_t i = 0; i < tok.size(); ++i) {
        if (tok[i] == "--vcd" || tok[i] == "--out") {
            ++i;   // and its value
            continue;
        }
        help = help || tok[i] == "--help" || tok[i] == "-h";
        args.push_back(tok[i]);
    }
    std::vector<char*> argv;
    for (std::string& s : args) argv.push_back(&s[0]);
    argv.push_back(nullptr);
    const int argc = static_cast<int>(args.size());

    bool valid = true;
    spec::SpanOptions o;
    try {
        o = spec::parse_span(argc, argv.data());
    } catch (const spec::UsageError& e) {
        valid = false;
        fuzz::one_line(e.what());
    }
    const int rc = specsim_main(argc, argv.data());
    if (help) fuzz::check(rc == 0, "specsim span --help exit code " + std::to_string(rc));
    else if (valid) fuzz::check(rc == 0, "specsim span on valid input: exit code " + std::to_string(rc));
    else fuzz::check(rc == 2, "specsim span on bad input: exit code " + std::to_string(rc));
    if (valid && !help) {
        auto pixels = [&](const char* model) {
            spec::SpanOptions x = o;
            x.model = model;
            x.vcd = "";
            try {
                return spec::span_pixels(x);
            } catch (const std::exception& e) {
                fuzz::fail(std::string("span_pixels --model ") + model + " on valid input: internal error: " + e.what());
            }
        };
        const std::vector<uint32_t> gold = pixels("golden");
        fuzz::check(gold.size() == o.regs.len + 1u, "golden: wrong pixel count");
        fuzz::check(pixels("rtl") == gold, "--model rtl differs from --model golden");
        fuzz::check(pixels("stream") == gold, "--model stream differs from --model golden");
    }
    return 0;
}
