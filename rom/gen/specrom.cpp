// specrom - writes the $readmemh images of ROM 9 and ROM 12 and the headers spec_params.vh / spec_params.h.
//
//   specrom [--out DIR] [--config default|up5k] [--mode patent|tuned] [--tables K,K,...]
//           [--tbl-aw N] [--tbl-frac N] [--scale-w N] [--scale-frac N]
//           [--c-w N] [--ang-w N] [--ang-frac N] [--n-w N] [--l-w N]
//           [--interp [--interp-frac N] [--delta-w N]]
//
// --mode tuned: ROM 9 holds the minimax scale per n and the table index (decoder 10 as a ROM; docs/tuned.md).
// --tables: the powers k of ROM 12's tables (default 1,2,4,16); any other set also puts the table into ROM 9.
//
// With no options it writes the default images (the ones committed in rom/) into the current directory.
// Bad input: a one-line message on stderr and exit code 2; nothing is written.
#include <iostream>

#include "cli.h"
#include "romgen.h"

int main(int argc, char** argv) {
    using namespace spec;
    try {
        Format f;
        std::string out = ".";
        Args a(argc, argv, 1);
        while (!a.done()) {
            std::string fl = a.flag();
            if (fl == "--help" || fl == "-h") {
                std::cout << "usage: specrom [--out DIR] [--config default|up5k] [--mode patent|tuned] [--tables K,K,...]\n"
                             "               [--tbl-aw N] [--tbl-frac N] [--scale-w N] [--scale-frac N]\n"
                             "               [--c-w N] [--ang-w N] [--ang-frac N] [--n-w N] [--l-w N]\n"
                             "               [--interp [--interp-frac N] [--delta-w N]]\n"
                             "Writes rom9_scale.hex, rom12_cosk.hex, spec_params.vh and spec_params.h into DIR.\n";
                return 0;
            }
            if (fl == "--out") { out = a.value(fl); continue; }
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
                                                : nullptr;
            if (!field) throw UsageError("unknown option " + fl);
            *field = static_cast<int>(parse_int(fl, a.value(fl), 0, 64));
            if (fl == "--c-w") f.out_w = f.c_w;
        }
        f.validate();
        write_all(f, out);
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "specrom: " << spec::printable(e.what()) << "\n";
        return 2;
    }
}
