// highlight_eval.cpp - the measurements of companion paper A (highlight_eval.h).
#include "highlight_eval.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "highlight_tests.h"
#include "nh_bound.h"
#include "span_host.h"
#include "stats.h"

namespace spec {
namespace methods {

namespace {
constexpr double kPi = 3.14159265358979323846;

struct TriStats {
    bool lit = false;            // the core outputs something (>= 1 LSB) on one of its pixels
    bool spot = false;           // ... at least 1 level of 255 of full scale (the visible highlight)
    bool boundary_spot = false;  // ... on a boundary pixel (first or last of a span, or its top / bottom span)
    int y_min = 1 << 30, y_max = -1;
};

// The triangle's vertices on the screen, as rasterize() projects them (render/raster.cpp).
std::array<glm::dvec2, 3> screen_vertices(const render::Scene& sc, const render::Frame& f, uint32_t tri_id) {
    uint32_t base = 0;
    size_t o = 0;
    while (o < sc.objects.size() && tri_id >= base + sc.objects[o].mesh.tri.size()) {
        base += uint32_t(sc.objects[o].mesh.tri.size());
        ++o;
    }
    const render::Mesh& mesh = sc.objects.at(o).mesh;
    const auto& tr = mesh.tri.at(tri_id - base);
    const render::Camera& cam = sc.camera;
    const glm::dmat4 pv = glm::perspective(glm::radians(cam.fov_deg), double(f.w) / double(f.h), 0.05, 1000.0) *
                          glm::lookAt(cam.eye, cam.target, cam.up);
    std::array<glm::dvec2, 3> s;
    for (int k = 0; k < 3; ++k) {
        const glm::dvec4 c = pv * glm::dvec4(mesh.pos[tr[k]], 1.0);
        s[k] = glm::dvec2((c.x / c.w + 1.0) * 0.5 * f.w, (1.0 - c.y / c.w) * 0.5 * f.h);
    }
    return s;
}

// Gouraud: the vertex intensities, interpolated by the pixel centre's screen-space barycentric coordinates.
double gouraud(const std::array<glm::dvec2, 3>& s, const double I[3], double x, double y) {
    const double d = (s[1].x - s[0].x) * (s[2].y - s[0].y) - (s[2].x - s[0].x) * (s[1].y - s[0].y);
    if (std::fabs(d) < 1e-300) return (I[0] + I[1] + I[2]) / 3;
    double w1 = ((x - s[0].x) * (s[2].y - s[0].y) - (s[2].x - s[0].x) * (y - s[0].y)) / d;
    double w2 = ((s[1].x - s[0].x) * (y - s[0].y) - (x - s[0].x) * (s[1].y - s[0].y)) / d;
    // pixel centres just outside the triangle (the raster's rounding): clamp to it
    w1 = std::min(1.0, std::max(0.0, w1));
    w2 = std::min(1.0 - w1, std::max(0.0, w2));
    return I[0] * (1 - w1 - w2) + I[1] * w1 + I[2] * w2;
}

Vec in_cap(std::mt19937_64& rng, const Vec& c, double r) {
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const double cos_a = 1.0 - u01(rng) * (1.0 - std::cos(r));
    const double sin_a = std::sqrt(std::max(0.0, 1.0 - cos_a * cos_a));
    const double phi = 2.0 * kPi * u01(rng);
    const Vec p = host::perpendicular(c);
    const Vec q = glm::cross(c, p);
    return glm::normalize(c * cos_a + (p * std::cos(phi) + q * std::sin(phi)) * sin_a);
}

Vec on_sphere(std::mt19937_64& rng) {
    std::normal_distribution<double> g(0.0, 1.0);
    for (;;) {
        const Vec v(g(rng), g(rng), g(rng));
        if (glm::length(v) > 1e-6) return glm::normalize(v);
    }
}

// The random triangles of synthetic_rows, r degrees.
std::vector<std::array<Vec, 4>> random_triangles(uint64_t samples, double r_deg) {
    std::mt19937_64 rng(1);
    const double r = r_deg * kPi / 180.0;
    std::vector<std::array<Vec, 4>> v;
    v.reserve(samples);
    for (uint64_t k = 0; k < samples; ++k) {
        const Vec c = on_sphere(rng);
        const Vec na = in_cap(rng, c, r), nb = in_cap(rng, c, r), nc = in_cap(rng, c, r);
        v.push_back({na, nb, nc, in_cap(rng, c, 1.5 * r)});
    }
    return v;
}

nhb::Vec3<Counted> cv(const Vec& v) { return nhb::Vec3<Counted>{v.x, v.y, v.z}; }
}  // namespace

SceneEval evaluate_scene(const std::string& label, const render::Scene& sc, int size, render::SpecModel model,
                         SpanCore* unit) {
    const Model core;
    SceneEval ev;
    ev.scene = label;
    const render::Frame fr = render::rasterize(sc, size, size);
    const render::Shading base = render::shade_base(sc, fr);
    const CullResult cr = cull_spans(sc, fr, core);
    const render::SpecRun all = render::shade_specular(sc, fr, model, unit, render::RgbMode::once);
    const render::SpecRun culled = render::shade_specular(sc, kept_frame(fr, cr), model, unit, render::RgbMode::once);
    const render::Image img_all = render::compose(base, all);
    const render::ImageStats st = render::compare(render::compose(base, culled), img_all, base.covered);
    CullRow& c = ev.cull;
    c.scene = label;
    c.triangles = cr.triangles;
    c.triangles_culled = cr.triangles_culled;
    c.spans = cr.spans;
    c.spans_culled = cr.spans_culled;
    c.pixels = cr.pixels;
    c.pixels_culled = cr.pixels_culled;
    c.cycles_all = all.core_cycles;
    c.cycles_culled = culled.core_cycles;
    c.differing = st.differing;
    c.max_abs = st.max_abs;
    c.spans_culled_centroid = cull_spans(sc, fr, core, false).spans_culled;
    // brute force: the golden core's output over every span, per triangle
    std::map<uint32_t, TriStats> tri;
    const uint32_t visible = uint32_t(std::ceil(std::ldexp(1.0, core.format().out_w) / 255.0));
    for (size_t k = 0; k < fr.spans.size(); ++k) {
        const render::Span& sp = fr.spans[k];
        const auto& m = sc.objects[sp.obj].mat;
        const host::SpanSetup s = host::setup_span(core, sp.ends, sc.light.intensity * m.ks, m.n, sp.l);
        const std::vector<uint32_t> px = core.span(s.regs);
        TriStats& t = tri[sp.tri];
        uint32_t peak = 0;
        for (uint32_t v : px) peak = std::max(peak, v);
        if (peak && !cr.keep[k]) ++c.culled_nonzero;
        t.lit = t.lit || peak > 0;
        t.spot = t.spot || peak >= visible;
        if (px.front() >= visible || px.back() >= visible) t.boundary_spot = true;
        t.y_min = std::min(t.y_min, sp.y);
        t.y_max = std::max(t.y_max, sp.y);
    }
    for (size_t k = 0; k < fr.spans.size(); ++k) {
        const render::Span& sp = fr.spans[k];
        TriStats& t = tri[sp.tri];
        if (sp.y != t.y_min && sp.y != t.y_max) continue;
        const auto& m = sc.objects[sp.obj].mat;
        const host::SpanSetup s = host::setup_span(core, sp.ends, sc.light.intensity * m.ks, m.n, sp.l);
        for (uint32_t v : core.span(s.regs)) t.boundary_spot = t.boundary_spot || v >= visible;
    }
    if (sc.objects.size() > 1) {
        ev.objects.resize(sc.objects.size());
        for (size_t o = 0; o < sc.objects.size(); ++o) {
            ev.objects[o].object = sc.objects[o].name;
        }
        for (size_t k = 0; k < fr.spans.size(); ++k) {
            ++ev.objects[fr.spans[k].obj].spans;
            ev.objects[fr.spans[k].obj].culled += !cr.keep[k];
        }
    }
    ev.culled_triangle.assign(fr.flipped.size(), 0);
    for (size_t k = 0; k < fr.spans.size(); ++k) {
        if (!cr.keep[k]) ev.culled_triangle[fr.spans[k].tri] = 1;
    }
    // the paper's test and the exact one per triangle, H at the centroid (normalized mean of the vertex H)
    ev.planes = {PlaneRow{"dominant axis of H"}, PlaneRow{"XOY (the paper's)"}};
    std::vector<uint8_t> accept[3];  // paper dominant, paper XOY, exact
    for (auto& a : accept) a.assign(fr.flipped.size(), 0);
    for (const auto& kv : tri) {
        Vec n[3], h[3];
        triangle_vectors(sc, fr, kv.first, n, h);
        const Vec hc = glm::normalize(h[0] + h[1] + h[2]);
        const bool in = spherical_inside(n[0], n[1], n[2], hc);
        const TriStats& t = kv.second;
        CaseRow& cs = ev.cases;
        ++cs.triangles;
        cs.lit += t.lit;
        cs.spot += t.spot;
        if (!in) (t.spot ? cs.out_cross : cs.out_free)++;
        else (t.boundary_spot ? cs.in_cross : cs.in_free)++;
        cs.lit_culled_by_bound += t.lit && ev.culled_triangle[kv.first];
        for (int p = 0; p < 2; ++p) {
            const PaperTestResult r = paper_test(n[0], n[1], n[2], hc, p == 0 ? ProjPlane::dominant : ProjPlane::xoy);
            PlaneRow& pr = ev.planes[size_t(p)];
            pr.says_inside += r.inside;
            pr.degenerate += r.inside && r.degenerate;
            pr.centre_inside += in;
            pr.centre_missed += in && !r.inside;
            pr.false_positive += r.inside && !in;
            pr.spot_rejected += t.spot && !r.inside;
            pr.lit_rejected += t.lit && !r.inside;
            accept[p][kv.first] = r.inside;
        }
        accept[2][kv.first] = in;
    }
    // the two readings of what the test gates, for each test, against the core everywhere (golden = rtl)
    const char* names[3] = {"paper, dominant plane", "paper, XOY", "exact spherical test"};
    for (int t = 0; t < 3; ++t) {
        CullResult pc;
        pc.keep.resize(fr.spans.size());
        uint64_t kept = 0, kept_px = 0, px = 0;
        for (size_t k = 0; k < fr.spans.size(); ++k) {
            pc.keep[k] = accept[t][fr.spans[k].tri];
            kept += pc.keep[k];
            px += fr.spans[k].l + 1;
            kept_px += pc.keep[k] ? fr.spans[k].l + 1 : 0;
        }
        const render::SpecRun part =
            render::shade_specular(sc, kept_frame(fr, pc), render::SpecModel::golden, render::RgbMode::once);
        for (int reading = 0; reading < 2; ++reading) {
            ReadingRow rr;
            rr.test = names[t];
            rr.reading = reading == 0 ? "cull" : "gouraud";
            rr.spans_to_core = kept;
            rr.spans = fr.spans.size();
            rr.core_pixels = px;
            rr.core_pixels_skipped = px - kept_px;
            render::SpecRun run = part;
            if (reading == 1) {
                std::map<uint32_t, std::array<double, 3>> vertex_i;
                for (const auto& kv : tri) {
                    if (accept[t][kv.first]) continue;
                    Vec n[3], h[3];
                    triangle_vectors(sc, fr, kv.first, n, h);
                    uint32_t base_id = 0;
                    size_t o = 0;
                    while (kv.first >= base_id + sc.objects[o].mesh.tri.size()) base_id += uint32_t(sc.objects[o++].mesh.tri.size());
                    const auto& m = sc.objects[o].mat;
                    std::array<double, 3> I;
                    for (int v = 0; v < 3; ++v) {
                        I[size_t(v)] = sc.light.intensity * m.ks * std::pow(std::max(0.0, glm::dot(n[v], h[v])), double(m.n));
                    }
                    rr.vertex_evaluations += 3;
                    vertex_i[kv.first] = I;
                }
                for (int y = 0; y < fr.h; ++y) {
                    for (int x = 0; x < fr.w; ++x) {
                        const size_t p = size_t(y) * size_t(fr.w) + size_t(x);
                        const int32_t id = fr.tri_id[p];
                        if (id < 0 || accept[t][size_t(id)]) continue;
                        const auto it = vertex_i.find(uint32_t(id));
                        if (it == vertex_i.end()) continue;
                        const double val = gouraud(screen_vertices(sc, fr, uint32_t(id)), it->second.data(), x + 0.5, y + 0.5);
                        for (int ch = 0; ch < 3; ++ch) run.spec[3 * p + size_t(ch)] = float(val * base.tint[3 * p + size_t(ch)]);
                    }
                }
            }
            const render::ImageStats s = render::compare(render::compose(base, run), img_all, base.covered);
            rr.differing = s.differing;
            rr.max_abs = s.max_abs;
            ev.readings.push_back(rr);
        }
    }
    ev.image = img_all;
    ev.frame = fr;
    return ev;
}

std::vector<SyntheticRow> synthetic_rows(uint64_t samples, const std::vector<double>& radii_deg) {
    std::vector<SyntheticRow> rows;
    for (double rdeg : radii_deg) {
        SyntheticRow r;
        r.r_deg = rdeg;
        r.samples = samples;
        for (const auto& t : random_triangles(samples, rdeg)) {
            const bool e = spherical_inside(t[0], t[1], t[2], t[3]);
            const bool d = paper_test(t[0], t[1], t[2], t[3], ProjPlane::dominant).inside;
            const bool x = paper_test(t[0], t[1], t[2], t[3], ProjPlane::xoy).inside;
            r.inside += e;
            r.dom_miss += e && !d;
            r.dom_false += d && !e;
            r.xoy_miss += e && !x;
            r.xoy_false += x && !e;
        }
        rows.push_back(r);
    }
    return rows;
}

std::vector<OpRow> op_counts(uint64_t samples) {
    const std::vector<std::array<Vec, 4>> tris = random_triangles(samples, 10.0);
    std::vector<OpRow> rows(5);
    rows[0].what = "the paper's test (dominant plane)";
    rows[1].what = "the exact spherical test (three triple products)";
    rows[2].what = "N.H bound per triangle, tightest cones (cone_of_triangle x 2, nh_max)";
    rows[3].what = "N.H bound per triangle, centroid cones (cone_of_cluster k = 3, x 2, nh_max)";
    rows[4].what = "N.H bound per cluster of 64 normals and 64 halfway vectors";
    for (const auto& t : tris) {
        const nhb::Vec3<Counted> a = cv(t[0]), b = cv(t[1]), c = cv(t[2]), h = cv(t[3]);
        {
            OpScope s(&rows[0].ops);
            (void)paper_test_t(a, b, c, h, true);
        }
        {
            OpScope s(&rows[1].ops);
            (void)spherical_sign_t(a, b, c, h);
        }
        {
            OpScope s(&rows[2].ops);
            // three distinct halfway vectors (H at the vertices)
            const nhb::Cone<Counted> cn = nhb::cone_of_triangle(a, b, c), ch = nhb::cone_of_triangle(h, a, b);
            (void)nhb::nh_max(cn, ch, Counted(1e-12));
        }
        {
            OpScope s(&rows[3].ops);
            const nhb::Vec3<Counted> vn[3] = {a, b, c}, vh[3] = {h, a, b};
            (void)nhb::nh_max(nhb::cone_of_cluster(vn, 3), nhb::cone_of_cluster(vh, 3), Counted(1e-12));
        }
        rows[0].count++, rows[1].count++, rows[2].count++, rows[3].count++;
    }
    // clusters: 64 vectors in a 10-degree cap each, from the same generator
    std::mt19937_64 rng(2);
    for (uint64_t k = 0; k < std::max<uint64_t>(1, samples / 64); ++k) {
        const Vec cn = on_sphere(rng), ch = on_sphere(rng);
        std::vector<nhb::Vec3<Counted>> n, h;
        for (int i = 0; i < 64; ++i) {
            n.push_back(cv(in_cap(rng, cn, 10 * kPi / 180)));
            h.push_back(cv(in_cap(rng, ch, 10 * kPi / 180)));
        }
        OpScope s(&rows[4].ops);
        (void)nhb::nh_max(nhb::cone_of_cluster(n.data(), 64), nhb::cone_of_cluster(h.data(), 64), Counted(1e-12));
        rows[4].count++;
    }
    return rows;
}

}  // namespace methods
}  // namespace spec
