// Double-precision analysis of the approximation (the patent's Fig. 5/8/10 numbers, recomputed).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

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

namespace {
// An independent computation of q(n, k) for Fig. 8 (nothing from analysis.h or fit.h): the relative error
// e(d) = cos^k(s d) / cos^n(d) - 1, s = sqrt(n/k), in the log domain g(d) = k ln cos(s d) - n ln cos d. Its
// extremes on [0, D] (D = the epicentre's end, the inflection point atan(1/sqrt(n - 1)), pi/3 for n = 1) lie
// at D or where g'(d) = n tan d - k s tan(s d) = 0: the roots are bracketed on a grid and bisected, so the
// worst error is found analytically rather than by maximizing samples (analysis.cpp's way).
double q_independent(int n, int k) {
    if (n == k) return 0.0;
    const double pi = std::acos(-1.0);
    const double D = n == 1 ? pi / 3 : std::atan(1.0 / std::sqrt(double(n) - 1.0));
    const double s = std::sqrt(double(n) / k);
    auto e = [&](double d) {
        if (s * d >= pi / 2) return -1.0;   // past the table's pi/2: the core outputs 0
        return std::expm1(k * std::log(std::cos(s * d)) - n * std::log(std::cos(d)));
    };
    auto dg = [&](double d) { return n * std::tan(d) - k * s * std::tan(s * d); };
    double q = std::fabs(e(D));
    const int grid = 256;
    for (int i = 0; i < grid; ++i) {
        double a = D * i / grid, b = D * (i + 1) / grid;
        if (i == 0) a = D * 1e-9;   // g'(0) = 0 for every n, k: step off it
        if (s * b >= pi / 2 || (dg(a) > 0) == (dg(b) > 0)) continue;
        for (int it = 0; it < 200 && b - a > 1e-15; ++it) {
            const double mid = 0.5 * (a + b);
            ((dg(mid) > 0) == (dg(a) > 0) ? a : b) = mid;
        }
        q = std::max(q, std::fabs(e(0.5 * (a + b))));
    }
    return q;
}
}  // namespace

// All 16 rows of the recomputed Fig. 8 (the n in 1..1000 that each table cos^k serves within 1 %) against the
// independent computation above: smallest and largest n, their count and whether they are contiguous.
TEST(Analysis, Fig8AllSixteenRowsAgreeWithAnIndependentComputation) {
    const auto rows = fig8(0.01);
    ASSERT_EQ(rows.size(), 16u);
    int near_limit = 0;
    for (int k = 1; k <= 16; ++k) {
        Fig8Row want{k, 0, 0, true, 0};
        int last = 0;
        for (int n = 1; n <= 1000; ++n) {
            const double q = q_independent(n, k);
            if (std::fabs(q - 0.01) < 1e-9) ++near_limit;   // the two computations could part here
            if (q > 0.01) continue;
            if (want.count == 0) want.n_lo = n;
            else if (n != last + 1) want.contiguous = false;
            want.n_hi = n;
            last = n;
            ++want.count;
        }
        const Fig8Row& got = rows[size_t(k - 1)];
        const std::string row = "k = " + std::to_string(k);
        EXPECT_EQ(got.k, k);
        EXPECT_EQ(got.n_lo, want.n_lo) << row;
        EXPECT_EQ(got.n_hi, want.n_hi) << row;
        EXPECT_EQ(got.count, want.count) << row;
        EXPECT_EQ(got.contiguous, want.contiguous) << row;
    }
    EXPECT_EQ(near_limit, 0) << "an n within 1e-9 of the 1 % limit: compare those rows by hand";
    // the two computations of q agree to 1e-9 of the limit wherever it matters (spot checks across the range)
    for (int k : {1, 2, 4, 7, 16})
        for (int n : {1, 3, 6, 17, 105, 1000}) EXPECT_NEAR(q_independent(n, k), q_error(unsigned(n), k), 1e-9) << n << " " << k;
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
