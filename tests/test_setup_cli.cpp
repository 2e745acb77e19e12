// specsim setup as a user runs it: the CSV format, rtl = golden character for character (descriptor and
// pixels, both configurations), host's values beside them, the parse -> compute -> report pieces.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>
#include <string>

#include "cmd_setup.h"
#include "setup_eval.h"

using namespace spec;

namespace {
struct Result {
    int code;
    std::string out, err;
};

Result run(const std::string& args) {
    const std::string errfile = ::testing::TempDir() + "/setup_err." + std::to_string(getpid()) + ".txt";
    const std::string cmd = std::string(SPECSIM_PATH) + " setup " + args + " 2>" + errfile + " </dev/null";
    Result r;
    FILE* p = popen(cmd.c_str(), "r");
    char buf[4096];
    size_t k;
    while ((k = fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, k);
    const int st = pclose(p);
    r.code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    FILE* e = fopen(errfile.c_str(), "r");
    while (e && (k = fread(buf, 1, sizeof buf, e)) > 0) r.err.append(buf, k);
    if (e) fclose(e);
    std::remove(errfile.c_str());
    return r;
}

// A random span's command line (components with 4 decimals, exactly representable steps not needed).
std::string random_args(std::mt19937_64& rng) {
    const SetupFormat sf = setup_format_config("ecp5");
    const SetupInput in = random_case(rng, sf, SpanKind(rng() % unsigned(SpanKind::count)), rng() % 1024, 12);
    std::ostringstream o;
    const int32_t* v[4] = {in.n1, in.n2, in.h1, in.h2};
    const char* names[4] = {"--n1", "--n2", "--h1", "--h2"};
    for (int i = 0; i < 4; ++i) {
        o << names[i] << " ";
        for (int k = 0; k < 3; ++k) o << (k ? "," : "") << std::ldexp(double(v[i][k]), -sf.vec_frac);
        o << " ";
    }
    o << "--n " << in.n << " --strength " << std::ldexp(double(in.strength), -sf.str_frac) << " --len " << in.l;
    return o.str();
}
}  // namespace

TEST(SetupCli, RtlEqualsGoldenCharacterForCharacter) {
    std::mt19937_64 rng(61);
    for (int i = 0; i < 12; ++i) {
        const std::string a = random_args(rng) + (i % 3 == 0 ? " --gamma midpoint" : "");
        for (const char* cfg : {"ecp5", "up5k"}) {
            const Result rtl = run(a + " --pixels --config " + cfg);
            const Result gold = run(a + " --pixels --model golden --config " + cfg);
            ASSERT_EQ(rtl.code, 0) << rtl.err;
            ASSERT_EQ(gold.code, 0) << gold.err;
            EXPECT_EQ(rtl.out, gold.out) << a << " --config " << cfg;
            EXPECT_EQ(rtl.out.rfind("c,zeta0,dzeta,n,l,flags\n", 0), 0u);
        }
    }
}

TEST(SetupCli, HostPrintsTheDoubleValues) {
    const Result r = run("--n1 0,0,1 --n2 0,0.1,1 --h1 0.05,0,1 --h2 0.1,0.05,1 --n 50 --strength 0.8 --len 7 --model host --pixels");
    ASSERT_EQ(r.code, 0) << r.err;
    std::istringstream is(r.out);
    std::string head, row, ph;
    std::getline(is, head);
    std::getline(is, row);
    double c, z0, dz;
    unsigned n, l, flags;
    ASSERT_EQ(std::sscanf(row.c_str(), "%lf,%lf,%lf,%u,%u,%u", &c, &z0, &dz, &n, &l, &flags), 6) << row;
    EXPECT_EQ(n, 50u);
    EXPECT_EQ(l, 7u);
    EXPECT_GT(c, 0.0);
    EXPECT_LT(c, 0.8);
    std::getline(is, ph);
    EXPECT_EQ(ph, "i,value");
    int rows = 0;
    for (std::string x; std::getline(is, x);) ++rows;
    EXPECT_EQ(rows, 8);
    // golden against host: the register codes are the host's values to the setup's precision
    const Result g = run("--n1 0,0,1 --n2 0,0.1,1 --h1 0.05,0,1 --h2 0.1,0.05,1 --n 50 --strength 0.8 --len 7 --model golden");
    std::istringstream gs(g.out);
    std::getline(gs, head);
    std::getline(gs, row);
    long long gc, gz, gd;
    ASSERT_EQ(std::sscanf(row.c_str(), "%lld,%lld,%lld", &gc, &gz, &gd), 3);
    EXPECT_NEAR(double(gc), c * 65536, 2.0);
    EXPECT_NEAR(std::ldexp(double(gz), -28), z0, 1e-5);
    EXPECT_NEAR(std::ldexp(double(gd), -28), dz, 1e-6);
}

TEST(SetupCli, HelpAndLibraryPieces) {
    const Result h = run("--help");
    EXPECT_EQ(h.code, 0);
    EXPECT_NE(h.out.find("--pixels"), std::string::npos);
    const Result bad = run("--n1 0,0,1 --n2 0,0,1 --h1 0,0,1 --h2 0,0,1 --n 3 --strength 1 --len 2 --config pipelined");
    EXPECT_EQ(bad.code, 2);
    EXPECT_NE(bad.err.find("unknown configuration 'pipelined' (ecp5, up5k)"), std::string::npos) << bad.err;
    const std::string flags = "specsim setup --n1 0,0,1 --n2 0,0,1 --h1 0,0.6,0.8 --h2 0,0.6,0.8 --n 3 --strength 1.5 --len 0";
    std::vector<std::string> words;
    std::istringstream is(flags);
    for (std::string w; is >> w;) words.push_back(w);
    std::vector<char*> argv;
    for (auto& w : words) argv.push_back(&w[0]);
    SetupOptions o = parse_setup(static_cast<int>(argv.size()), argv.data());
    EXPECT_EQ(o.in.strength, 49152u);
    EXPECT_EQ(o.in.h1[1], 9830);
    o.model = "golden";
    const SetupReport r = setup_compute(o);
    EXPECT_EQ(r.flags, unsigned(kSetupFlat | kSetupSinglePixel));
    EXPECT_EQ(setup_csv(o, r).substr(0, 24), "c,zeta0,dzeta,n,l,flags\n");
}
