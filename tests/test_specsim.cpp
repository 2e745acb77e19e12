// specsim as a user runs it: output format, model agreement, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "common.h"

using namespace spec::test;

TEST(Specsim, SpanRtlAndGoldenPrintTheSameCharacters) {
    const char* spans[] = {
        "--n 10 --c 0.75 --zeta0 -0.15 --dzeta 0.1 --len 3",
        "--n 0 --c 0.5 --zeta0 1 --dzeta 0.3 --len 5",
        "--n 1000 --c 0.99 --zeta0 -0.05 --dzeta 0.001 --len 100",
        "--n 1 --c 0.3 --zeta0 -3 --dzeta 0.06 --len 100",
        "--n 3 --c 0.123 --zeta0 7.9 --dzeta -1.9 --len 8",
    };
    for (const char* s : spans) {
        CliRun rtl = specsim(std::string("span ") + s);
        CliRun gold = specsim(std::string("span ") + s + " --model golden");
        CliRun stream = specsim(std::string("span ") + s + " --model stream");
        ASSERT_EQ(rtl.code, 0) << rtl.err;
        ASSERT_EQ(gold.code, 0) << gold.err;
        ASSERT_EQ(stream.code, 0) << stream.err;
        EXPECT_EQ(rtl.out, gold.out) << s;
        EXPECT_EQ(stream.out, rtl.out) << s;
        // LANES = 2, 4 and 4 packed print what spec_unit prints (issue 14)
        for (const char* lanes : {" --lanes 2", " --lanes 4", " --lanes 4 --pack"}) {
            CliRun wide = specsim(std::string("span ") + s + " --model stream" + lanes);
            ASSERT_EQ(wide.code, 0) << wide.err;
            EXPECT_EQ(wide.out, rtl.out) << s << lanes;
        }
        auto l = lines(rtl.out);
        ASSERT_GE(l.size(), 2u);
        EXPECT_EQ(l[0], "i,value");
        for (size_t i = 1; i < l.size(); ++i) {
            const auto comma = l[i].find(',');
            ASSERT_NE(comma, std::string::npos);
            EXPECT_EQ(std::stoul(l[i].substr(0, comma)), i - 1);
            const double v = std::stod(l[i].substr(comma + 1));
            EXPECT_GE(v, 0.0);
            EXPECT_LT(v, 1.0);
        }
    }
    CliRun r = specsim("span --n 10 --c 0.75 --zeta0 -0.15 --dzeta 0.1 --len 3");
    EXPECT_EQ(lines(r.out).size(), 5u) << "header and l + 1 rows";
}

TEST(Specsim, RefIsDoublePrecisionBlinnPhong) {
    CliRun r = specsim("span --n 10 --c 0.75 --zeta0 -0.15 --dzeta 0.1 --len 3 --model ref");
    ASSERT_EQ(r.code, 0) << r.err;
    auto l = lines(r.out);
    ASSERT_EQ(l.size(), 5u);
    for (int i = 0; i < 4; ++i) {
        const double ang = -0.15 + 0.1 * i;
        const double v = std::stod(l[i + 1].substr(l[i + 1].find(',') + 1));
        EXPECT_NEAR(v, 0.75 * std::pow(std::cos(ang), 10), 1e-15);
    }
    CliRun back = specsim("span --n 5 --c 0.5 --zeta0 2 --dzeta 0.5 --len 1 --model ref");
    EXPECT_NE(back.out.find("1,0.0000000000000000"), std::string::npos) << "max(0, cos) past pi/2";
}

TEST(Specsim, BadInputGetsOneLineAndExitCode2) {
    const std::string ok = "--c 0.5 --zeta0 0 --dzeta 0.1 --len 3";
    const char* bad[] = {
        "span --n 1024 --c 0.5 --zeta0 0 --dzeta 0.1 --len 3",
        "span --n -1 --c 0.5 --zeta0 0 --dzeta 0.1 --len 3",
        "span --n 1.5 --c 0.5 --zeta0 0 --dzeta 0.1 --len 3",
        "span --n 5 --c 1.0 --zeta0 0 --dzeta 0.1 --len 3",
        "span --n 5 --c -0.1 --zeta0 0 --dzeta 0.1 --len 3",
        "span --n 5 --c nan --zeta0 0 --dzeta 0.1 --len 3",
        "span --n 5 --c 0.5 --zeta0 inf --dzeta 0.1 --len 3",
        "span --n 5 --c 0.5 --zeta0 8 --dzeta 0.1 --len 3",
        "span --n 5 --c 0.5 --zeta0 0 --dzeta 0.1 --len 65536",
        "span --n 5 --c 0.5 --zeta0 0 --dzeta 0.1 --len -1",
        "span --n 5 --c 0.5 --zeta0 7 --dzeta 0.5 --len 3",   // last angle 8.5 leaves the format
        "span --n 5 --c 0.5 --zeta0 0 --dzeta 0.1 --len 3 --model fast",
        "span --n 5 --c 0.5 --zeta0 0 --dzeta 0.1 --len 3 --frobnicate 1",
        "span --n 5 --c 0.5 --zeta0 0 --dzeta 0.1 --len",
        "span --n --c 0.5 --zeta0 0 --dzeta 0.1 --len 3",
        "span --c 0.5 --zeta0 0 --dzeta 0.1 --len 3",
        "span --n 5 --c abc --zeta0 0 --dzeta 0.1 --len 3",
        "span --n 5 --c 0.5 --zeta0 0 --dzeta 0.1 --len 3 extra",
        "frobnicate",
        "",
        "vectors --spans 3",
        // control characters in a value stay inside the one line (escaped: \n, \t, \xNN; found by make fuzz)
        "span --n '1\n2' --c 0.5 --zeta0 0 --dzeta 0.1 --len 3",
        "span --n 5 --c 0.5 --zeta0 0 --dzeta 0.1 --len 3 --model 'a\tb\x01\r\n'",
    };
    for (const char* b : bad) {
        CliRun r = specsim(b);
        EXPECT_EQ(r.code, 2) << b;
        EXPECT_TRUE(r.out.empty()) << b << ": " << r.out;
        auto l = lines(r.err);
        EXPECT_EQ(l.size(), 1u) << b << ": " << r.err;
        if (!l.empty()) EXPECT_EQ(l[0].rfind("specsim: ", 0), 0u) << l[0];
    }
    EXPECT_NE(specsim("span --n '1\n2' " + ok).err.find("'1\\n2' is not an integer"), std::string::npos);
    EXPECT_EQ(specsim("span --n 5 " + ok).code, 0);
    EXPECT_EQ(specsim("span --n 5 --c 0.5 --zeta0 -8 --dzeta 0 --len 3").code, 0) << "-8 is the format's minimum";
}

TEST(Specsim, Fig8PrintsTheRecomputedTable) {
    CliRun r = specsim("fig8");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("Fig. 8 recomputed"), std::string::npos);
    EXPECT_NE(r.out.find("n = 3..6"), std::string::npos);
    EXPECT_EQ(lines(r.out).size() > 20, true);
}
