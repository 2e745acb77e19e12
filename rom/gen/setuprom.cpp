// setuprom - writes a setup configuration's files (docs/setup.md explains them):
//   ecp5 (the multiplier setup, spec_setup; rom/gen/setup_format.h): the EFU tables (setup_efu.hex), the finish
//     stage's exp2 table (setup_exp2.hex), the machine's microcode (setup_ucode.hex) and the parameter headers
//     (setup_params.vh, setup_params.h); --format narrow and the unit counts change it (the synthesis rows' variants)
//   up5k (the small CORDIC setup, spec_setup_small; rom/gen/setup_small_format.h): setup_small_log2.hex,
//     setup_small_exp2.hex, setup_small_params.vh, setup_small_params.h
//
//   setuprom [--out DIR] [--rom-path P] [--config ecp5|up5k] [--format ecp5|narrow] [--mul N] [--add N] [--efu N]
//            [--misc N] [--idot N] [--max-ii N] [--fp-m N] [--fp-e N]           (ecp5)
//            [--f N] [--iters N] [--zf N] [--lf N] [--ef N] [--tb N] [--rb N] [--gain-frac N] [--flat-log2 N]
//            [--opp-tau-log2 N]                                                   (up5k: the formal jobs' widths)
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
        SmallSetupFormat ss;
        bool small = false, machine_options = false, small_options = false;
        std::string out = ".", rom_path = "rom";
        Args a(argc, argv, 1);
        while (!a.done()) {
            const std::string fl = a.flag();
            if (fl == "--help" || fl == "-h") {
                std::cout << "usage: setuprom [--out DIR] [--rom-path P] [--config ecp5|up5k] [--format ecp5|narrow]\n"
                             "                [--mul N] [--add N] [--efu N] [--misc N] [--idot N] [--max-ii N] [--fp-m N] [--fp-e N]\n"
                             "                [--f N] [--iters N] [--zf N] [--lf N] [--ef N] [--tb N] [--rb N] [--gain-frac N]\n"
                             "                [--flat-log2 N] [--opp-tau-log2 N] (up5k)\n"
                             "ecp5 (default): writes setup_efu.hex, setup_exp2.hex, setup_ucode.hex, setup_params.vh and\n"
                             "setup_params.h (the multiplier setup's tables, microcode and parameters) into DIR;\n"
                             "up5k: setup_small_log2.hex, setup_small_exp2.hex, setup_small_params.vh and\n"
                             "setup_small_params.h (the small CORDIC setup's). docs/setup.md.\n";
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
            if (fl == "--config") {
                const std::string c = a.value(fl);
                if (c != "ecp5" && c != "up5k") throw UsageError("unknown configuration '" + c + "' (ecp5, up5k)");
                small = c == "up5k";
                continue;
            }
            if (fl == "--format") {   // the multiplier setup's named format; the options after it change it
                try {
                    sf = setup_format_config(a.value(fl));
                } catch (const std::invalid_argument& e) {
                    throw UsageError(e.what());
                }
                machine_options = true;
                continue;
            }
            int* sfield = fl == "--f"              ? &ss.f
                          : fl == "--iters"        ? &ss.iters
                          : fl == "--zf"           ? &ss.zf
                          : fl == "--lf"           ? &ss.lf
                          : fl == "--ef"           ? &ss.ef
                          : fl == "--tb"           ? &ss.tb
                          : fl == "--rb"           ? &ss.rb
                          : fl == "--gain-frac"    ? &ss.gain_frac
                          : fl == "--flat-log2"    ? &ss.flat_log2
                          : fl == "--opp-tau-log2" ? &ss.opp_tau_log2
                                                   : nullptr;
            if (sfield) {
                *sfield = static_cast<int>(parse_int(fl, a.value(fl), -64, 64));
                small_options = true;
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
            machine_options = true;
        }
        if (small_options && !small) throw UsageError("--f, --iters ... are the up5k configuration's options");
        if (small) {
            if (machine_options) throw UsageError("--format and the unit options are the ecp5 configuration's");
            try {
                ss.validate();
            } catch (const std::invalid_argument& e) {
                throw UsageError(e.what());
            }
            try {
                write_small_all(ss, out, rom_path);
            } catch (const std::runtime_error& e) {   // a file that cannot be written
                throw UsageError(e.what());
            }
            return 0;
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
