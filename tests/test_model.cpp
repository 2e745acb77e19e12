// The bit-exact model on its own: properties that follow from the formats.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "spec_model.h"

using namespace spec;

TEST(Model, NZeroGivesCExactly) {
    const Model m;
    std::mt19937 rng(1);
    for (int i = 0; i < 2000; ++i) {
        const uint32_t c = rng() & 0xffff;
        const int64_t a = static_cast<int32_t>(rng());
        EXPECT_EQ(m.pixel(c, a, 0), c);
    }
}

TEST(Model, EvenInTheAngle) {
    const Model m;
    std::mt19937 rng(2);
    for (int i = 0; i < 5000; ++i) {
        const int64_t a = static_cast<int32_t>(rng() | 1);
        const unsigned n = rng() % 1024;
        EXPECT_EQ(m.pixel(0xffff, a, n), m.pixel(0xffff, -a, n));
    }
}

TEST(Model, ZeroPastQuarterTurn) {
    const Model m;
    for (unsigned n = 1; n < 1024; ++n) {
        const double s = std::sqrt(double(n) / k_of_n(n));
        const double edge = (M_PI / 2) / s;  // the angle where sqrt(n/k) * angle = pi/2
        if (edge * (1 + 1e-4) < 7.99) {
            EXPECT_EQ(m.pixel(0xffff, m.quantize_angle(edge * (1 + 1e-4)), n), 0u) << n;
            EXPECT_EQ(m.pixel(0xffff, m.quantize_angle(-edge * (1 + 1e-4)), n), 0u) << n;
        }
        EXPECT_EQ(m.pixel(0xffff, m.angle_min(), n), 0u) << n;
        EXPECT_EQ(m.pixel(0xffff, m.angle_max(), n), 0u) << n;
        EXPECT_GT(m.pixel(0xffff, m.quantize_angle(edge * 0.5), n), 0u) << n;
        if (k_of_n(n) == 1) EXPECT_GT(m.pixel(0xffff, m.quantize_angle(edge * 0.999), n), 0u) << n;
    }
}

TEST(Model, AccumulatorSaturates) {
    const Model m;
    EXPECT_EQ(m.accumulate(m.angle_max(), 1), m.angle_max());
    EXPECT_EQ(m.accumulate(m.angle_min(), -1), m.angle_min());
    EXPECT_EQ(m.accumulate(m.angle_max() - 5, 3), m.angle_max() - 2);
    EXPECT_EQ(m.accumulate(-7, 3), -4);
    SpanRegs r{0x8000, 1 << 28, 6 << 28, 10, 4};
    auto a = m.angles(r);
    ASSERT_EQ(a.size(), 5u);
    EXPECT_EQ(a[0], int64_t(6) << 28);
    EXPECT_EQ(a[1], int64_t(7) << 28);
    EXPECT_EQ(a[2], m.angle_max());
    EXPECT_EQ(a[4], m.angle_max());
}

TEST(Model, SpanHasLPlusOnePixels) {
    const Model m;
    for (uint32_t l : {0u, 1u, 3u, 100u}) EXPECT_EQ(m.span(SpanRegs{1, 0, 0, 5, l}).size(), l + 1);
}

TEST(Model, QuantizationChecksRange) {
    const Model m;
    EXPECT_EQ(m.quantize_c(0.5), 0x8000u);
    EXPECT_EQ(m.quantize_c(0.9999999), 0xffffu);  // rounds up to 1.0: the largest code
    EXPECT_THROW(m.quantize_c(1.0), std::out_of_range);
    EXPECT_THROW(m.quantize_c(-0.1), std::out_of_range);
    EXPECT_THROW(m.quantize_c(NAN), std::out_of_range);
    EXPECT_EQ(m.quantize_angle(-1.0), -(int64_t(1) << 28));
    EXPECT_THROW(m.quantize_angle(8.0), std::out_of_range);
    EXPECT_NO_THROW(m.quantize_angle(-8.0));
    EXPECT_THROW(m.quantize_angle(INFINITY), std::out_of_range);
}
