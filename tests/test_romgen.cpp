// ROM generator: contents, range checks, headers.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "romgen.h"
#include "spec_params.h"  // the committed header (rom/)

using namespace spec;

TEST(RomGen, CommittedHeaderMatchesDefinitions) {
    const Format f;
    EXPECT_EQ(spec_params::C_W, f.c_w);
    EXPECT_EQ(spec_params::ANG_W, f.ang_w);
    EXPECT_EQ(spec_params::ANG_FRAC, f.ang_frac);
    EXPECT_EQ(spec_params::N_W, f.n_w);
    EXPECT_EQ(spec_params::L_W, f.l_w);
    EXPECT_EQ(spec_params::OUT_W, f.out_w);
    EXPECT_EQ(spec_params::SCALE_W, f.scale_w);
    EXPECT_EQ(spec_params::SCALE_FRAC, f.scale_frac);
    EXPECT_EQ(spec_params::TBL_AW, f.tbl_aw);
    EXPECT_EQ(spec_params::TBL_FRAC, f.tbl_frac);
}

TEST(RomGen, Rom9HoldsScaledSqrtNOverK) {
    const Format f;
    auto r9 = make_rom9(f);
    ASSERT_EQ(r9.size(), 1024u);
    EXPECT_EQ(r9[0], 0u);  // n = 0: cos^0 = 1 through table position 0
    for (unsigned n = 1; n < 1024; ++n) {
        const double exact = std::sqrt(double(n) / k_of_n(n)) * 2.0 / M_PI;
        EXPECT_NEAR(std::ldexp(double(r9[n]), -f.scale_frac), exact, std::ldexp(0.5, -f.scale_frac)) << n;
        EXPECT_LT(r9[n], 1u << f.scale_w);
    }
    // Fig. 14: n = 1 -> sqrt(1/1), 2 -> sqrt(2/2), 3 -> sqrt(3/4), 7 -> sqrt(7/16)
    EXPECT_EQ(r9[1], r9[2]);
    EXPECT_EQ(r9[4], r9[1]);
    EXPECT_EQ(r9[16], r9[1]);
    EXPECT_LT(r9[3], r9[1]);
}

TEST(RomGen, Rom12HoldsFourCosinePowerTables) {
    const Format f;
    auto r12 = make_rom12(f);
    const size_t per = size_t(1) << f.tbl_aw;
    ASSERT_EQ(r12.size(), 4 * per);
    for (int t = 0; t < 4; ++t) {
        EXPECT_EQ(r12[t * per], 1u << f.tbl_frac) << "cos^k(0) = 1 exactly";
        for (size_t i = 1; i < per; ++i) {
            EXPECT_LE(r12[t * per + i], r12[t * per + i - 1]) << "monotone";
            const double x = double(i) * M_PI / 2.0 / double(per);
            EXPECT_NEAR(std::ldexp(double(r12[t * per + i]), -f.tbl_frac), std::pow(std::cos(x), kTables[t]),
                        std::ldexp(0.5, -f.tbl_frac));
        }
    }
}

TEST(RomGen, Fig10Rule) {
    EXPECT_EQ(k_of_n(1), 1);
    EXPECT_EQ(k_of_n(2), 2);
    for (unsigned n = 3; n <= 6; ++n) EXPECT_EQ(k_of_n(n), 4);
    for (unsigned n = 7; n <= 1023; ++n) EXPECT_EQ(k_of_n(n), 16);
    EXPECT_EQ(k_of_n(0), 16);
}

TEST(RomGen, RangeChecked) {
    EXPECT_THROW(hex_image({0x1ffff}, 16, "X"), std::out_of_range);
    EXPECT_EQ(hex_image({0xffff, 0x1}, 16, "X"), "ffff\n0001\n");
    Format f;
    f.scale_w = 17;  // 5.09 no longer fits 2 integer bits
    EXPECT_THROW(f.validate(), std::invalid_argument);
    Format g;
    g.out_w = 12;
    EXPECT_THROW(g.validate(), std::invalid_argument);
}

TEST(RomGen, TableSizeIsAParameter) {
    Format f;
    f.tbl_aw = 8;
    auto r12 = make_rom12(f);
    EXPECT_EQ(r12.size(), 4u << 8);
    const std::string dir = ::testing::TempDir();
    write_all(f, dir, "rom/");
    std::ifstream vh(dir + "/spec_params.vh");
    std::stringstream ss;
    ss << vh.rdbuf();
    EXPECT_NE(ss.str().find("`define SPEC_TBL_AW 8"), std::string::npos);
    std::ifstream hx(dir + "/rom12_cosk.hex");
    int lines = 0;
    std::string first;
    for (std::string l; std::getline(hx, l);) {
        if (first.empty()) first = l;
        else ++lines;
    }
    EXPECT_EQ(lines, 4 << 8);
    // the first line names the parameters the image was made for (the RTL reads it back at time 0)
    EXPECT_EQ(first, rom12_header(f));
    EXPECT_NE(first.find("tbl_aw=8 tsel_w=2 tbl_frac=16 interp=0"), std::string::npos);
}
