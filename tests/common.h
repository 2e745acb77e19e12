// common.h - what the GoogleTest files share: specsim run as a user runs it (exit code, stdout, stderr),
// a per-process scratch directory, and the random span generators.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "analysis.h"
#include "cli.h"
#include "fit.h"
#include "spec_model.h"

namespace spec {
namespace test {

// A scratch directory of this process under GoogleTest's temporary directory (ctest runs the tests of one
// binary as parallel processes, so every process gets its own).
inline std::string tmpdir() {
    static const std::string d = [] {
        const std::string t = ::testing::TempDir() + "/spec_test." + std::to_string(::getpid());
        if (std::system(("mkdir -p '" + t + "'").c_str()) != 0) ADD_FAILURE() << "cannot create " << t;
        return t;
    }();
    return d;
}

// A count from the environment for spec_long (SPEC_LONG_PIXELS, SPEC_LONG_SPANS, SPEC_LONG_SEED): dflt when
// unset; a value that is not a count is bad input (one line, exit 2).
inline uint64_t env_u64(const char* name, uint64_t dflt) {
    const char* v = std::getenv(name);
    if (!v || !*v) return dflt;
    try {
        return static_cast<uint64_t>(parse_int(name, v, 0, std::numeric_limits<long long>::max()));
    } catch (const UsageError& e) {
        std::fprintf(stderr, "spec_long: %s\n", e.what());
        std::exit(2);
    }
}

inline bool exists(const std::string& path) { return std::ifstream(path).good(); }

inline void write_file(const std::string& path, const std::string& text) {
    std::ofstream o(path);
    o << text;
    if (!o) ADD_FAILURE() << "cannot write " << path;
}

inline std::string read_file(const std::string& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

inline std::vector<std::string> lines(const std::string& s) {
    std::vector<std::string> v;
    std::istringstream is(s);
    for (std::string l; std::getline(is, l);) v.push_back(l);
    return v;
}

struct CliRun {
    int code;          // exit code (-1: killed by a signal)
    std::string out;   // stdout
    std::string err;   // stderr
};

#ifdef SPECSIM_PATH
// Runs `specsim ARGS` through the shell (ARGS is shell text: quote what needs it), stdin from /dev/null.
inline CliRun specsim(const std::string& args) {
    static std::atomic<unsigned> serial{0};
    const std::string ef = tmpdir() + "/specsim_err." + std::to_string(serial++) + ".txt";
    const std::string cmd = std::string(SPECSIM_PATH) + " " + args + " 2>" + ef + " </dev/null";
    CliRun r;
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) {
        ADD_FAILURE() << "popen failed: " << cmd;
        return CliRun{-1, "", ""};
    }
    char buf[4096];
    size_t k;
    while ((k = fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, k);
    const int st = pclose(p);
    r.code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    r.err = read_file(ef);
    std::remove(ef.c_str());
    return r;
}

// The promise for bad input (docs/bad-input.md): exit 2, nothing on stdout, one line on stderr that starts
// with "specsim: ".
inline ::testing::AssertionResult is_bad_input(const CliRun& r) {
    if (r.code != 2) return ::testing::AssertionFailure() << "exit code " << r.code << ", stderr: " << r.err;
    if (!r.out.empty()) return ::testing::AssertionFailure() << "wrote to stdout: " << r.out;
    const auto l = lines(r.err);
    if (l.size() != 1 || r.err.back() != '\n') return ::testing::AssertionFailure() << "stderr not one line: " << r.err;
    if (l[0].rfind("specsim: ", 0) != 0) return ::testing::AssertionFailure() << "stderr: " << l[0];
    return ::testing::AssertionSuccess();
}
#endif  // SPECSIM_PATH

// A span around the highlight of n, with the decimal values it was made from: angles inside [-pi, pi], half
// of the spans within three epicentres, half reaching well past the table's pi/2; C in [0, 1).
struct RandomSpan {
    SpanRegs regs;
    double c, zeta0, dzeta;  // the decimal values given (before quantization)
};
inline RandomSpan random_span(std::mt19937_64& rng, const Model& m, unsigned n, uint32_t max_len) {
    RandomSpan s;
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    s.c = u01(rng) * 0.999999;
    const double reach = std::min(M_PI, (rng() % 2 ? 3.0 : 9.0) * epicentre_end(n) + 0.05 * u01(rng));
    std::uniform_real_distribution<double> ang(-reach, reach);
    const uint32_t len = static_cast<uint32_t>(rng() % (max_len + 1));
    s.zeta0 = ang(rng);
    const double end = ang(rng);
    s.dzeta = len ? (end - s.zeta0) / len : 0.0;
    s.regs = SpanRegs{m.quantize_c(s.c), m.quantize_angle(s.dzeta), m.quantize_angle(s.zeta0), n, len};
    return s;
}

// A span as a host sends it to a stream of spans: any n and C, short ones often (span boundaries are where a
// streaming core breaks: l = 0 one time in four, l < 4 one in four), otherwise up to max_len; angles within
// six epicentres, or raw register contents (saturating angles, any step) one time in sixteen.
inline SpanRegs random_stream_span(std::mt19937_64& rng, const Model& m, uint32_t max_len) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const Format& f = m.format();
    SpanRegs r;
    r.n = static_cast<uint32_t>(rng() % (uint64_t(1) << f.n_w));
    r.c = static_cast<uint32_t>(rng() & ((uint64_t(1) << f.c_w) - 1));
    const int kind = static_cast<int>(rng() % 4);
    const uint64_t top = (uint64_t(1) << f.l_w) - 1;
    r.len = kind == 0 ? 0
          : kind == 1 ? static_cast<uint32_t>(rng() % 4)
                      : static_cast<uint32_t>(std::min<uint64_t>(rng() % (uint64_t(max_len) + 1), top));
    const double reach = std::min(M_PI, 6.0 * epicentre_end(r.n));
    r.zeta0 = m.quantize_angle(reach * u(rng));
    r.dzeta = m.quantize_angle(r.len ? (reach * u(rng) - m.angle_value(r.zeta0)) / r.len : 0.0);
    if (rng() % 16 == 0) {
        r.zeta0 = static_cast<int32_t>(rng());
        r.dzeta = static_cast<int32_t>(rng()) >> (rng() % 32);
    }
    return r;
}
inline std::vector<SpanRegs> random_spans(std::mt19937_64& rng, const Model& m, size_t count, uint32_t max_len) {
    std::vector<SpanRegs> v;
    for (size_t i = 0; i < count; ++i) v.push_back(random_stream_span(rng, m, max_len));
    return v;
}

// The bound tests (docs/verification.md, "bound ratios"). Each pixel's error against double precision is held
// to a bound computed per case, and two worst ratios are asserted against what they measure today:
//   error_over_bound  |out - ref| / bound: how close the core comes to its bound (approximation + fixed point)
//   fixed_over_slack  |out - C_q * approximation(x_q)| / slack: the fixed-point error alone (out against the
//                     double-precision approximation at the angle register 8 holds, C as register 1 holds it)
//                     over the bound's fixed-point allowance slack = 0.2 % + 2^-14 of ref in the epicentre,
//                     0.2 % + 2^-13 of C outside it.
// The approximation's own error dominates the first ratio, so a fixed point twice as coarse moves it by 2 %;
// the second doubles with it. Each test asserts fixed_over_slack <= 1.25 x its measured worst, so a regression
// to twice today's fixed-point error fails (tests/mutants.py shows it on a deliberately coarsened ROM 12).
inline double approximation(const Format& f, unsigned n, double x) {
    const TableFit& t = table_fits(f)[n];
    return approx_scaled(t.k, t.scale, x);
}
inline double fixed_point_slack(unsigned n, double c, double angle, double ref) {
    return std::fabs(angle) <= epicentre_end(n) ? 0.002 * ref + std::ldexp(1.0, -14) : 0.002 * c + std::ldexp(1.0, -13);
}
struct BoundRatios {
    double error_over_bound = 0, fixed_over_slack = 0;
    unsigned fixed_n = 0;
    // One pixel of span r (index i, register 8 at angle_raw) from model m's format: out the core's word, ref the
    // double reference, bound its bound, c the decimal C the reference uses.
    void add(const Model& m, const SpanRegs& r, int64_t angle_raw, uint32_t out, double ref, double bound, double c,
             double angle) {
        const double o = m.out_value(out);
        error_over_bound = std::max(error_over_bound, std::fabs(o - ref) / bound);
        const double ideal = m.out_value(r.c) * approximation(m.format(), r.n, m.angle_value(angle_raw));
        const double f = std::fabs(o - ideal) / fixed_point_slack(r.n, c, angle, ref);
        if (f > fixed_over_slack) {
            fixed_over_slack = f;
            fixed_n = r.n;
        }
    }
};

#ifdef SPEC_SOURCE_DIR
// The bound test `name`'s row of docs/verification.md's table ("| `Name` | 0.898 | ≤ 0.95 | 0.362 (n = 139) |
// ≤ 0.45 |") must hold what the test measured (to the table's three decimals) and the limits it asserts: the
// document cannot drift from the tests.
inline void expect_documented_ratios(const std::string& name, const BoundRatios& w, double limit_error,
                                     double limit_fixed) {
    const std::string doc = read_file(std::string(SPEC_SOURCE_DIR) + "/docs/verification.md");
    const size_t at = doc.find("| `" + name + "` |");
    if (at == std::string::npos) {
        ADD_FAILURE() << "docs/verification.md has no row for " << name;
        return;
    }
    const std::string row = doc.substr(at, doc.find('\n', at) - at);
    double v[4] = {0, 0, 0, 0};
    unsigned n = 0;
    const size_t cells = row.find("` |") + 3;
    if (std::sscanf(row.c_str() + cells, " %lf | \xe2\x89\xa4 %lf | %lf (n = %u) | \xe2\x89\xa4 %lf |", &v[0], &v[1], &v[2], &n,
                    &v[3]) != 5) {
        ADD_FAILURE() << "docs/verification.md: cannot read the row " << row;
        return;
    }
    EXPECT_NEAR(w.error_over_bound, v[0], 0.0005) << name << ": docs/verification.md says " << v[0];
    EXPECT_EQ(limit_error, v[1]) << name << ": docs/verification.md's limit";
    EXPECT_NEAR(w.fixed_over_slack, v[2], 0.0005) << name << ": docs/verification.md says " << v[2];
    EXPECT_EQ(w.fixed_n, n) << name << ": docs/verification.md's n";
    EXPECT_EQ(limit_fixed, v[3]) << name << ": docs/verification.md's limit";
}
#endif  // SPEC_SOURCE_DIR

}  // namespace test
}  // namespace spec
