// commands.h - the entry points of specsim's commands, for main.cpp.
//
// Every command lives in its own files under sim/specsim/ and is split three ways: parse (argv -> an options
// struct), compute (library functions the unit tests call and check: cmd_*.h) and report (printing, files).
// An entry point takes specsim's argc/argv (argv[1] is the command) and returns the exit code. Bad input
// throws spec::UsageError (the command line) or spec::InputError (a file, an output path): one line on stderr,
// exit 2. Anything else that escapes is an internal error: exit 3 (main.cpp).
#pragma once

namespace spec {

int cmd_span(int argc, char** argv);      // one span through the core (cmd_span.cpp)
int cmd_fig8(int argc, char** argv);      // the recomputed Fig. 8 (cmd_fig8.cpp)
int cmd_demo(int argc, char** argv);      // the Fig. 11/12 run and representative spans (cmd_demo.cpp)
int cmd_accuracy(int argc, char** argv);  // worst errors per BRDF range against double precision (cmd_accuracy.cpp)
int cmd_vectors(int argc, char** argv);   // test vectors for the Icarus testbenches (cmd_vectors.cpp)

int cmd_render(int argc, char** argv);        // a scene through the core: PNG, panel, stats (render_*.cpp)
int cmd_render_bench(int argc, char** argv);  // pixels/s of rtl and golden, spans/s of the host (cmd_render_bench.cpp)
int cmd_plots(int argc, char** argv);         // the patent's Fig. 5 and Fig. 9 redrawn (cmd_plots.cpp)
int cmd_export_obj(int argc, char** argv);    // a built-in scene's meshes as an OBJ file (cmd_plots.cpp)

int cmd_bench_stream(int argc, char** argv);    // cycles/pixel and simulation speed (cmd_bench_stream.cpp)
int cmd_stream_diagram(int argc, char** argv);  // AXI timing from a simulation (cmd_stream_diagram.cpp)
int cmd_bench_lanes(int argc, char** argv);     // pixels per clock with LANES = 1, 2, 4 (cmd_bench_lanes.cpp)

int cmd_compare(int argc, char** argv);  // patent vs tuned vs prototype per BRDF range (cmd_compare.cpp)
int cmd_tables(int argc, char** argv);   // table sets and sizes against ROM bits (cmd_tables.cpp)

int cmd_highlight(int argc, char** argv);  // companion paper A measured (cmd_highlight.cpp, report_highlight.cpp)
int cmd_normalize(int argc, char** argv);  // companion paper B measured (cmd_normalize.cpp, report_normalize.cpp)
int cmd_parallax(int argc, char** argv);   // companion paper C measured (cmd_parallax.cpp, report_parallax.cpp)

int cmd_setup(int argc, char** argv);           // span ends through spec_setup (cmd_setup.cpp, issue 13)
int cmd_setup_accuracy(int argc, char** argv);  // the shader against the host per pixel (cmd_setup_accuracy.cpp)
int cmd_bench_shader(int argc, char** argv);    // spec_shader's pixels per clock (cmd_bench_shader.cpp)
int cmd_shader_diagram(int argc, char** argv);  // spec_shader's ports cycle by cycle (cmd_shader_diagram.cpp)
int cmd_setup_vectors(int argc, char** argv);   // Icarus vectors for spec_shader (cmd_setup_vectors.cpp)

// The usage lines, for specsim --help and COMMAND --help: each command's block starts with a line
// "  NAME  ..." (two spaces, the name) and runs to the next such line.
extern const char* const kSpanUsage;      // cmd_span.cpp
extern const char* const kFig8Usage;      // cmd_fig8.cpp
extern const char* const kDemoUsage;      // cmd_demo.cpp
extern const char* const kAccuracyUsage;  // cmd_accuracy.cpp
extern const char* const kVectorsUsage;   // cmd_vectors.cpp
extern const char* const kRenderUsage;    // render, render-bench, plots, export-obj
extern const char* const kBenchUsage;     // stream-diagram, bench-stream
extern const char* const kBenchLanesUsage;  // bench-lanes (cmd_bench_lanes.cpp)
extern const char* const kTunedUsage;     // compare, tables
extern const char* const kMethodsUsage;   // highlight, normalize, parallax (methods_usage.cpp)
extern const char* const kSetupUsage;          // cmd_setup.cpp
extern const char* const kSetupAccuracyUsage;  // cmd_setup_accuracy.cpp
extern const char* const kBenchShaderUsage;    // cmd_bench_shader.cpp
extern const char* const kShaderDiagramUsage;  // cmd_shader_diagram.cpp
extern const char* const kSetupVectorsUsage;   // cmd_setup_vectors.cpp

}  // namespace spec
