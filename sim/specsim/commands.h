// commands.h - specsim subcommands that live outside main.cpp (the renderer, issue 3).
// Each takes specsim's argc/argv (argv[1] is the command), returns the exit code, and throws
// spec::UsageError / std::exception with a one-line message for bad input (main prints it, exits 2).
#pragma once

namespace spec {

int cmd_render(int argc, char** argv);        // specsim render: a scene through the core, PNG, panel, stats
int cmd_render_bench(int argc, char** argv);  // specsim render-bench: pixels/s of rtl and golden, spans/s of the host
int cmd_plots(int argc, char** argv);         // specsim plots: the patent's Fig. 5 and Fig. 9 redrawn (gnuplot)
int cmd_export_obj(int argc, char** argv);    // specsim export-obj: a built-in scene's meshes as an OBJ file

int cmd_bench_stream(int argc, char** argv);  // specsim bench-stream: cycles/pixel and simulation speed (cmd_bench.cpp)
int cmd_stream_diagram(int argc, char** argv);  // specsim stream-diagram: AXI timing from a simulation (cmd_bench.cpp)

int cmd_compare(int argc, char** argv);  // specsim compare: patent vs tuned vs prototype per BRDF range (cmd_tuned.cpp)
int cmd_tables(int argc, char** argv);   // specsim tables: table sets and sizes against ROM bits (cmd_tuned.cpp)

int cmd_highlight(int argc, char** argv);  // specsim highlight: companion paper A measured (cmd_highlight.cpp)
int cmd_normalize(int argc, char** argv);  // specsim normalize: companion paper B measured (cmd_normalize.cpp)
int cmd_parallax(int argc, char** argv);   // specsim parallax: companion paper C measured (cmd_parallax.cpp)

int cmd_setup(int argc, char** argv);   // specsim setup: span ends through spec_setup (cmd_setup.cpp, issue 13)
int cmd_bench_shader(int argc, char** argv);
int cmd_setup_accuracy(int argc, char** argv);   // specsim setup-accuracy: the shader against the host (issue 13)   // specsim bench-shader: spec_shader's pixels per clock (issue 13)

// The usage lines of these commands, for specsim --help.
extern const char* const kRenderUsage;
extern const char* const kBenchUsage;
extern const char* const kTunedUsage;
extern const char* const kMethodsUsage;
extern const char* const kSetupUsage;
extern const char* const kBenchShaderUsage;
extern const char* const kSetupAccuracyUsage;

}  // namespace spec
