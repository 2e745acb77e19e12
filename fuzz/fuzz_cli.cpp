// fuzz_cli - rom/gen/cli.h: parse_int, parse_double, parse_tables and Args, as specrom and specsim use
// them. Promise: a value within the asked range / finite / a valid table set, or UsageError with a one-line
// message; nothing else thrown, no undefined behaviour, Args always finishes.
#include <cmath>

#include "cli.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    fuzz::Input in(data, size);
    const int64_t lo = in.range(-70000, 70000);
    const int64_t hi = lo + in.range(0, 140000);
    std::vector<std::string> tok = in.tokens();
    for (const std::string& s : tok) {
        try {
            const long long v = spec::parse_int("--x", s, lo, hi);
            fuzz::check(v >= lo && v <= hi, "parse_int out of range: " + s);
        } catch (const spec::UsageError& e) {
            fuzz::one_line(e.what());
        }
        try {
            const double d = spec::parse_double("--x", s);
            fuzz::check(std::isfinite(d), "parse_double not finite: " + s);
        } catch (const spec::UsageError& e) {
            fuzz::one_line(e.what());
        }
        try {
            const std::vector<int> t = spec::parse_tables("--tables", s);
            fuzz::check(!t.empty() && t.size() <= 16, "parse_tables size");
            for (size_t i = 0; i < t.size(); ++i)
                fuzz::check(t[i] >= 1 && t[i] <= 256 && (i == 0 || t[i] > t[i - 1]), "parse_tables order: " + s);
        } catch (const spec::UsageError& e) {
            fuzz::one_line(e.what());
        }
    }
    // Args over the tokens as argv
    std::vector<char*> argv;
    static char prog[] = "prog";
    argv.push_back(prog);
    for (std::string& s : tok) argv.push_back(&s[0]);
    spec::Args a(static_cast<int>(argv.size()), argv.data(), 1);
    size_t steps = 0;
    try {
        while (!a.done()) {
            fuzz::check(++steps <= argv.size(), "Args does not advance");
            const std::string fl = a.flag();
            if (fl.size() % 2) a.value(fl);   // a value after some flags, not after others
        }
    } catch (const spec::UsageError& e) {
        fuzz::one_line(e.what());
    }
    return 0;
}
