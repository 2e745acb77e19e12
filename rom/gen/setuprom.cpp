// setuprom - writes spec_setup's tables and parameter headers: setup_log2.hex, setup_exp2.hex,
// setup_params.vh and setup_params.h (rom/gen/setup_format.h, docs/setup.md).
//
//   setuprom [--out DIR] [--config default|narrow] [--f N] [--iters N] [--zf N] [--lf N] [--ef N] [--tb N] [--rb N] [--gain-frac N]
//            [--flat-log2 N] [--opp-tau-log2 N]
//
// With no options it writes the default files (the ones committed in rom/) into the current directory.
// Bad input: a one-line message on stderr and exit code 2; nothing is written.
#include <iostream>

#include "cli.h"
#include "setup_rom.h"

int main(int argc, char** argv) {
    using namespace spec;
    try {
        SetupFormat sf;
        std::string out = ".";
        Args a(argc, argv, 1);
        while (!a.done()) {
            const std::string fl = a.flag();
            if (fl == "--help" || fl == "-h") {
                std::cout << "usage: setuprom [--out DIR] [--config default|narrow] [--f N] [--iters N] [--zf N] [--lf N] [--ef N] [--tb N] [--rb N]\n"
                             "                [--gain-frac N] [--flat-log2 N] [--opp-tau-log2 N]\n"
                             "Writes setup_log2.hex, setup_exp2.hex, setup_params.vh and setup_params.h into DIR.\n";
                return 0;
            }
            if (fl == "--out") {
                out = a.value(fl);
                continue;
            }
            if (fl == "--config") {   // a named format (setup_format.h); the options after it change it
                try {
                    sf = setup_format_config(a.value(fl));
                } catch (const std::invalid_argument& e) {
                    throw UsageError(e.what());
                }
                continue;
            }
            int* field = fl == "--f"           ? &sf.f
                         : fl == "--iters"     ? &sf.iters
                         : fl == "--zf"        ? &sf.zf
                         : fl == "--lf"        ? &sf.lf
                         : fl == "--ef"        ? &sf.ef
                         : fl == "--tb"        ? &sf.tb
                         : fl == "--rb"        ? &sf.rb
                         : fl == "--gain-frac" ? &sf.gain_frac
                         : fl == "--flat-log2" ? &sf.flat_log2
                         : fl == "--opp-tau-log2" ? &sf.opp_tau_log2
                                               : nullptr;
            if (!field) throw UsageError("unknown option " + fl);
            *field = static_cast<int>(parse_int(fl, a.value(fl), -64, 64));
        }
        try {
            sf.validate();
        } catch (const std::invalid_argument& e) {
            throw UsageError(e.what());
        }
        write_setup_all(sf, out);
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "setuprom: " << spec::printable(e.what()) << "\n";
        return 2;
    }
}
