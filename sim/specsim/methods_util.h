// methods_util.h - what the companion papers' commands (specsim highlight, normalize, parallax) share:
// formatting, output directories, gnuplot, and the named table blocks `make methods` embeds into
// docs/methods.md (scripts/methods_doc.py; ctest methods_doc_tables compares them).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace spec {
namespace methods_cli {

std::string strf(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
double pct(double a, double b);  // 100 a / b, 0 when b = 0
void make_dir(const std::string& dir);
// Writes `text` to path whole or not at all.
void write_text(const std::string& path, const std::string& text);
// Runs gnuplot on `script` (written to dir/name.gp); false when gnuplot fails or is missing.
bool run_gnuplot(const std::string& dir, const std::string& name, const std::string& script);

// The document's tables: each block is printed on stdout as the command runs and, with --tables FILE,
// written to FILE between the markers <!-- methods:NAME --> and <!-- /methods:NAME -->.
class DocTables {
public:
    void add(const std::string& name, const std::string& text);
    void write(const std::string& path) const;  // nothing when path is empty

private:
    std::vector<std::pair<std::string, std::string>> blocks_;
};

// A command's usage text and its --help: true (and the text printed) when argv holds --help or -h.
bool wants_help(int argc, char** argv, const char* usage);

}  // namespace methods_cli
}  // namespace spec
