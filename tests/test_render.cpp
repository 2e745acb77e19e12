// The renderer: rasterizer coverage and normals, the models' images against each other, OBJ input, PNG,
// plots, and `specsim render` as a user runs it (bad input: one line, exit 2, no output file).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "Vspec_stream.h"
#include "common.h"
#include "image.h"
#include "mesh.h"
#include "raster.h"
#include "scene.h"
#include "shade.h"
#include "stats.h"
#include "stream_driver.h"
#include "unit_driver.h"

using namespace spec;
using namespace spec::render;
using namespace spec::test;

namespace {


Image render_scene(const Scene& sc, int size, SpecModel m, RgbMode rgb = RgbMode::once, Shading* base = nullptr) {
    const Frame f = rasterize(sc, size, size);
    const Shading b = shade_base(sc, f);
    if (base) *base = b;
    if (m == SpecModel::rtl) {
        UnitDriver core;   // the renderer takes the core it is given (sim/model/span_core.h)
        return compose(b, shade_specular(sc, f, m, &core, rgb));
    }
    return compose(b, shade_specular(sc, f, m, rgb));
}

// A flat grid of k x k quads (2 triangles each) in the plane z = 0, facing +z.
Mesh grid(int k, double half) {
    Mesh m;
    for (int i = 0; i <= k; ++i) {
        for (int j = 0; j <= k; ++j) {
            m.pos.emplace_back(-half + 2 * half * j / k, -half + 2 * half * i / k, 0.0);
            m.nrm.emplace_back(0, 0, 1);
        }
    }
    for (int i = 0; i < k; ++i) {
        for (int j = 0; j < k; ++j) {
            const uint32_t a = i * (k + 1) + j, b = a + 1, c = a + k + 2, d = a + k + 1;
            m.tri.push_back({a, b, c});
            m.tri.push_back({a, c, d});
        }
    }
    return m;
}
}  // namespace

// Shared edges: every pixel of a tessellated plane belongs to exactly one span (no gaps, no double hits),
// and the plane's pixels in each row are contiguous.
TEST(Raster, TessellatedPlaneCoversEachPixelOnce) {
    Scene sc;
    sc.objects.push_back({"grid", grid(13, 1.0), Material()});
    sc.camera.eye = dvec3(0.3, 0.2, 3.0);
    sc.camera.target = dvec3(0.1, 0.0, 0.0);
    sc.validate();
    const Frame f = rasterize(sc, 200, 200);
    std::vector<int> hits(200 * 200, 0);
    for (const Span& s : f.spans) {
        for (uint32_t i = 0; i <= s.l; ++i) ++hits[size_t(s.y) * 200 + size_t(s.x0) + i];
    }
    size_t covered = 0;
    for (int y = 0; y < 200; ++y) {
        int first = -1, last = -1, n = 0;
        for (int x = 0; x < 200; ++x) {
            const int h = hits[size_t(y) * 200 + x];
            ASSERT_LE(h, 1) << "pixel " << x << "," << y << " in two spans";
            EXPECT_EQ(h == 1, f.tri_id[size_t(y) * 200 + x] >= 0);
            if (h) {
                if (first < 0) first = x;
                last = x;
                ++n;
            }
        }
        if (n) EXPECT_EQ(n, last - first + 1) << "gap in row " << y;
        covered += size_t(n);
    }
    EXPECT_GT(covered, 10000u);
    EXPECT_EQ(f.hidden_spans, 0u);
    EXPECT_EQ(f.back_facing, 0u);
}

// The span end normals of a sphere are close to the true normals at those pixels (ray-sphere), and face
// the viewer.
TEST(Raster, SphereSpanNormalsAreTheSurfaceNormals) {
    Scene sc = make_scene("sphere");
    sc.validate();
    const Frame f = rasterize(sc, 160, 160);
    const glm::dmat4 view = glm::lookAt(sc.camera.eye, sc.camera.target, sc.camera.up);
    const glm::dmat4 inv = glm::inverse(glm::perspective(glm::radians(sc.camera.fov_deg), 1.0, 0.05, 1000.0) * view);
    double worst = 0;
    size_t checked = 0;
    for (const Span& s : f.spans) {
        const double px = s.x0 + 0.5, py = s.y + 0.5;
        const glm::dvec4 a = inv * glm::dvec4(2 * px / 160 - 1, 1 - 2 * py / 160, -1, 1);
        const glm::dvec4 b = inv * glm::dvec4(2 * px / 160 - 1, 1 - 2 * py / 160, 1, 1);
        const dvec3 o = dvec3(a) / a.w, d = glm::normalize(dvec3(b) / b.w - o);
        const double bb = glm::dot(o, d), cc = glm::dot(o, o) - 1.0, disc = bb * bb - cc;
        if (disc < 0.05) continue;  // silhouette pixels: the polygon and the sphere differ there
        const dvec3 hit = o + d * (-bb - std::sqrt(disc));
        worst = std::max(worst, std::acos(std::min(1.0, glm::dot(glm::normalize(hit), s.ends.n1))));
        EXPECT_GT(glm::dot(s.ends.n1, glm::normalize(sc.camera.eye - hit)), 0.0);
        ++checked;
    }
    EXPECT_GT(checked, 1000u);
    EXPECT_LT(worst, 0.05);  // 96 x 48 facets; flat interpolation in screen space
}

TEST(Mesh, TeapotNormalsOutwardAndWindingConsistent) {
    const Mesh t = make_teapot(6);
    t.validate("teapot");
    EXPECT_GT(t.tri.size(), 2000u);
    for (const auto& tr : t.tri) {
        const dvec3 e = glm::cross(t.pos[tr[1]] - t.pos[tr[0]], t.pos[tr[2]] - t.pos[tr[0]]);
        ASSERT_GT(glm::dot(e, t.nrm[tr[0]] + t.nrm[tr[1]] + t.nrm[tr[2]]), 0.0);
    }
    // body (radius > 1.6 around the y axis, between the bottom and the rim): normals point away from the axis
    size_t body = 0;
    for (size_t i = 0; i < t.pos.size(); ++i) {
        const dvec3 p = t.pos[i];
        const double r = std::hypot(p.x, p.z);
        if (r > 1.6 && std::fabs(p.z) > 0.5 && p.y > 0.5 && p.y < 2.3 && std::fabs(p.x) < 2.0) {
            EXPECT_GT((p.x * t.nrm[i].x + p.z * t.nrm[i].z) / r, 0.3) << i;
            ++body;
        }
    }
    EXPECT_GT(body, 50u);
}

// The Verilated core and the bit-exact model give the same picture, bit for bit.
TEST(Render, RtlEqualsGoldenBitForBit) {
    Scene sc = make_scene("default");
    sc.validate();
    const Frame f = rasterize(sc, 160, 160);
    UnitDriver unit;
    const SpecRun a = shade_specular(sc, f, SpecModel::rtl, &unit, RgbMode::once);
    const SpecRun b = shade_specular(sc, f, SpecModel::golden, RgbMode::once);
    EXPECT_EQ(a.spec, b.spec);
    EXPECT_GT(a.core_cycles, 2 * a.core_pixels);
    const SpecRun c = shade_specular(sc, f, SpecModel::rtl, &unit, RgbMode::per_channel);
    const SpecRun d = shade_specular(sc, f, SpecModel::golden, RgbMode::per_channel);
    EXPECT_EQ(c.spec, d.spec);
    EXPECT_EQ(c.core_runs, 3 * a.core_runs);
    // any SpanCore: the Verilated spec_stream gives the same picture; rtl without a core is refused
    StreamCore<Vspec_stream> stream;
    EXPECT_EQ(shade_specular(sc, f, SpecModel::rtl, &stream, RgbMode::once).spec, a.spec);
    EXPECT_THROW(shade_specular(sc, f, SpecModel::rtl, RgbMode::once), std::invalid_argument);
}

// A core that drops a span's last pixel is an internal error of the renderer, not a silently short span.
TEST(Render, ACoreThatLosesPixelsIsAnError) {
    struct Short : SpanCore {
        const Model m;
        std::vector<uint32_t> span(const SpanRegs& r) override {
            auto px = m.span(r);
            if (px.size() > 1) px.pop_back();
            return px;
        }
        uint64_t cycle() const override { return 0; }
    } core;
    Scene sc = make_scene("sphere");
    sc.validate();
    EXPECT_THROW(shade_specular(sc, rasterize(sc, 48, 48), SpecModel::rtl, &core, RgbMode::once), std::runtime_error);
}

// The bound: rtl and ref within 4 levels of 255 in every channel, default scene, at 256 and 512;
// the prototype's error measurably larger.
TEST(Render, RtlWithinFourLevelsOfRefPrototypeFarWorse) {
    Scene sc = make_scene("default");
    sc.validate();
    for (int size : {256, 512}) {
        Shading base;
        const Image ref = render_scene(sc, size, SpecModel::ref, RgbMode::once, &base);
        const Image rtl = render_scene(sc, size, SpecModel::rtl);
        const Image proto = render_scene(sc, size, SpecModel::prototype);
        const ImageStats sr = compare(rtl, ref, base.covered), sp = compare(proto, ref, base.covered);
        EXPECT_LE(sr.max_abs, 4) << size << " at " << sr.worst_x << "," << sr.worst_y;
        EXPECT_EQ(sr.over_4, 0u);
        EXPECT_GE(sp.max_abs, 15) << size;
        EXPECT_GE(sp.max_abs, 4 * sr.max_abs) << size;
        EXPECT_GT(sp.mean_abs, 4 * sr.mean_abs) << size;
        EXPECT_GT(sp.over_4, 1000u) << size;
        EXPECT_GT(sr.psnr, sp.psnr + 10) << size;
    }
}

// Running the core once per span and colouring on the host = three runs with C per channel, up to one level.
TEST(Render, RgbOnceMatchesPerChannel) {
    Scene sc = make_scene("default");
    sc.light.color = dvec3(1.0, 0.85, 0.6);
    for (auto& o : sc.objects) o.mat.spec_color = dvec3(0.9, 1.0, 0.7);
    sc.validate();
    Shading base;
    const Image a = render_scene(sc, 192, SpecModel::golden, RgbMode::once, &base);
    const Image b = render_scene(sc, 192, SpecModel::golden, RgbMode::per_channel);
    EXPECT_LE(compare(a, b, base.covered).max_abs, 1);
}

// The host's share: with the midpoint gamma the host is closer to ref than with the patent's.
TEST(Render, HostModelIsolatesTheHostsError) {
    Scene sc = make_scene("teapot");
    sc.objects[0].mesh = make_teapot(4);
    sc.objects[0].mesh.transform(glm::scale(glm::dmat4(1.0), dvec3(0.55)));
    sc.validate();
    const Frame f = rasterize(sc, 256, 256);
    const Shading b = shade_base(sc, f);
    const Image ref = compose(b, shade_specular(sc, f, SpecModel::ref, RgbMode::once));
    const Image hp = compose(b, shade_specular(sc, f, SpecModel::host, RgbMode::once, host::GammaRule::patent));
    const Image hm = compose(b, shade_specular(sc, f, SpecModel::host, RgbMode::once, host::GammaRule::midpoint));
    const int ep = compare(hp, ref, b.covered).max_abs, em = compare(hm, ref, b.covered).max_abs;
    EXPECT_GE(ep, 5);  // a coarse teapot: spans over which the normal turns by up to a radian
    EXPECT_LE(em, 1);
}

TEST(Obj, RoundTripThroughTinyobjloaderRendersTheSame) {
    const std::string p = tmpdir() + "/teapot.obj";
    Scene sc = make_scene("teapot");
    write_obj(sc.objects[0].mesh, p);
    const Mesh m = load_obj(p);
    const Mesh& o = sc.objects[0].mesh;
    ASSERT_EQ(m.tri.size(), o.tri.size());  // (vertices no triangle uses are not read back)
    double dp = 0, dn = 0;
    for (size_t t = 0; t < m.tri.size(); ++t) {
        for (int c = 0; c < 3; ++c) {
            dp = std::max(dp, glm::length(m.pos[m.tri[t][c]] - o.pos[o.tri[t][c]]));
            dn = std::max(dn, glm::length(m.nrm[m.tri[t][c]] - o.nrm[o.tri[t][c]]));
        }
    }
    EXPECT_LT(dp, 1e-12);
    EXPECT_LT(dn, 1e-12);
    Scene s2 = sc;
    s2.objects[0].mesh = m;
    sc.validate();
    s2.validate();
    Shading base;
    const Image a = render_scene(sc, 128, SpecModel::golden, RgbMode::once, &base);
    const Image b = render_scene(s2, 128, SpecModel::golden);
    EXPECT_LE(compare(a, b, base.covered).max_abs, 1);
}

TEST(Obj, NormalsAveragedWhenAbsent) {
    const std::string p = tmpdir() + "/tet.obj";
    write_file(p, "# a tetrahedron without normals\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
             "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    const Mesh m = load_obj(p);
    EXPECT_EQ(m.tri.size(), 4u);
    EXPECT_EQ(m.pos.size(), 4u);
    // vertex 4 (0,0,1): faces 1-2-4, 1-4-3 and 2-3-4 around it; its normal points up and outward
    EXPECT_GT(m.nrm[3].z, 0.5);
    for (const auto& n : m.nrm) EXPECT_NEAR(glm::length(n), 1.0, 1e-12);
}

TEST(Png, RoundTripAndNoTmpLeft) {
    Image img(37, 23);
    for (size_t i = 0; i < img.rgb.size(); ++i) img.rgb[i] = uint8_t((i * 7919) % 256);
    const std::string p = tmpdir() + "/x.png";
    write_png(p, img);
    EXPECT_FALSE(exists(p + ".tmp"));
    const Image r = read_png(p);
    EXPECT_EQ(r.w, 37);
    EXPECT_EQ(r.h, 23);
    EXPECT_EQ(r.rgb, img.rgb);
    EXPECT_THROW(write_png(tmpdir() + "/no/such/dir/x.png", img), std::runtime_error);
    EXPECT_FALSE(exists(tmpdir() + "/no/such/dir/x.png.tmp"));
    const ImageStats s = compare(img, img, std::vector<uint8_t>(37 * 23, 1));
    EXPECT_EQ(s.max_abs, 0);
    EXPECT_TRUE(std::isinf(s.psnr));
    Image d = img;
    d.at(3, 4)[1] = uint8_t(d.at(3, 4)[1] ^ 0x10);
    EXPECT_EQ(compare(d, img, std::vector<uint8_t>(37 * 23, 1)).max_abs, 16);
    EXPECT_EQ(compare(d, img, std::vector<uint8_t>(37 * 23, 1)).worst_x, 3);
}

TEST(Specsim, RenderWritesImagePanelAndStats) {
    const std::string d = tmpdir();
    const CliRun r = specsim("render --size 96 --out " + d + "/r.png --panel " + d + "/p.png --stats " + d +
                          "/s.json --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "");
    const Image img = read_png(d + "/r.png");
    EXPECT_EQ(img.w, 96);
    const Image panel = read_png(d + "/p.png");
    EXPECT_GT(panel.w, 5 * 96);
    std::ifstream s(d + "/s.json");
    std::stringstream ss;
    ss << s.rdbuf();
    for (const char* key : {"\"rtl\"", "\"ref\"", "\"golden\"", "\"prototype\"", "\"max_abs\"", "\"psnr_db\"",
                            "\"c_saturated\""}) {
        EXPECT_NE(ss.str().find(key), std::string::npos) << key;
    }
    EXPECT_NE(r.out.find("rtl and golden images: identical"), std::string::npos) << r.out;
}

TEST(Specsim, RenderBadInputExitsTwoWithoutOutput) {
    const std::string d = tmpdir();
    write_file(d + "/quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
    write_file(d + "/nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");   // a position (a normal would be computed)
    write_file(d + "/two.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n");
    write_file(d + "/nonormal.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//2\n");
    write_file(d + "/malformed.obj", "v 0 0 0\nv 1 x 0\nv 0 1 0\nf 1 2 3\n");
    write_file(d + "/index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
    write_file(d + "/empty.obj", "# nothing\n");
    write_file(d + "/flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nf 1 2 3\nf 1 2 4 3\n");  // no face has an area
    const char* bad[] = {
        "--obj /nonexistent/file.obj",
        "--obj @/nan.obj",
        "--obj @/two.obj",
        "--obj @/nonormal.obj",
        "--obj @/malformed.obj",
        "--obj @/index.obj",
        "--obj @/empty.obj",
        "--obj @/flat.obj",
        "--size 0",
        "--size 10000",
        "--model phong",
        "--light-dir 0,0,0",
        "--light-dir 1,nan,0",
        "--light-dir 1,2",
        "--eye 0,0,0 --target 0,0,0",
        "--up 0,-2,-8.2",  // parallel to the default scene's view direction
        "--n 2000",
        "--ks 1.5",
        "--color 1,0.5,2",
        "--fov 180",
        "--scene nope",
        "--scene sphere --obj @/quad.obj",
        "--rgb twice",
        "--host exact",
        "--frobnicate 1",
    };
    for (const char* b : bad) {
        std::string args = b;
        for (size_t k; (k = args.find('@')) != std::string::npos;) args.replace(k, 1, d);
        const std::string out = d + "/bad.png";
        std::remove(out.c_str());
        std::remove((d + "/badp.png").c_str());
        const CliRun r = specsim("render --size 64 --quiet " + args + " --out " + out + " --panel " + d + "/badp.png");
        EXPECT_EQ(r.code, 2) << args << ": " << r.err;
        EXPECT_FALSE(r.err.empty()) << args;
        EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << args << ": " << r.err;  // exactly one line
        EXPECT_FALSE(exists(out)) << args;
        EXPECT_FALSE(exists(out + ".tmp")) << args;
        EXPECT_FALSE(exists(d + "/badp.png")) << args;
    }
    const CliRun r = specsim("render --size 64");
    EXPECT_EQ(r.code, 2);  // --out is required
}

TEST(Specsim, PlotsRedrawFig5AndFig9) {
    const std::string d = tmpdir() + "/plots";
    const CliRun r = specsim("plots --out-dir " + d);
    ASSERT_EQ(r.code, 0) << r.err;
    for (const char* f : {"/fig5.png", "/fig9.png"}) {
        const Image img = read_png(d + f);
        EXPECT_GT(img.w, 600) << f;
    }
    std::ifstream in(d + "/fig5.dat");
    std::string line;
    std::getline(in, line);  // header
    int rows = 0;
    while (std::getline(in, line)) {
        std::istringstream is(line);
        double n, qp, qk, qc;
        is >> n >> qp >> qk >> qc;
        ++rows;
        if (n == 1) EXPECT_NEAR(qp, 8.97, 0.01);
        if (n == 3) {
            EXPECT_NEAR(qk, 1.089, 0.001);  // the patent's worst case (README)
            EXPECT_NEAR(qc, qk, 0.05);
        }
        if (n >= 3) EXPECT_GT(qp, 2 * qk) << n;  // the prototype is worse for every n that is not 1, 2, 4, 16
        EXPECT_LE(qk, 1.09) << n;
    }
    EXPECT_EQ(rows, 1000);
}
