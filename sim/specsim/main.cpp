// specsim - the command-line front end of the UA 71489 specular-shading core: one table of commands.
//
//   specsim --help                 every command's usage
//   specsim COMMAND --help         that command's usage (exit 0)
//   specsim COMMAND [options]      see commands.h and each cmd_*.cpp
//
// Exit codes (exit_codes.h): 0 success; 2 bad input (spec::UsageError, spec::InputError: one line on stderr);
// 3 an internal error (anything else: "specsim: internal error: ..."), a bug, never the user's input.
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>

#include "cli.h"
#include "commands.h"
#include "exit_codes.h"

using namespace spec;

namespace {

struct Command {
    const char* name;
    int (*run)(int, char**);
};
const Command kCommands[] = {
    {"span", cmd_span},           {"fig8", cmd_fig8},
    {"demo", cmd_demo},           {"accuracy", cmd_accuracy},
    {"vectors", cmd_vectors},     {"render", cmd_render},
    {"render-bench", cmd_render_bench}, {"plots", cmd_plots},
    {"export-obj", cmd_export_obj},     {"stream-diagram", cmd_stream_diagram},
    {"bench-stream", cmd_bench_stream}, {"compare", cmd_compare},
    {"tables", cmd_tables},       {"highlight", cmd_highlight},
    {"normalize", cmd_normalize}, {"parallax", cmd_parallax},
    {"bench-lanes", cmd_bench_lanes},
    {"setup", cmd_setup},         {"setup-accuracy", cmd_setup_accuracy},
    {"bench-shader", cmd_bench_shader}, {"shader-diagram", cmd_shader_diagram},
    {"setup-vectors", cmd_setup_vectors},
};

std::string full_usage() {
    return std::string("usage: specsim <command> [options]   (specsim <command> --help: that command alone)\n\n"
                       "commands:\n") +
           kSpanUsage + kFig8Usage + kDemoUsage + kAccuracyUsage + kVectorsUsage + kRenderUsage + kBenchUsage +
           kBenchLanesUsage + kTunedUsage + kMethodsUsage + kSetupUsage + kSetupAccuracyUsage + kBenchShaderUsage +
           kShaderDiagramUsage + kSetupVectorsUsage;
}

// The block of `name` in the usage text: from its line "  name ..." to the next command's line.
std::string usage_of(const std::string& name) {
    std::istringstream is(full_usage());
    std::string out, line;
    bool in = false;
    for (; std::getline(is, line);) {
        const bool command_line = line.size() > 2 && line[0] == ' ' && line[1] == ' ' && line[2] != ' ';
        if (command_line) {
            const std::string word = line.substr(2, line.find(' ', 2) == std::string::npos ? std::string::npos
                                                                                            : line.find(' ', 2) - 2);
            in = word == name;
        }
        if (in) out += line + "\n";
    }
    return "usage: specsim " + name + " [options]\n" + out;
}

bool asks_for_help(int argc, char** argv) {
    for (int i = 2; i < argc; ++i) {
        if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0) return true;
    }
    return false;
}

int dispatch(int argc, char** argv) {
    if (argc < 2) throw UsageError("missing command (span, fig8, demo, accuracy, vectors); see specsim --help");
    const std::string cmd = argv[1];
    if (cmd == "--help" || cmd == "-h" || cmd == "help") {
        std::cout << full_usage();
        return 0;
    }
    for (const Command& c : kCommands) {
        if (cmd != c.name) continue;
        if (asks_for_help(argc, argv)) {
            std::cout << usage_of(c.name);
            return 0;
        }
        return c.run(argc, argv);
    }
    throw UsageError("unknown command '" + cmd + "'; see specsim --help");
}

}  // namespace

int main(int argc, char** argv) {
    return exit_code_of([&] { return dispatch(argc, argv); }, std::cerr);
}
