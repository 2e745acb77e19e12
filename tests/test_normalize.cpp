// Companion paper B: adaptive normalization. The paper's formulas against the vectors themselves, the halving
// against slerp, the adaptive method within its bounds, and the Phong path's images.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "normalize.h"
#include "raster.h"
#include "scene.h"
#include "span_host.h"
#include "stats.h"

using namespace spec;
using namespace spec::methods;

namespace {
constexpr double kPi = 3.14159265358979323846;

NVec unit_at(double psi) { return NVec(std::sin(psi), 0.0, std::cos(psi)); }

NVec random_unit(std::mt19937_64& rng) {
    std::normal_distribution<double> g(0.0, 1.0);
    return glm::normalize(NVec(g(rng), g(rng), g(rng)));
}

// b at angle psi from a, in a random direction
NVec rotate_from(std::mt19937_64& rng, const NVec& a, double psi) {
    const NVec p = glm::normalize(glm::cross(a, random_unit(rng)));
    return glm::normalize(a * std::cos(psi) + p * std::sin(psi));
}
}  // namespace

// eq. (2): the deficit of the plain average of two unit vectors psi / 2^(i-1) apart, measured on the vectors;
// eq. (1): z by the recursion equals |Na + Nb| of the segments at each halving level.
TEST(Normalize, DeviationAndZRecursionAgainstTheVectors) {
    for (double deg = 1; deg <= 179; deg += 2) {
        const double psi = deg * kPi / 180;
        for (int i = 1; i <= 6; ++i) {
            const double seg = psi / std::ldexp(1.0, i - 1);
            const double measured = 1.0 - glm::length(0.5 * (unit_at(0) + unit_at(seg)));
            EXPECT_NEAR(deviation(psi, i), measured, 1e-14) << deg << " " << i;
            EXPECT_NEAR(z_level(psi, i), glm::length(unit_at(0) + unit_at(seg)), 1e-12) << deg << " " << i;
        }
    }
}

TEST(Normalize, ThePapersFigures) {
    const double deg = kPi / 180;
    EXPECT_NEAR(angle_for_deviation(0.01) / deg, 16.2, 0.05);  // "1 % at 16 degrees"
    EXPECT_NEAR(angle_for_deviation(0.04) / deg, 32.5, 0.05);  // "4 % at 32 degrees"
    EXPECT_NEAR(deviation(90 * deg, 1), 0.2929, 1e-4);        // "0.293 at cos psi -> 0"
    EXPECT_NEAR(deviation(kPi, 1), 1.0, 1e-12);               // but psi can be larger
    double rmin = 10;
    for (int k = 1; k <= 1800; ++k) {
        const double r = deviation(k * 0.1 * deg, 1) / deviation(k * 0.1 * deg, 2);
        EXPECT_LT(r, 4.0);
        rmin = std::min(rmin, r);
    }
    EXPECT_NEAR(rmin, 2 + std::sqrt(2.0), 1e-9);  // 4 cos^2(22.5 deg) = 3.414 at psi = 180 deg: "3.4 to 4"
    // the specular rule: at the bound the midpoint's (z/2)^n is exactly 1 - ds
    for (unsigned n : {1u, 10u, 100u}) {
        const double c = specular_cos_bound(0.01, n);
        EXPECT_NEAR(std::pow(std::sqrt((1 + c) / 2), double(n)), 0.99, 1e-12);
    }
}

// Halving to every pixel is spherical interpolation toward the extended end: normalize(N1 + (N2 - N1) 2^k / l).
TEST(Normalize, HalvingIsSlerpTowardTheExtendedEnd) {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    SpanVectors v;
    for (int k = 0; k < 500; ++k) {
        const NVec n1 = random_unit(rng), h1 = random_unit(rng);
        const NVec n2 = rotate_from(rng, n1, 1.2 * u01(rng)), h2 = rotate_from(rng, h1, 0.3 * u01(rng));
        const uint32_t l = 2 + uint32_t(u01(rng) * 200);
        NormOps ops;
        interpolate_span(n1, n2, h1, h2, l, NormMode::halving, NormBounds(), 10, &v, &ops);
        ASSERT_EQ(v.n.size(), size_t(l) + 1);
        uint32_t L2 = 1;
        while (L2 < l) L2 <<= 1;
        const NVec e = glm::normalize(n1 + (n2 - n1) * (double(L2) / l));
        for (uint32_t i = 0; i < l; ++i) {
            EXPECT_LT(glm::length(v.n[i] - host::slerp(n1, e, double(i) / L2)), 1e-12) << k << " " << i;
        }
        EXPECT_EQ(v.n[l], n2);
        EXPECT_EQ(ops.lerped, 0u);
        EXPECT_EQ(ops.vectors, 2 * (uint64_t(l) + 1));
    }
}

// The adaptive method keeps its promise on every vector: |N| >= 1 - dd (the diffuse term's relative error
// against the normalized vector) and (|N| |H|)^n >= 1 - ds; and it normalizes far fewer vectors than full.
TEST(Normalize, AdaptiveWithinItsBounds) {
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    SpanVectors v;
    NormOps full_ops, ad_ops;
    for (int k = 0; k < 3000; ++k) {
        const NormBounds b{0.002 + 0.05 * u01(rng), 0.002 + 0.05 * u01(rng)};
        const unsigned n = 1 + unsigned(u01(rng) * 300);
        const NVec n1 = random_unit(rng), h1 = random_unit(rng);
        const NVec n2 = rotate_from(rng, n1, 1.5 * u01(rng)), h2 = rotate_from(rng, h1, 0.2 * u01(rng));
        const uint32_t l = uint32_t(u01(rng) * 300);
        interpolate_span(n1, n2, h1, h2, l, NormMode::full, b, n, &v, &full_ops);
        interpolate_span(n1, n2, h1, h2, l, NormMode::adaptive, b, n, &v, &ad_ops);
        for (uint32_t i = 0; i <= l; ++i) {
            const double ln = glm::length(v.n[i]), lh = glm::length(v.h[i]);
            ASSERT_GE(ln, 1 - b.diffuse - 1e-12) << k << " " << i;
            ASSERT_GE(std::pow(ln * lh, double(n)), 1 - b.specular - 1e-9) << k << " " << i;
            ASSERT_LE(ln, 1 + 1e-12);
        }
    }
    EXPECT_LT(ad_ops.normalized + ad_ops.halved, full_ops.normalized / 2);
}

// The Phong path: adaptive within a few levels of full normalization on the default scene, and far closer to it
// than no normalization at all would be (bounds 0.5: lerp whole spans).
TEST(Normalize, PhongImagesAdaptiveCloseToFull) {
    const render::Scene sc = render::make_scene("default");
    const render::Frame fr = render::rasterize(sc, 200, 200);
    std::vector<uint8_t> covered(size_t(fr.w) * size_t(fr.h), 1);
    const PhongRun full = shade_phong(sc, fr, NormMode::full, NormBounds());
    const PhongRun ad = shade_phong(sc, fr, NormMode::adaptive, NormBounds());
    const PhongRun loose = shade_phong(sc, fr, NormMode::adaptive, NormBounds{0.49, 0.49});
    const render::ImageStats s = render::compare(ad.img, full.img, covered);
    const render::ImageStats sl = render::compare(loose.img, full.img, covered);
    EXPECT_LE(s.max_abs, 4);
    EXPECT_GT(sl.max_abs, 2 * s.max_abs);
    EXPECT_LT(ad.ops.normalized + ad.ops.halved, full.ops.normalized);
}
