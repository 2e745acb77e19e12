// Users' OBJ files (issue 12, item 6): polygons triangulated (quads, convex and concave n-gons, either winding,
// any orientation), smooth normals where the file has none or an unusable one (counted), any model size framed
// automatically, --view and --light-dir; malformed files still one line and exit 2. Every file is written here.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "common.h"
#include "image.h"
#include "mesh.h"
#include "polygon.h"
#include "raster.h"
#include "scene.h"
#include "shade.h"
#include "stats.h"

using namespace spec;
using namespace spec::render;
using namespace spec::test;

namespace {
// The polygon's area (half the Newell normal's length) and the triangles' areas about the same normal: the
// triangles cover the polygon once when every one winds with it (positive) and their sum is its area.
void expect_covers(const std::vector<dvec3>& pts, const std::vector<std::array<uint32_t, 3>>& tris,
                   size_t want_tris, const std::string& what) {
    const dvec3 nn = newell_normal(pts);
    const double area = 0.5 * glm::length(nn);
    const dvec3 w = glm::normalize(nn);
    double sum = 0;
    for (const auto& t : tris) {
        const double a = 0.5 * glm::dot(glm::cross(pts[t[1]] - pts[t[0]], pts[t[2]] - pts[t[0]]), w);
        EXPECT_GT(a, 0) << what << ": a triangle winds against the polygon or has no area";
        sum += a;
    }
    EXPECT_EQ(tris.size(), want_tris) << what;
    EXPECT_NEAR(sum, area, 1e-9 * area) << what << ": the triangles do not cover the polygon exactly once";
}

std::vector<dvec3> xy(const std::vector<std::pair<double, double>>& p) {
    std::vector<dvec3> v;
    for (auto& q : p) v.emplace_back(q.first, q.second, 0.0);
    return v;
}

// The 'U' of polygon.h: area 3 x 3 - 1 x 2 = 7
const std::vector<std::pair<double, double>> kU = {{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};

std::string obj_of(const std::vector<dvec3>& v, const std::string& faces) {
    std::string s;
    char b[160];
    for (const dvec3& p : v) {
        std::snprintf(b, sizeof b, "v %.17g %.17g %.17g\n", p.x, p.y, p.z);
        s += b;
    }
    return s + faces;
}

// A cube of six quads (outward, counter-clockwise), no normals; corners scaled by `s` and moved by `t`.
std::string cube(double s, dvec3 t = dvec3(0)) {
    std::vector<dvec3> v;
    for (int i = 0; i < 8; ++i) v.push_back(t + s * dvec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
    return obj_of(v, "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n");
}

Image render_golden(const Scene& sc, int size, Shading* base = nullptr) {
    const Frame f = rasterize(sc, size, size);
    const Shading b = shade_base(sc, f);
    if (base) *base = b;
    return compose(b, shade_specular(sc, f, SpecModel::golden, RgbMode::once));
}

// Covered pixels, and whether any touches the image's border (the model is not wholly in view).
size_t covered(const Shading& b, bool* on_border) {
    size_t n = 0;
    *on_border = false;
    for (int y = 0; y < b.h; ++y) {
        for (int x = 0; x < b.w; ++x) {
            if (!b.covered[size_t(y) * size_t(b.w) + size_t(x)]) continue;
            ++n;
            if (x == 0 || y == 0 || x == b.w - 1 || y == b.h - 1) *on_border = true;
        }
    }
    return n;
}
}  // namespace

TEST(Polygon, ConvexNgonsGiveNMinusTwoTriangles) {
    for (int n = 3; n <= 40; ++n) {
        std::vector<dvec3> p;
        for (int i = 0; i < n; ++i) p.emplace_back(std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n), 0.0);
        expect_covers(p, triangulate_polygon(p), size_t(n - 2), std::to_string(n) + "-gon");
    }
}

TEST(Polygon, ConcaveEitherWindingAndAnyOrientation) {
    std::vector<dvec3> u = xy(kU);
    expect_covers(u, triangulate_polygon(u), 6, "U counter-clockwise");
    EXPECT_NEAR(0.5 * glm::length(newell_normal(u)), 7.0, 1e-12);
    std::vector<dvec3> r(u.rbegin(), u.rend());   // clockwise about +z: what tinyobjloader fans wrongly
    expect_covers(r, triangulate_polygon(r), 6, "U clockwise");
    // the same faces turned into every orientation (the yz plane too), and not starting at vertex 0
    std::mt19937_64 rng(5);
    for (int k = 0; k < 200; ++k) {
        const glm::dmat4 rot = glm::rotate(glm::dmat4(1.0), 6.28 * double(rng() % 1000) / 1000.0,
                                           glm::normalize(dvec3(double(rng() % 7) - 3, double(rng() % 7) - 3, 1.0)));
        std::vector<dvec3> p;
        const auto& src = k % 2 ? r : u;
        for (size_t i = 0; i < src.size(); ++i) p.push_back(dvec3(rot * glm::dvec4(src[(i + size_t(k)) % src.size()], 1.0)));
        expect_covers(p, triangulate_polygon(p), 6, "turned U " + std::to_string(k));
    }
    // a ten-pointed star: every other vertex reflex
    std::vector<dvec3> star;
    for (int i = 0; i < 20; ++i) {
        const double rad = i % 2 ? 0.4 : 1.0;
        star.emplace_back(rad * std::cos(M_PI * i / 10), rad * std::sin(M_PI * i / 10), 0.0);
    }
    expect_covers(star, triangulate_polygon(star), 18, "star");
    // a comb: many reflex vertices in a row
    std::vector<std::pair<double, double>> comb = {{0, 0}, {9, 0}, {9, 2}};
    for (int t = 8; t >= 1; --t) comb.push_back({double(t), t % 2 ? 2.0 : 0.5});
    comb.push_back({0, 2});
    const auto c = xy(comb);
    expect_covers(c, triangulate_polygon(c), c.size() - 2, "comb");
}

TEST(Polygon, CollinearRepeatedAndDegenerate) {
    // a unit square with its edge midpoints: the midpoints add no area and no triangle
    const auto sq = xy({{0, 0}, {0.5, 0}, {1, 0}, {1, 0.5}, {1, 1}, {0.5, 1}, {0, 1}, {0, 0.5}});
    const auto t = triangulate_polygon(sq);
    expect_covers(sq, t, t.size(), "square with midpoints");
    EXPECT_GE(t.size(), 2u);
    EXPECT_LE(t.size(), 6u);
    // a repeated vertex
    const auto rep = xy({{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 1}});
    expect_covers(rep, triangulate_polygon(rep), 2, "repeated vertex");
    // no area at all
    EXPECT_TRUE(triangulate_polygon(xy({{0, 0}, {1, 0}, {2, 0}, {3, 0}})).empty());
    EXPECT_TRUE(triangulate_polygon(xy({{0, 0}, {0, 0}, {0, 0}})).empty());
    // a non-planar quad still gives two triangles
    const std::vector<dvec3> bent{{0, 0, 0}, {1, 0, 0.2}, {1, 1, 0}, {0, 1, 0.2}};
    EXPECT_EQ(triangulate_polygon(bent).size(), 2u);
    // self-intersecting: a bow tie with unequal lobes gets triangles, no error; a symmetric one has no net area
    EXPECT_FALSE(triangulate_polygon(xy({{0, 0}, {3, 3}, {3, 0}, {0, 1}})).empty());
    EXPECT_TRUE(triangulate_polygon(xy({{0, 0}, {1, 1}, {1, 0}, {0, 1}})).empty());
}

TEST(Obj, QuadsAndConcaveNgonsAreTriangulated) {
    const std::string d = tmpdir();
    // a quad, the U as one face, and the U reversed (facing -z) beside it
    std::vector<dvec3> v{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    for (auto& q : kU) v.emplace_back(q.first + 2, q.second, 0.0);
    write_file(d + "/poly.obj", obj_of(v, "f 1 2 3 4\nf 5 6 7 8 9 10 11 12\nf 12 11 10 9 8 7 6 5\n"));
    ObjStats st;
    const Mesh m = load_obj(d + "/poly.obj", &st);
    EXPECT_EQ(st.faces, 3u);
    EXPECT_EQ(st.polygons, 3u);
    EXPECT_EQ(st.triangles, 2u + 6u + 6u);
    EXPECT_EQ(m.tri.size(), 14u);
    EXPECT_EQ(st.degenerate, 0u);
    double front = 0, back = 0;
    for (const auto& t : m.tri) {
        const double a = 0.5 * glm::cross(m.pos[t[1]] - m.pos[t[0]], m.pos[t[2]] - m.pos[t[0]]).z;
        (a > 0 ? front : back) += std::fabs(a);
    }
    EXPECT_NEAR(front, 1.0 + 7.0, 1e-12) << "the quad and the U, counter-clockwise";
    EXPECT_NEAR(back, 7.0, 1e-12) << "the reversed U keeps its winding";
    EXPECT_EQ(st.normals_missing, m.pos.size());
    for (const auto& n : m.nrm) EXPECT_NEAR(std::fabs(n.z), 1.0, 1e-12);
}

TEST(Obj, SmoothNormalsWhereMissingZeroOrNotFinite) {
    const std::string d = tmpdir();
    write_file(d + "/cube.obj", cube(1.0));
    ObjStats st;
    const Mesh m = load_obj(d + "/cube.obj", &st);
    EXPECT_EQ(st.polygons, 6u);
    EXPECT_EQ(m.tri.size(), 12u);
    EXPECT_EQ(st.normals_missing, 8u);
    EXPECT_EQ(st.normals_computed(), 8u);
    for (size_t i = 0; i < m.pos.size(); ++i) {
        // each corner: three faces meeting at right angles, equal angle weights: along the corner's diagonal
        EXPECT_LT(glm::length(m.nrm[i] - glm::normalize(m.pos[i])), 1e-12) << i;
    }
    // given, zero-length and non-finite normals on one quad: the given one kept (normalized), the others computed
    write_file(d + "/mixed.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 2\nvn 0 0 0\nvn nan 0 1\nvn 1 inf 0\n"
                                 "f 1//1 2//2 3//3 4//4\n");
    const Mesh x = load_obj(d + "/mixed.obj", &st);
    EXPECT_EQ(st.normals_zero, 1u);
    EXPECT_EQ(st.normals_not_finite, 2u);
    EXPECT_EQ(st.normals_missing, 0u);
    for (const auto& n : x.nrm) EXPECT_LT(glm::length(n - dvec3(0, 0, 1)), 1e-12);
    // a normal given at some corners of a position and not at others: only the missing ones computed
    write_file(d + "/some.obj", cube(1.0) + "vn 0 1 0\nf 3//1 4//1 8//1 7//1\n");
    load_obj(d + "/some.obj", &st);
    EXPECT_EQ(st.normals_missing, 8u);
    EXPECT_EQ(m.pos.size() + 4, load_obj(d + "/some.obj").pos.size());
}

TEST(Obj, HugeAndTinyModelsAreFramedWhole) {
    const std::string d = tmpdir();
    std::vector<std::pair<std::string, std::string>> files = {
        {"unit", cube(1.0)},
        {"huge", cube(1e150, dvec3(3e150, -1e150, 7e149))},
        {"far", cube(1e300)},
        {"tiny", cube(1e-150, dvec3(-2e-150, 0, 5e-151))},
        {"tinier", cube(1e-300)},
        {"offset", cube(0.01, dvec3(1e4, 2e4, -3e4))},
    };
    Shading ref_base;
    Image ref;
    for (size_t k = 0; k < files.size(); ++k) {
        const std::string p = d + "/" + files[k].first + ".obj";
        write_file(p, files[k].second);
        Scene sc = scene_from_obj(p, Material());
        sc.validate();
        for (const dvec3& q : sc.objects[0].mesh.pos) EXPECT_LE(glm::length(q), 1.0 + 1e-12) << files[k].first;
        Shading b;
        const Image img = render_golden(sc, 96, &b);
        bool border = false;
        const size_t n = covered(b, &border);
        EXPECT_FALSE(border) << files[k].first << ": the model leaves the picture";
        EXPECT_GT(n, 96u * 96u / 10) << files[k].first << ": the model is too small in the picture";
        if (k == 0) {
            ref = img;
            ref_base = b;
        } else {
            EXPECT_LE(compare(img, ref, ref_base.covered).max_abs, 1) << files[k].first << ": the size changed the picture";
        }
    }
}

TEST(Obj, ViewTurnsTheCameraAndLightDirTheLight) {
    const std::string d = tmpdir();
    const std::string p = d + "/teapot.obj";
    write_obj(make_scene("teapot").objects[0].mesh, p);
    const Scene front = scene_from_obj(p, Material());
    Shading b0;
    const Image i0 = render_golden(front, 96, &b0);
    for (const dvec3 view : {dvec3(1, 0, 0), dvec3(0, 1, 0), dvec3(0, -3, 0), dvec3(-1, 0.2, -1)}) {
        Scene s = scene_from_obj(p, Material(), view);
        s.validate();   // looking along the up vector: another up is chosen
        EXPECT_LT(glm::length(glm::normalize(s.camera.eye - s.camera.target) - glm::normalize(view)), 1e-12);
        Shading b;
        const Image img = render_golden(s, 96, &b);
        bool border = false;
        EXPECT_GT(covered(b, &border), 96u * 96u / 10);
        EXPECT_FALSE(border) << view.x << "," << view.y << "," << view.z;
        EXPECT_GT(compare(img, i0, b0.covered).differing, 500u);
    }
    EXPECT_THROW(scene_from_obj(p, Material(), dvec3(0)), InputError);
    // through specsim: --view, --light-dir, the statistics
    const CliRun a = specsim("render --obj " + p + " --size 64 --model golden --quiet --out " + d + "/a.png");
    const CliRun v = specsim("render --obj " + p + " --size 64 --model golden --quiet --view 1,0.3,0 --out " + d + "/v.png");
    const CliRun l = specsim("render --obj " + p + " --size 64 --model golden --quiet --light-dir 0,-1,1 --out " + d + "/l.png");
    ASSERT_EQ(a.code, 0) << a.err;
    ASSERT_EQ(v.code, 0) << v.err;
    ASSERT_EQ(l.code, 0) << l.err;
    const Image ia = read_png(d + "/a.png"), iv = read_png(d + "/v.png"), il = read_png(d + "/l.png");
    const std::vector<uint8_t> all(64 * 64, 1);
    EXPECT_GT(compare(iv, ia, all).differing, 300u) << "--view turns the camera";
    EXPECT_GT(compare(il, ia, all).differing, 300u) << "--light-dir turns the light";
    const CliRun bad = specsim("render --obj " + p + " --view 0,0,0 --out " + d + "/z.png");
    EXPECT_TRUE(is_bad_input(bad));
    EXPECT_NE(bad.err.find("view direction has zero length"), std::string::npos) << bad.err;
    const CliRun sc = specsim("render --scene sphere --size 32 --model golden --quiet --view 0,1,0 --out " + d + "/s.png");
    EXPECT_EQ(sc.code, 0) << sc.err << ": --view turns a built-in scene's camera too";
}

TEST(Obj, SpecsimRendersUsersFilesAndCountsComputedNormals) {
    const std::string d = tmpdir();
    // quads without normals, a concave face, a zero normal and a non-finite one
    write_file(d + "/user.obj", cube(2.0) +
                                    "v 5 0 0\nv 8 0 0\nv 8 3 0\nv 7 3 0\nv 7 1 0\nv 6 1 0\nv 6 3 0\nv 5 3 0\n"
                                    "f 9 10 11 12 13 14 15 16\n"
                                    "v 0 0 5\nv 1 0 5\nv 0 1 5\nvn 0 0 0\nvn nan nan nan\nf 17//1 18//2 19//1\n");
    const CliRun r = specsim("render --obj " + d + "/user.obj --size 64 --model rtl --quiet --out " + d +
                             "/u.png --stats " + d + "/u.json");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("obj: 8 faces (7 polygons triangulated), 19 triangles, 0 of no area left out; normals "
                         "computed for 19 vertices (16 without vn, 2 zero-length, 1 not finite)"),
              std::string::npos)
        << r.out;
    const std::string j = read_file(d + "/u.json");
    EXPECT_NE(j.find("\"obj\": {\"faces\": 8, \"polygons\": 7, \"triangles\": 19, \"degenerate\": 0, "
                     "\"normals_computed\": 19, \"normals_missing\": 16, \"normals_zero\": 2, "
                     "\"normals_not_finite\": 1}"),
              std::string::npos)
        << j;
    EXPECT_NE(j.find("\"rtl\": {\"max_abs\": "), std::string::npos);
    EXPECT_GT(read_png(d + "/u.png").w, 0);
}

TEST(Obj, MalformedFilesStillGetOneLineAndExitTwo) {
    const std::string d = tmpdir();
    const std::vector<std::pair<std::string, std::string>> bad = {
        {"two.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n"},
        {"index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 9\n"},
        {"number.obj", "v 0 0 0\nv 1 0 0\nv 0 1 zero\nf 1 2 3\n"},
        {"nanpos.obj", "v 0 0 0\nv 1 0 inf\nv 0 1 0\nf 1 2 3\n"},
        {"normal.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n"},
        {"line.obj", "v 0 0 0\nv 1 1 1\nv 2 2 2\nv 3 3 3\nf 1 2 3 4\n"},
        {"point.obj", "v 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\n"},
        {"empty.obj", "# no faces\nv 0 0 0\n"},
        {"vertex.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n"},
    };
    for (const auto& b : bad) {
        write_file(d + "/" + b.first, b.second);
        const CliRun r = specsim("render --obj " + d + "/" + b.first + " --size 32 --out " + d + "/bad.png");
        EXPECT_TRUE(is_bad_input(r)) << b.first;
        EXPECT_FALSE(exists(d + "/bad.png")) << b.first;
        EXPECT_THROW(load_obj(d + "/" + b.first), InputError) << b.first;
    }
}
