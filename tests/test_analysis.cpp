// Double-precision analysis of the approximation (the patent's Fig. 5/8/10 numbers, recomputed).
#include <gtest/gtest.h>

#include <cmath>

#include "analysis.h"
#include "spec_format.h"

using namespace spec;

TEST(Analysis, EpicentreIsTheInflectionPoint) {
    for (unsigned n = 2; n < 50; ++n) {
        const double d = epicentre_end(n);
        // second derivative of cos^n changes sign at d: n(n-1)cos^(n-2) sin^2 - n cos^n = 0
        const double s = std::sin(d), c = std::cos(d);
        EXPECT_NEAR((n - 1) * s * s, c * c, 1e-12) << n;
    }
    EXPECT_DOUBLE_EQ(epicentre_end(1), M_PI / 3.0);
}

TEST(Analysis, ExactWhereKEqualsN) {
    EXPECT_LT(q_error(1, 1), 1e-15);
    EXPECT_LT(q_error(2, 2), 1e-15);
    EXPECT_LT(q_error(4, 4), 1e-15);
    EXPECT_LT(q_error(16, 16), 1e-15);
    EXPECT_LT(a_error(16, 16), 1e-15);
}

TEST(Analysis, PatentClaimIsNotQuiteTrue) {
    // The digest's section 6: about 1.09 % at n = 3 (k = 4), about 0.88 % at n = 6, 0.60 % from n = 8 on.
    const double q3 = q_error(3, 4);
    EXPECT_GT(q3, 0.0105);
    EXPECT_LT(q3, 0.0112);
    EXPECT_GT(q_error(6, 4), 0.0080);
    EXPECT_LT(q_error(6, 4), 0.0095);
    for (unsigned n = 8; n <= 1000; n += 7) EXPECT_LE(q_error(n, 16), 0.0061) << n;
}

TEST(Analysis, ErrorsAgreeWithBruteForce) {
    // A plain dense scan never finds more than the maximizer does (and nearly the same).
    for (unsigned n : {3u, 5u, 7u, 10u, 100u, 1000u}) {
        const int k = k_of_n(n);
        double q = 0, a = 0;
        for (int i = 0; i <= 200000; ++i) {
            const double d = epicentre_end(n) * i / 200000.0;
            const double ref = std::pow(std::cos(d), n);
            q = std::max(q, std::fabs(approx(n, k, d) - ref) / ref);
            const double d2 = (M_PI / 2) * i / 200000.0;
            a = std::max(a, std::fabs(approx(n, k, d2) - std::pow(std::cos(d2), n)));
        }
        EXPECT_LE(q, q_error(n, k) * (1 + 1e-9)) << n;
        EXPECT_GE(q, q_error(n, k) * (1 - 1e-4)) << n;
        EXPECT_LE(a, a_error(n, k) * (1 + 1e-9)) << n;
        EXPECT_GE(a, a_error(n, k) * (1 - 1e-3)) << n;
    }
}

TEST(Analysis, Fig8Recomputed) {
    auto rows = fig8(0.01);
    ASSERT_EQ(rows.size(), 16u);
    EXPECT_EQ(rows[0].n_lo, 1);   // k = 1: only n = 1
    EXPECT_EQ(rows[0].n_hi, 1);
    EXPECT_EQ(rows[1].n_lo, 2);   // k = 2: only n = 2
    EXPECT_EQ(rows[1].n_hi, 2);
    EXPECT_EQ(rows[15].n_hi, 1000);  // k = 16 covers the top of the range
    EXPECT_GE(rows[15].n_lo, 7);
    // k = 4 does not cover n = 3 within 1 % (1.09 %)
    EXPECT_GT(rows[3].n_lo, 3);
}
