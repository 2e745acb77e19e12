// specrom - writes the $readmemh images of ROM 9 and ROM 12 and the headers spec_params.vh / spec_params.h.
//
//   specrom [--out DIR] [--config default|up5k] [--mode patent|tuned] [--tables K,K,...]
//           [--tbl-aw N] [--tbl-frac N] [--scale-w N] [--scale-frac N]
//           [--c-w N] [--ang-w N] [--ang-frac N] [--n-w N] [--l-w N]
//           [--interp [--interp-frac N] [--delta-w N]] [--rom-path PREFIX]
//           [--pow-seg-w N] [--pow-idx-w N] [--pow-frac N] [--pow-val-w N] [--pow-dlt-w N] [--pow-sh-w N]
//           [--pow-xb N] [--pow-yf N] [--pow-yi N]
//
// spec_params.vh names the images as PREFIX + file name (SPEC_ROM9_FILE, SPEC_ROM12_FILE); PREFIX defaults to the
// absolute path of DIR, so a simulation that includes DIR's header finds the images from any working directory.
// The committed rom/spec_params.vh is made with --rom-path rom/ (relative to the repository root).
//
// --mode tuned: ROM 9 holds the minimax scale per n and the table index (decoder 10 as a ROM; docs/tuned.md).
// --tables: the powers k of ROM 12's tables (default 1,2,4,16); any other set also puts the table into ROM 9.
// --mode pow: ROM 9 the log table, ROM 12 exp2 (docs/pow.md); --pow-*: its formats (spec_format.h).
//
// With no options it writes the default images (the ones committed in rom/) into the current directory.
// Bad input: a one-line message on stderr and exit code 2; nothing is written.
#include <filesystem>
#include <iostream>

#include "cli.h"
#include "romgen.h"

int main(int argc, char** argv) {
    using namespace spec;
    try {
        Format f;
        std::string out = ".";
        std::string rom_path;
        bool have_rom_path = false;
        Args a(argc, argv, 1);
        while (!a.done()) {
            std::string fl = a.flag();
            if (fl == "--help" || fl == "-h") {
                std::cout << "usage: specrom [--out DIR] [--config default|up5k] [--mode patent|tuned] [--tables K,K,...]\n"
                             "               [--tbl-aw N] [--tbl-frac N] [--scale-w N] [--scale-frac N]\n"
                             "               [--c-w N] [--ang-w N] [--ang-frac N] [--n-w N] [--l-w N]\n"
                             "               [--interp [--interp-frac N] [--delta-w N]] [--rom-path PREFIX]\n"
                             "               [--mode pow [--pow-seg-w N] [--pow-idx-w N] [--pow-frac N] [--pow-val-w N]\n"
                             "                [--pow-dlt-w N] [--pow-sh-w N] [--pow-xb N] [--pow-yf N] [--pow-yi N]]\n"
                             "Writes rom9_scale.hex, rom12_cosk.hex, spec_params.vh and spec_params.h into DIR.\n"
                             "spec_params.vh names the images PREFIX + file name; PREFIX defaults to DIR's absolute\n"
                             "path with a trailing '/', so the header works from any working directory.\n";
                return 0;
            }
            if (fl == "--out") { out = a.value(fl); continue; }
            if (fl == "--rom-path") { rom_path = a.value(fl); have_rom_path = true; continue; }
            if (fl == "--interp") { f.interp = true; continue; }
            if (fl == "--config") {
                const Mode mode = f.mode;
                const std::vector<int> tables = f.tables;
                f = config_format(a.value(fl));
                f.mode = mode;
                f.tables = tables;
                continue;
            }
            if (fl == "--mode") { f.mode = parse_mode(a.value(fl)); continue; }
            if (fl == "--tables") { f.tables = parse_tables(fl, a.value(fl)); continue; }
            int* field = fl == "--tbl-aw"       ? &f.tbl_aw
                         : fl == "--tbl-frac"   ? &f.tbl_frac
                         : fl == "--scale-w"    ? &f.scale_w
                         : fl == "--scale-frac" ? &f.scale_frac
                         : fl == "--c-w"        ? &f.c_w
                         : fl == "--ang-w"      ? &f.ang_w
                         : fl == "--ang-frac"   ? &f.ang_frac
                         : fl == "--n-w"        ? &f.n_w
                         : fl == "--l-w"        ? &f.l_w
                         : fl == "--interp-frac" ? &f.interp_frac
                         : fl == "--delta-w"    ? &f.delta_w
                         : fl == "--pow-seg-w"  ? &f.pow_seg_w
                         : fl == "--pow-idx-w"  ? &f.pow_idx_w
                         : fl == "--pow-frac"   ? &f.pow_frac
                         : fl == "--pow-val-w"  ? &f.pow_val_w
                         : fl == "--pow-dlt-w"  ? &f.pow_dlt_w
                         : fl == "--pow-sh-w"   ? &f.pow_sh_w
                         : fl == "--pow-xb"     ? &f.pow_xb
                         : fl == "--pow-yf"     ? &f.pow_yf
                         : fl == "--pow-yi"     ? &f.pow_yi
                                                : nullptr;
            if (!field) throw UsageError("unknown option " + fl);
            *field = static_cast<int>(parse_int(fl, a.value(fl), 0, 64));
            if (fl == "--c-w") f.out_w = f.c_w;
        }
        f.validate();
        if (!have_rom_path) {
            std::error_code ec;
            const std::filesystem::path dir = std::filesystem::canonical(out, ec);
            // (a directory that does not exist fails in write_all, after the range checks)
            rom_path = (ec ? out : dir.string()) + "/";
        }
        for (char ch : rom_path) {
            if (ch == '"' || ch == '\\' || static_cast<unsigned char>(ch) < 0x20) {
                throw UsageError("the ROM path '" + rom_path + "' cannot be written in a Verilog string; pass --rom-path");
            }
        }
        write_all(f, out, rom_path);
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "specrom: " << spec::printable(e.what()) << "\n";
        return 2;
    }
}
