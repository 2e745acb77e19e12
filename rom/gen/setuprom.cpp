// setuprom - writes spec_setup's files for a configuration: the EFU tables (setup_efu.hex), the finish stage's
// exp2 table (setup_exp2.hex), the machine's microcode (setup_ucode.hex) and the parameter headers
// (setup_params.vh, setup_params.h). rom/gen/setup_format.h defines the configurations, docs/setup.md explains them.
//
//   setuprom [--out DIR] [--rom-path P] [--config ecp5|up5k] [--mul N] [--add N] [--efu N] [--misc N] [--idot N]
//            [--max-ii N] [--fp-m N] [--fp-e N]
//
// With no options it writes the ecp5 configuration (the files committed in rom/) into the current directory.
// --rom-path is the directory the headers name the hex files by (default "rom", as the committed files are used
// from the repository's root). Bad input: a one-line message on stderr and exit code 2; nothing is written.
#include <iostream>

#include "cli.h"
#include "setup_rom.h"

int main(int argc, char** argv) {
    using namespace spec;
    try {
        SetupFormat sf;
        std::string out = ".", rom_path = "rom";
        Args a(argc, argv, 1);
        while (!a.done()) {
            const std::string fl = a.flag();
            if (fl == "--help" || fl == "-h") {
                std::cout << "usage: setuprom [--out DIR] [--rom-path P] [--config ecp5|up5k] [--mul N] [--add N] [--efu N]\n"
                             "                [--misc N] [--idot N] [--max-ii N] [--fp-m N] [--fp-e N]\n"
                             "Writes setup_efu.hex, setup_exp2.hex, setup_ucode.hex, setup_params.vh and setup_params.h\n"
                             "into DIR (the configuration's tables, microcode and parameters; docs/setup.md).\n";
                return 0;
            }
            if (fl == "--out") {
                out = a.value(fl);
                continue;
            }
            if (fl == "--rom-path") {
                rom_path = a.value(fl);
                continue;
            }
            if (fl == "--config") {   // a named configuration; the options after it change it
                try {
                    sf = setup_format_config(a.value(fl));
                } catch (const std::invalid_argument& e) {
                    throw UsageError(e.what());
                }
                continue;
            }
            int* field = fl == "--mul"      ? &sf.mach.mul
                         : fl == "--add"    ? &sf.mach.add
                         : fl == "--efu"    ? &sf.mach.efu
                         : fl == "--misc"   ? &sf.mach.misc
                         : fl == "--idot"   ? &sf.mach.idot
                         : fl == "--max-ii" ? &sf.mach.max_ii
                         : fl == "--fp-m"   ? &sf.fp.m
                         : fl == "--fp-e"   ? &sf.fp.e
                                            : nullptr;
            if (!field) throw UsageError("unknown option " + fl);
            *field = static_cast<int>(parse_int(fl, a.value(fl), 0, 4096));
        }
        try {
            sf.validate();
        } catch (const std::invalid_argument& e) {
            throw UsageError(e.what());
        }
        try {
            write_setup_all(sf, out, rom_path);
        } catch (const std::runtime_error& e) {   // no schedule within --max-ii, a file that cannot be written
            throw UsageError(e.what());
        }
        return 0;
    } catch (const UsageError& e) {
        std::cerr << "setuprom: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "setuprom: internal error: " << spec::printable(e.what()) << "\n";
        return 3;
    }
}
