// methods_util.cpp - shared pieces of the companion papers' commands (methods_util.h).
#include "methods_util.h"

#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "fileutil.h"

namespace spec {
namespace methods_cli {

std::string strf(const char* fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    va_list ap2;
    va_copy(ap2, ap);
    const int n = std::vsnprintf(nullptr, 0, fmt, ap);
    va_end(ap);
    std::string s(size_t(n > 0 ? n : 0), '\0');
    if (n > 0) std::vsnprintf(&s[0], size_t(n) + 1, fmt, ap2);
    va_end(ap2);
    return s;
}

double pct(double a, double b) { return b > 0 ? 100.0 * a / b : 0.0; }

void make_dir(const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw std::runtime_error("cannot create " + dir + ": " + ec.message());
}

void write_text(const std::string& path, const std::string& text) {
    render::write_atomic(path, [&](const std::string& tmp) {
        std::ofstream o(tmp);
        o << text;
        o.close();
        if (!o) throw std::runtime_error("cannot write " + path);
    });
}

bool run_gnuplot(const std::string& dir, const std::string& name, const std::string& script) {
    const std::string gp = dir + "/" + name + ".gp";
    write_text(gp, script);
    const std::string cmd = "gnuplot '" + gp + "' 2>/dev/null";
    return std::system(cmd.c_str()) == 0;
}

void DocTables::add(const std::string& name, const std::string& text) { blocks_.emplace_back(name, text); }

void DocTables::write(const std::string& path) const {
    if (path.empty()) return;
    std::string s;
    for (const auto& b : blocks_) {
        s += "<!-- methods:" + b.first + " -->\n" + b.second;
        if (!b.second.empty() && b.second.back() != '\n') s += "\n";
        s += "<!-- /methods:" + b.first + " -->\n";
    }
    write_text(path, s);
}

bool wants_help(int argc, char** argv, const char* usage) {
    for (int i = 2; i < argc; ++i) {
        if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0) {
            std::fputs(usage, stdout);
            return true;
        }
    }
    return false;
}

}  // namespace methods_cli
}  // namespace spec
