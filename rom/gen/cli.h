// cli.h - strict parsing of command-line values, shared by specrom and specsim.
// Every failure throws UsageError with a one-line message; the programs print it and exit 2. InputError is
// the same promise for input that is not the command line (a file, an output path that cannot be written).
// Anything else a program throws is an internal error (specsim: exit 3).
#pragma once

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace spec {

// A message made one printable line: control characters (a newline in an argument, say) become C escapes
// (\n, \t, \xNN), so that echoing the user's input cannot split the one-line error into several.
inline std::string printable(const std::string& s) {
    static const char* hex = "0123456789abcdef";
    std::string o;
    o.reserve(s.size());
    for (unsigned char c : s) {
        if (c == '\n') o += "\\n";
        else if (c == '\r') o += "\\r";
        else if (c == '\t') o += "\\t";
        else if (c < 0x20 || c == 0x7f) {
            o += "\\x";
            o += hex[c >> 4];
            o += hex[c & 15];
        } else {
            o += static_cast<char>(c);
        }
    }
    return o;
}

struct UsageError : std::runtime_error {
    explicit UsageError(const std::string& what) : std::runtime_error(printable(what)) {}
};

struct InputError : std::runtime_error {
    explicit InputError(const std::string& what) : std::runtime_error(printable(what)) {}
};

inline long long parse_int(const std::string& flag, const std::string& s, long long lo, long long hi) {
    if (s.empty()) throw UsageError(flag + ": missing value");
    errno = 0;
    char* end = nullptr;
    long long v = std::strtoll(s.c_str(), &end, 0);
    if (errno == ERANGE || end == s.c_str() || *end != '\0') {
        throw UsageError(flag + ": '" + s + "' is not an integer");
    }
    if (v < lo || v > hi) {
        throw UsageError(flag + ": " + s + " is outside " + std::to_string(lo) + ".." + std::to_string(hi));
    }
    return v;
}

inline double parse_double(const std::string& flag, const std::string& s) {
    if (s.empty()) throw UsageError(flag + ": missing value");
    errno = 0;
    char* end = nullptr;
    double v = std::strtod(s.c_str(), &end);
    if (end == s.c_str() || *end != '\0') throw UsageError(flag + ": '" + s + "' is not a number");
    if (!std::isfinite(v) || errno == ERANGE) throw UsageError(flag + ": '" + s + "' is not a finite number");
    return v;
}

// A table set "1,2,4,16": strictly increasing integers in 1..256, at most 16 of them.
inline std::vector<int> parse_tables(const std::string& flag, const std::string& s) {
    std::vector<int> t;
    size_t pos = 0;
    while (true) {
        const size_t comma = s.find(',', pos);
        const std::string item = s.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
        const int k = static_cast<int>(parse_int(flag, item, 1, 256));
        if (!t.empty() && k <= t.back()) throw UsageError(flag + ": the powers must be strictly increasing");
        t.push_back(k);
        if (comma == std::string::npos) break;
        pos = comma + 1;
    }
    if (t.size() > 16) throw UsageError(flag + ": at most 16 tables");
    return t;
}

// Walks argv as "--flag value" pairs (and bare "--switch"es the caller names).
class Args {
public:
    Args(int argc, char** argv, int first) : argc_(argc), argv_(argv), i_(first) {}
    bool done() const { return i_ >= argc_; }
    std::string flag() {
        std::string f = argv_[i_++];
        if (f.rfind("--", 0) != 0) throw UsageError("unexpected argument '" + f + "'");
        return f;
    }
    std::string value(const std::string& flag) {
        if (i_ >= argc_) throw UsageError(flag + ": missing value");
        std::string v = argv_[i_++];
        if (v.rfind("--", 0) == 0 && !(v.size() > 2 && (std::isdigit(static_cast<unsigned char>(v[2])) || v[2] == '.'))) {
            throw UsageError(flag + ": missing value");
        }
        return v;
    }

private:
    int argc_;
    char** argv_;
    int i_;
};

}  // namespace spec
