// boardsim - the reference designs in simulation (docs/boards.md):
//   boardsim run --board icebreaker|ulx3s [--mode M] [--frames N] [--out-dir DIR]
//   boardsim split [--mode M] [--k K,...] [--shader host|rtl]
//   boardsim gen --out-dir DIR [--k K,...]
//   boardsim models
// Bad input: one line on stderr, exit 2; a failed check: exit 1; an internal error: exit 3.
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include "board_harness.h"
#include "board_scene.h"
#include "boardsim_cli.h"
#include "boardsim_compute.h"
#include "boardsim_report.h"
#include "cli.h"

using namespace spec;
using namespace spec::board;

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fputs(usage(), stderr);
        return 2;
    }
    const std::string cmd = argv[1];
    try {
        if (cmd == "--help" || cmd == "-h" || cmd == "help") {
            std::fputs(usage(), stdout);
            return 0;
        }
        for (int i = 2; i < argc; ++i) {
            if (std::strcmp(argv[i], "--help") == 0) {
                std::fputs(usage(), stdout);
                return 0;
            }
        }
        if (cmd == "run") {
            const RunOptions o = parse_run(argc, argv);
            const RunReport r = run_board_sim(o);
            if (!o.quiet) print_run(r);
            write_run(r);
            return r.failures.empty() ? 0 : 1;
        }
        if (cmd == "split") {
            const SplitOptions o = parse_split(argc, argv);
            print_split(o, split_study(o));
            return 0;
        }
        if (cmd == "gen") {
            const GenOptions o = parse_gen(argc, argv);
            for (const std::string& f : write_rtl_tables(o.out_dir, o.ks)) std::printf("%s/%s\n", o.out_dir.c_str(), f.c_str());
            return 0;
        }
        if (cmd == "models") {
            for (const std::string& m : available_models()) std::printf("%s\n", m.c_str());
            return 0;
        }
        throw UsageError("unknown command '" + cmd + "' (run, split, gen, models; boardsim --help)");
    } catch (const UsageError& e) {
        std::fprintf(stderr, "boardsim: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "boardsim: internal error: %s\n", printable(e.what()).c_str());
        return 3;
    }
}
