// Companion paper A: the highlight-in-triangle test, the N.H bound behind --cull-specular, the core bound it
// relies on, and culling in the renderer (no pixel may change). Also the three subcommands as a user runs
// them (tables printed, bad input: one line on stderr, exit 2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "common.h"
#include "highlight.h"
#include "raster.h"
#include "scene.h"
#include "shade.h"
#include "span_host.h"

using namespace spec;
using namespace spec::methods;
using spec::test::CliRun;
using spec::test::specsim;

namespace {
constexpr double kPi = 3.14159265358979323846;

Vec on_sphere(std::mt19937_64& rng) {
    std::normal_distribution<double> g(0.0, 1.0);
    for (;;) {
        const Vec v(g(rng), g(rng), g(rng));
        if (glm::length(v) > 1e-6) return glm::normalize(v);
    }
}

Vec in_cap(std::mt19937_64& rng, const Vec& c, double r) {
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const double ca = 1.0 - u01(rng) * (1.0 - std::cos(r));
    const double sa = std::sqrt(std::max(0.0, 1.0 - ca * ca));
    const double phi = 2 * kPi * u01(rng);
    const Vec p = host::perpendicular(c), q = glm::cross(c, p);
    return glm::normalize(c * ca + (p * std::cos(phi) + q * std::sin(phi)) * sa);
}

// A point of the spherical triangle with barycentric-like weights w (normalized convex combination).
Vec in_tri(const Vec t[3], const double w[3]) { return glm::normalize(t[0] * w[0] + t[1] * w[1] + t[2] * w[2]); }

void weights(std::mt19937_64& rng, double w[3]) {
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    double a = u01(rng), b = u01(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    w[0] = a, w[1] = b, w[2] = 1 - a - b;
}

double angle(const Vec& a, const Vec& b) { return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)); }

}  // namespace

// The exact test against solving H = a NA + b NB + c NC: inside iff a, b, c >= 0.
TEST(Highlight, SphericalInsideMatchesBarycentricSolve) {
    std::mt19937_64 rng(1);
    int inside = 0, checked = 0;
    for (int k = 0; k < 20000; ++k) {
        const double r = (0.5 + 40.0 * (k % 10) / 9.0) * kPi / 180;
        const Vec c = on_sphere(rng);
        const Vec n[3] = {in_cap(rng, c, r), in_cap(rng, c, r), in_cap(rng, c, r)};
        const Vec h = in_cap(rng, c, 0.6 * r);
        const glm::dmat3 m(n[0], n[1], n[2]);
        if (std::fabs(glm::determinant(m)) < 1e-14) continue;
        const Vec w = glm::inverse(m) * h;
        if (std::min({std::fabs(w.x), std::fabs(w.y), std::fabs(w.z)}) < 1e-9) continue;  // on an edge
        const bool want = w.x > 0 && w.y > 0 && w.z > 0;
        ASSERT_EQ(spherical_inside(n[0], n[1], n[2], h), want) << k;
        inside += want;
        ++checked;
    }
    EXPECT_GT(checked, 19000);
    EXPECT_GT(inside, checked / 20);
    EXPECT_LT(inside, checked * 9 / 10);
}

TEST(Highlight, BoundingConeContainsTheSphericalTriangle) {
    std::mt19937_64 rng(2);
    for (int k = 0; k < 3000; ++k) {
        const double r = (0.1 + 80.0 * (k % 20) / 19.0) * kPi / 180;
        const Vec c = on_sphere(rng);
        const Vec t[3] = {in_cap(rng, c, r), in_cap(rng, c, r), in_cap(rng, c, r)};
        const Cone cone = bounding_cone(t[0], t[1], t[2]);
        if (!cone.valid) continue;
        EXPECT_LE(cone.radius, r + 1e-9);  // never larger than the cap the points came from
        for (int j = 0; j < 100; ++j) {
            double w[3];
            weights(rng, w);
            ASSERT_LE(angle(in_tri(t, w), cone.axis), cone.radius) << k;
        }
    }
}

// The bound against brute force: N.H at points of both triangles, and the host's sinusoid on random spans whose
// end vectors lie in them (the renderer's spans do: spherical interpolation keeps them inside).
TEST(Highlight, TriangleBoundHoldsForPointsAndHostSinusoid) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const Model core;
    double tightest = 1;
    for (int k = 0; k < 3000; ++k) {
        const Vec cn = on_sphere(rng);
        const Vec ch = in_cap(rng, cn, (10 + 110 * u01(rng)) * kPi / 180);
        const double rn = (0.3 + 15 * u01(rng)) * kPi / 180, rh = (0.05 + 4 * u01(rng)) * kPi / 180;
        const Vec n[3] = {in_cap(rng, cn, rn), in_cap(rng, cn, rn), in_cap(rng, cn, rn)};
        const Vec h[3] = {in_cap(rng, ch, rh), in_cap(rng, ch, rh), in_cap(rng, ch, rh)};
        const TriangleBound b = triangle_bound(n, h);
        ASSERT_TRUE(b.valid);
        double worst = -2;
        for (int j = 0; j < 60; ++j) {
            double w1[3], w2[3];
            weights(rng, w1);
            weights(rng, w2);
            worst = std::max(worst, glm::dot(in_tri(n, w1), in_tri(h, w2)));
        }
        ASSERT_LE(worst, b.nh_max + 1e-12) << k;
        tightest = std::min(tightest, b.nh_max - worst);
        for (int j = 0; j < 5; ++j) {
            double w1[3], w2[3];
            weights(rng, w1);
            weights(rng, w2);
            const host::SpanEnds e{in_tri(n, w1), in_tri(n, w2), in_tri(h, w1), in_tri(h, w2)};
            const uint32_t l = 1 + uint32_t(u01(rng) * 60);
            const host::SpanSetup s = host::setup_span(core, e, 0.5, 10, l);
            for (uint32_t i = 0; i <= l; ++i) {
                const double sin_val = (s.flags & host::kFlat) ? s.a : s.a * std::cos(s.zeta0 + i * s.dzeta);
                ASSERT_LE(sin_val, b.b_host) << k;
            }
        }
    }
    EXPECT_LT(tightest, 0.01);  // the bound is not trivially loose
}

// The core's output is non-increasing in |angle| and non-decreasing in C: what core_output_sup relies on.
TEST(Highlight, CoreOutputMonotone) {
    const Model m;
    const Format& f = m.format();
    const uint32_t cmax = (1u << f.c_w) - 1;
    for (unsigned n : {1u, 2u, 3u, 4u, 6u, 7u, 10u, 100u, 1000u, 1023u}) {
        uint32_t prev = m.pixel(cmax, 0, n);
        for (int64_t raw = 0; raw < m.quantize_angle(3.2); raw += 1 << 14) {
            const uint32_t v = m.pixel(cmax, raw, n);
            ASSERT_LE(v, prev) << "n = " << n << " raw angle " << raw;
            ASSERT_EQ(v, m.pixel(cmax, -raw, n));
            prev = v;
        }
        for (int64_t raw : {int64_t(0), m.quantize_angle(0.05), m.quantize_angle(0.3), m.quantize_angle(1.0)}) {
            uint32_t p = 0;
            for (uint32_t c = 0; c <= cmax; c += 97) {
                const uint32_t v = m.pixel(c, raw, n);
                ASSERT_GE(v, p) << "n = " << n;
                p = v;
            }
        }
    }
}

// core_output_sup bounds what the bit-exact core outputs on spans inside a triangle with that bound.
TEST(Highlight, CoreOutputSupBoundsTheCore) {
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const Model core;
    const unsigned ns[] = {1, 2, 3, 5, 10, 30, 100, 1000};
    for (int k = 0; k < 1500; ++k) {
        const unsigned n = ns[k % 8];
        const double strength = 0.3 + 0.7 * u01(rng);
        const Vec cn = on_sphere(rng);
        const Vec ch = in_cap(rng, cn, (2 + 60 * u01(rng)) * kPi / 180);
        const double rn = (0.3 + 8 * u01(rng)) * kPi / 180, rh = 0.5 * kPi / 180;
        const Vec nv[3] = {in_cap(rng, cn, rn), in_cap(rng, cn, rn), in_cap(rng, cn, rn)};
        const Vec hv[3] = {in_cap(rng, ch, rh), in_cap(rng, ch, rh), in_cap(rng, ch, rh)};
        const TriangleBound b = triangle_bound(nv, hv);
        const uint32_t sup = core_output_sup(core, n, strength, b.b_host, 64);
        for (int j = 0; j < 4; ++j) {
            double w1[3], w2[3];
            weights(rng, w1);
            weights(rng, w2);
            const host::SpanEnds e{in_tri(nv, w1), in_tri(nv, w2), in_tri(hv, w1), in_tri(hv, w2)};
            const uint32_t l = uint32_t(u01(rng) * 64);
            const host::SpanSetup s = host::setup_span(core, e, strength, n, l);
            for (uint32_t v : core.span(s.regs)) ASSERT_LE(v, sup) << "n = " << n << " k = " << k;
        }
    }
}

TEST(Highlight, CullThresholds) {
    const Model m;
    // n = 1000, Is ks = 0.8: 0.8 A^1000 < 2^-17 from A < 0.98851; the threshold is a little lower (table error)
    const double t = cull_threshold(m, 1000, 0.8, 512);
    EXPECT_GT(t, 0.97);
    EXPECT_LT(t, std::pow(std::ldexp(1.0, -17) / 0.8, 1.0 / 1000));
    // n = 3 (cos^4(sqrt(3/4) x) reaches past pi/2): only triangles facing away from H are safe
    EXPECT_EQ(cull_threshold(m, 3, 0.5, 512), 0.0);
    EXPECT_LT(cull_threshold(m, 0, 0.5, 512), -1.0);  // n = 0: the core outputs C everywhere
    EXPECT_GT(cull_threshold(m, 0, 0.0, 512), 1.0);   // ... which is 0
    EXPECT_LT(cull_threshold(m, 10, 0.6, 512), cull_threshold(m, 100, 0.6, 512));
}

// The paper's test is conservative when the projection's pole lies inside the spherical triangle (every
// projected arc bulges outward) ...
TEST(Highlight, PaperTestNeverMissesWhenThePoleIsInside) {
    std::mt19937_64 rng(6);
    int inside = 0;
    for (int k = 0; k < 100000; ++k) {
        const double r = (1 + 40.0 * (k % 8) / 7.0) * kPi / 180;
        const Vec c = in_cap(rng, Vec(0, 0, 1), 0.3 * r);
        const Vec n[3] = {in_cap(rng, c, r), in_cap(rng, c, r), in_cap(rng, c, r)};
        if (!spherical_inside(n[0], n[1], n[2], Vec(0, 0, 1))) continue;  // the pole (XOY: z) must be inside
        const Vec h = in_cap(rng, c, 0.6 * r);
        if (!spherical_inside(n[0], n[1], n[2], h)) continue;
        ++inside;
        ASSERT_TRUE(paper_test(n[0], n[1], n[2], h, ProjPlane::xoy).inside) << k;
    }
    EXPECT_GT(inside, 1000);
}

// ... and not otherwise: an arc whose great circle separates the pole from the triangle bulges inward in
// the projection, and H just inside near its ends falls outside the paper's triangle abc.
TEST(Highlight, PaperTestMissesFarFromThePole) {
    std::mt19937_64 rng(7);
    int misses_dom = 0, misses_xoy = 0, inside = 0;
    for (int k = 0; k < 20000; ++k) {
        const Vec c = on_sphere(rng);
        const double r = 10 * kPi / 180;
        const Vec n[3] = {in_cap(rng, c, r), in_cap(rng, c, r), in_cap(rng, c, r)};
        double w[3];
        weights(rng, w);
        w[0] += 30, w[1] += 30;  // near the edge NA NB
        const double s = w[0] + w[1] + w[2];
        const double ww[3] = {w[0] / s, w[1] / s, w[2] / s};
        const Vec h = in_tri(n, ww);
        if (!spherical_inside(n[0], n[1], n[2], h)) continue;
        ++inside;
        misses_dom += !paper_test(n[0], n[1], n[2], h, ProjPlane::dominant).inside;
        misses_xoy += !paper_test(n[0], n[1], n[2], h, ProjPlane::xoy).inside;
    }
    EXPECT_GT(inside, 15000);
    EXPECT_GT(misses_dom, 0);
    EXPECT_GT(misses_xoy, misses_dom);
}

// --cull-specular in the renderer: spans are skipped, and not one pixel changes; every skipped span is one the
// core would have filled with zeros.
TEST(Highlight, CullingChangesNoPixel) {
    const Model core;
    for (const char* name : {"default", "teapot"}) {
        const render::Scene sc = render::make_scene(name);
        const render::Frame fr = render::rasterize(sc, 200, 200);
        const render::Shading base = render::shade_base(sc, fr);
        const CullResult cr = cull_spans(sc, fr, core);
        EXPECT_GT(cr.spans_culled, cr.spans / 10) << name;
        for (size_t k = 0; k < fr.spans.size(); ++k) {
            if (cr.keep[k]) continue;
            const render::Span& sp = fr.spans[k];
            const auto& m = sc.objects[sp.obj].mat;
            const host::SpanSetup s = host::setup_span(core, sp.ends, sc.light.intensity * m.ks, m.n, sp.l);
            for (uint32_t v : core.span(s.regs)) ASSERT_EQ(v, 0u) << name << " span " << k;
        }
        const render::Image all =
            render::compose(base, render::shade_specular(sc, fr, render::SpecModel::golden, render::RgbMode::once));
        const render::Image cull = render::compose(
            base, render::shade_specular(sc, kept_frame(fr, cr), render::SpecModel::golden, render::RgbMode::once));
        EXPECT_TRUE(all.rgb == cull.rgb) << name;
    }
}

TEST(MethodsCli, RenderCullSpecularWritesTheSameImage) {
    const std::string d = ::testing::TempDir() + "/cull." + std::to_string(getpid());
    std::system(("mkdir -p '" + d + "'").c_str());
    const CliRun a = specsim("render --size 96 --model golden --quiet --out " + d + "/a.png");
    const CliRun b = specsim("render --size 96 --model golden --quiet --cull-specular --out " + d + "/b.png");
    ASSERT_EQ(a.code, 0) << a.err;
    ASSERT_EQ(b.code, 0) << b.err;
    EXPECT_NE(b.out.find("cull-specular:"), std::string::npos) << b.out;
    std::ifstream fa(d + "/a.png", std::ios::binary), fb(d + "/b.png", std::ios::binary);
    std::stringstream sa, sb;
    sa << fa.rdbuf();
    sb << fb.rdbuf();
    EXPECT_GT(sa.str().size(), 100u);
    EXPECT_EQ(sa.str(), sb.str());
    std::system(("rm -rf '" + d + "'").c_str());
}

TEST(MethodsCli, SubcommandsPrintTheirTables) {
    const CliRun h = specsim("highlight --size 64 --model golden --scene sphere --samples 1000");
    ASSERT_EQ(h.code, 0) << h.err;
    EXPECT_NE(h.out.find("| sphere |"), std::string::npos) << h.out;
    EXPECT_NE(h.out.find("dominant axis of H"), std::string::npos);
    const CliRun n = specsim("normalize --size 64 --runs 3 --scene sphere-lo");
    ASSERT_EQ(n.code, 0) << n.err;
    EXPECT_NE(n.out.find("| sphere-lo |"), std::string::npos) << n.out;
    EXPECT_NE(n.out.find("| 16° |"), std::string::npos);
    const CliRun p = specsim("parallax --map waves --map-size 64 --grid 4 --max-iter 8 --budgets 1,8");
    ASSERT_EQ(p.code, 0) << p.err;
    EXPECT_NE(p.out.find("| waves | 30° |"), std::string::npos) << p.out;
}

// Every companion command answers --help (and -h) with its usage on stdout and exit 0, whatever else is given.
TEST(MethodsCli, EveryCommandAnswersHelp) {
    for (const char* cmd : {"highlight", "normalize", "parallax"}) {
        for (const char* flag : {"--help", "-h", "--size 8 --help"}) {
            const CliRun r = specsim(std::string(cmd) + " " + flag);
            EXPECT_EQ(r.code, 0) << cmd << " " << flag << ": " << r.err;
            EXPECT_EQ(r.err, "") << cmd << " " << flag;
            EXPECT_NE(r.out.find(std::string("  ") + cmd), std::string::npos) << cmd << " " << flag << ": " << r.out;
            EXPECT_NE(r.out.find("--tables FILE"), std::string::npos) << cmd;
        }
    }
}

TEST(MethodsCli, BadInputGetsOneLineAndExitCode2) {
    const std::string d = ::testing::TempDir() + "/methods_bad." + std::to_string(getpid());
    for (const std::string& args : std::vector<std::string>{"highlight --size 8", "highlight --model ref", "highlight --scene nope", "highlight --bogus 1",
          "highlight --samples", "normalize --diffuse-bound 0", "normalize --specular-bound 0.7",
          "normalize --scene nope", "normalize --runs 2", "parallax --map nope", "parallax --map-size 100",
          "parallax --depth 0", "parallax --threshold -1", "parallax --max-iter 0", "parallax --grid x",
          "parallax --max-iter 64", "parallax --budgets 4,2", "parallax --budgets 0", "parallax --budgets 1,,2",
          "highlight --coarse-n 1024", "highlight --samples 10", "normalize --timing 1", "normalize --extend linear",
          "render --cull-specular yes --out " + d + "/x.png"}) {
        const CliRun r = specsim(args + " --out-dir " + d);
        EXPECT_EQ(r.code, 2) << args;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
        EXPECT_EQ(r.out, "") << args;
        EXPECT_FALSE(std::ifstream(d).good()) << args << ": created " << d;
    }
}
