// boardsim's command line: bad input gets one line on stderr and exit code 2, --help exit 0, gen writes the
// committed tables.
#include <gtest/gtest.h>

#include <algorithm>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace {

struct Out {
    int rc = -1;
    std::string err;
};

Out run(const std::string& args) {
    const std::string cmd = std::string(BOARDSIM_PATH) + " " + args + " 2>&1 >/dev/null";
    Out o;
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return o;
    std::array<char, 512> buf{};
    while (fgets(buf.data(), int(buf.size()), p)) o.err += buf.data();
    const int st = pclose(p);
    o.rc = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    return o;
}

}  // namespace

TEST(BoardsimCli, BadInputOneLineExitTwo) {
    const char* cases[] = {
        "",                                              // no command
        "frobnicate",                                    // unknown command
        "run",                                           // no --board
        "run --board de0",                               // unknown board
        "run --board ulx3s --mode 800x600",              // unknown mode
        "run --board icebreaker --mode 1280x720",        // the iCEBreaker has no 720p design
        "run --board ulx3s --frames 0",                  // out of range
        "run --board ulx3s --frames x",                  // not a number
        "run --board ulx3s --out-dir /nonexistent/dir",  // no such directory
        "run --board ulx3s --frames",                    // missing value
        "split --k 0",                                   // out of range
        "split --shader exact",                          // unknown shader
        "gen",                                           // --out-dir missing
        "gen --out-dir /nonexistent/dir",
    };
    for (const char* c : cases) {
        const Out o = run(c);
        EXPECT_EQ(o.rc, 2) << c;
        if (std::string(c).empty()) continue;    // (the usage text)
        EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << c << ": " << o.err;
        EXPECT_EQ(o.err.rfind("boardsim: ", 0), 0u) << c << ": " << o.err;
    }
    EXPECT_EQ(run("--help").rc, 0);
    EXPECT_EQ(run("run --help").rc, 0);
}
