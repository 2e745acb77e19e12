// cmd_methods.cpp - specsim highlight, normalize, parallax: the three companion papers, each claim measured
// (issue 6; docs/methods.md).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "cli.h"
#include "commands.h"
#include "fileutil.h"
#include "highlight.h"
#include "image.h"
#include "methods_usage.h"
#include "normalize.h"
#include "raster.h"
#include "scene.h"
#include "shade.h"
#include "span_host.h"
#include "stats.h"

namespace spec {

const char* const kMethodsUsage =
    "  highlight  companion paper A: the highlight-in-triangle test and the --cull-specular bound, measured\n"
    "           --size N (16..4096, default 512)  --model rtl|golden (default rtl)  --scene NAME (repeatable;\n"
    "           default: default, sphere, torus, teapot)  --samples N (synthetic triangles, default 200000)\n"
    "           --out-dir DIR (cull_SCENE.png: culled triangles tinted)\n"
    "  normalize  companion paper B: adaptive normalization, its figures and its speed-up, measured\n"
    "           --size N (default 512)  --runs R (3..15, default 5)  --diffuse-bound D  --specular-bound S\n"
    "           (relative errors, (0, 0.5), default 0.01)  --extend paper|slerp (how a span is extended to\n"
    "           2^k intervals; default paper)  --scene NAME (repeatable; default: the four built-in\n"
    "           scenes and sphere-lo, torus-lo, teapot-lo of 300-1500 triangles)  --out-dir DIR (fig2.png,\n"
    "           fig3.png, panel_SCENE.png)\n" SPEC_PARALLAX_USAGE;

namespace {
using methods::Vec;

double now_s() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double cpu_s() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t k = v.size() / 2;
    return v.size() % 2 ? v[k] : 0.5 * (v[k - 1] + v[k]);
}

double pct(double a, double b) { return b > 0 ? 100.0 * a / b : 0.0; }

void make_dir(const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw std::runtime_error("cannot create " + dir + ": " + ec.message());
}

std::vector<std::string> split_names(const std::vector<std::string>& given, const std::vector<std::string>& dflt) {
    return given.empty() ? dflt : given;
}

// ---------------------------------------------------------------------------------------------------------
// highlight
// ---------------------------------------------------------------------------------------------------------

// Uniform direction in the cap of angular radius r around unit c.
Vec in_cap(std::mt19937_64& rng, const Vec& c, double r) {
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const double cos_a = 1.0 - u01(rng) * (1.0 - std::cos(r));
    const double sin_a = std::sqrt(std::max(0.0, 1.0 - cos_a * cos_a));
    const double phi = 2.0 * M_PI * u01(rng);
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

struct TriStats {
    bool lit = false;               // the core outputs something (>= 1 LSB) on one of its pixels
    bool spot = false;              // ... at least 1 level of 255 of full scale (the visible highlight)
    bool boundary_spot = false;     // ... on a boundary pixel (first or last of a span, or its top / bottom span)
    int y_min = 1 << 30, y_max = -1;
};

int cmd_highlight_impl(int argc, char** argv) {
    int size = 512;
    std::string model_name = "rtl", out_dir;
    std::vector<std::string> scenes;
    long long samples = 200000;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string f = a.flag();
        if (f == "--size") size = int(parse_int(f, a.value(f), 16, 4096));
        else if (f == "--model") {
            model_name = a.value(f);
            if (model_name != "rtl" && model_name != "golden") throw UsageError("--model: must be rtl or golden");
        } else if (f == "--scene") scenes.push_back(a.value(f));
        else if (f == "--samples") samples = parse_int(f, a.value(f), 1000, 10000000);
        else if (f == "--out-dir") out_dir = a.value(f);
        else throw UsageError("highlight: unknown option " + f);
    }
    scenes = split_names(scenes, render::scene_names());
    for (const auto& s : scenes) render::make_scene(s);  // unknown names: exit 2 before any output
    if (!out_dir.empty()) make_dir(out_dir);
    const render::SpecModel model = model_name == "rtl" ? render::SpecModel::rtl : render::SpecModel::golden;
    const Model core;

    std::printf("Companion paper A (seeds/004): highlight-in-triangle test and the --cull-specular bound\n\n");
    std::printf("1. --cull-specular: a triangle goes to the core only if the bound on max N.H over it lets the core\n"
                "   output at least 1 LSB (docs/methods.md). Scenes at %dx%d through the %s core, images with and\n"
                "   without culling compared byte for byte:\n\n",
                size, size, model_name.c_str());
    std::printf("| scene | triangles drawn | culled | spans | culled | core pixels culled | core cycles: all -> "
                "culled (saved) | culled spans with a non-zero core pixel | pixels differing | bound time |\n"
                "|---|---|---|---|---|---|---|---|---|---|\n");
    struct PaperRow {
        std::string scene;
        uint64_t tris = 0, lit = 0, spot = 0, c_out_free = 0, c_out_cross = 0, c_in_free = 0, c_in_cross = 0;
        uint64_t dom_pos = 0, dom_degen = 0, dom_miss_lit = 0, dom_miss_spot = 0, dom_miss_centre = 0, dom_false = 0;
        uint64_t xoy_pos = 0, xoy_degen = 0, xoy_miss_lit = 0, xoy_miss_spot = 0, xoy_miss_centre = 0, xoy_false = 0;
        uint64_t exact_in = 0, bound_culled_lit = 0;
        // the paper's test used as the cull (dominant plane): spans kept, and the image against no culling
        uint64_t paper_spans_kept = 0, paper_differing = 0, spans = 0;
        int paper_max = 0;
    };
    std::vector<PaperRow> prow;
    std::string per_object;
    for (const auto& name : scenes) {
        const render::Scene sc = render::make_scene(name);
        const render::Frame fr = render::rasterize(sc, size, size);
        const render::Shading base = render::shade_base(sc, fr);
        const double t0 = now_s();
        const methods::CullResult cr = methods::cull_spans(sc, fr, core);
        const double t_bound = now_s() - t0;
        const render::SpecRun all = render::shade_specular(sc, fr, model, render::RgbMode::once);
        const render::Frame kept = methods::kept_frame(fr, cr);
        const render::SpecRun culled = render::shade_specular(sc, kept, model, render::RgbMode::once);
        const render::Image img_all = render::compose(base, all), img_cull = render::compose(base, culled);
        const render::ImageStats st = render::compare(img_cull, img_all, base.covered);
        // brute force: the golden core's output over every span, per triangle
        std::map<uint32_t, TriStats> tri;
        uint64_t culled_nonzero = 0;
        const uint32_t visible = uint32_t(std::ceil(std::ldexp(1.0, core.format().out_w) / 255.0));
        for (size_t k = 0; k < fr.spans.size(); ++k) {
            const render::Span& sp = fr.spans[k];
            const auto& m = sc.objects[sp.obj].mat;
            const host::SpanSetup s = host::setup_span(core, sp.ends, sc.light.intensity * m.ks, m.n, sp.l);
            const std::vector<uint32_t> px = core.span(s.regs);
            TriStats& t = tri[sp.tri];
            uint32_t peak = 0;
            for (uint32_t v : px) peak = std::max(peak, v);
            if (peak && !cr.keep[k]) ++culled_nonzero;
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
        char cyc[96];
        if (model == render::SpecModel::rtl) {
            std::snprintf(cyc, sizeof cyc, "%llu -> %llu (%.1f %%)", (unsigned long long)all.core_cycles,
                          (unsigned long long)culled.core_cycles,
                          pct(double(all.core_cycles - culled.core_cycles), double(all.core_cycles)));
        } else {
            std::snprintf(cyc, sizeof cyc, "(golden: no cycles)");
        }
        std::printf("| %s | %llu | %llu (%.1f %%) | %llu | %llu (%.1f %%) | %llu (%.1f %%) | %s | %llu | %llu (max %d levels) "
                    "| %.1f ms |\n",
                    name.c_str(), (unsigned long long)cr.triangles, (unsigned long long)cr.triangles_culled,
                    pct(double(cr.triangles_culled), double(cr.triangles)), (unsigned long long)cr.spans,
                    (unsigned long long)cr.spans_culled, pct(double(cr.spans_culled), double(cr.spans)),
                    (unsigned long long)cr.pixels_culled, pct(double(cr.pixels_culled), double(cr.pixels)), cyc,
                    (unsigned long long)culled_nonzero, (unsigned long long)st.differing, st.max_abs, 1e3 * t_bound);
        std::fflush(stdout);
        if (sc.objects.size() > 1) {
            std::vector<uint64_t> sp_all(sc.objects.size(), 0), sp_cut(sc.objects.size(), 0);
            for (size_t k = 0; k < fr.spans.size(); ++k) {
                ++sp_all[fr.spans[k].obj];
                sp_cut[fr.spans[k].obj] += !cr.keep[k];
            }
            for (size_t o = 0; o < sc.objects.size(); ++o) {
                per_object += "| " + name + ": " + sc.objects[o].name + " | " + std::to_string(sp_all[o]) + " | " +
                              std::to_string(sp_cut[o]) + " (" +
                              std::to_string(int(std::lround(pct(double(sp_cut[o]), double(sp_all[o]))))) + " %) |\n";
            }
        }

        PaperRow pr;
        pr.scene = name;
        std::vector<uint8_t> culled_tri(fr.flipped.size(), 0);
        for (size_t k = 0; k < fr.spans.size(); ++k) {
            if (!cr.keep[k]) culled_tri[fr.spans[k].tri] = 1;
        }
        for (const auto& kv : tri) {
            Vec n[3], h[3];
            methods::triangle_vectors(sc, fr, kv.first, n, h);
            const Vec hc = glm::normalize(h[0] + h[1] + h[2]);
            const bool in = methods::spherical_inside(n[0], n[1], n[2], hc);
            const methods::PaperTestResult dr = methods::paper_test(n[0], n[1], n[2], hc, methods::ProjPlane::dominant);
            const methods::PaperTestResult xr = methods::paper_test(n[0], n[1], n[2], hc, methods::ProjPlane::xoy);
            const bool dom = dr.inside, xoy = xr.inside;
            const TriStats& t = kv.second;
            ++pr.tris;
            pr.lit += t.lit;
            pr.spot += t.spot;
            pr.exact_in += in;
            if (!in) (t.spot ? pr.c_out_cross : pr.c_out_free)++;
            else (t.boundary_spot ? pr.c_in_cross : pr.c_in_free)++;
            pr.dom_pos += dom;
            pr.dom_degen += dom && dr.degenerate;
            pr.dom_miss_lit += t.lit && !dom;
            pr.dom_miss_spot += t.spot && !dom;
            pr.dom_miss_centre += in && !dom;
            pr.dom_false += dom && !in;
            pr.xoy_pos += xoy;
            pr.xoy_degen += xoy && xr.degenerate;
            pr.xoy_miss_lit += t.lit && !xoy;
            pr.xoy_miss_spot += t.spot && !xoy;
            pr.xoy_miss_centre += in && !xoy;
            pr.xoy_false += xoy && !in;
            pr.bound_culled_lit += t.lit && culled_tri[kv.first];
        }
        {
            std::vector<uint8_t> keep_tri(fr.flipped.size(), 0);
            for (const auto& kv : tri) {
                Vec n[3], h[3];
                methods::triangle_vectors(sc, fr, kv.first, n, h);
                const Vec hc = glm::normalize(h[0] + h[1] + h[2]);
                keep_tri[kv.first] = methods::paper_test(n[0], n[1], n[2], hc, methods::ProjPlane::dominant).inside;
            }
            methods::CullResult pc;
            pc.keep.resize(fr.spans.size());
            for (size_t k = 0; k < fr.spans.size(); ++k) {
                pc.keep[k] = keep_tri[fr.spans[k].tri];
                pr.paper_spans_kept += pc.keep[k];
            }
            const render::Image img_p = render::compose(
                base, render::shade_specular(sc, methods::kept_frame(fr, pc), render::SpecModel::golden,
                                             render::RgbMode::once));
            const render::ImageStats sp = render::compare(img_p, img_all, base.covered);
            pr.paper_differing = sp.differing;
            pr.paper_max = sp.max_abs;
            pr.spans = fr.spans.size();
        }
        prow.push_back(pr);
        if (!out_dir.empty()) {
            // the image, culled triangles tinted blue
            render::Image v = img_all;
            for (int y = 0; y < fr.h; ++y) {
                for (int x = 0; x < fr.w; ++x) {
                    const int32_t id = fr.tri_id[size_t(y) * size_t(fr.w) + size_t(x)];
                    if (id < 0 || !culled_tri[size_t(id)]) continue;
                    uint8_t* p = v.at(x, y);
                    p[0] = uint8_t(p[0] / 2);
                    p[1] = uint8_t(p[1] / 2);
                    p[2] = uint8_t(std::min(255, p[2] / 2 + 110));
                }
            }
            render::write_png(out_dir + "/cull_" + name + ".png", v);
        }
    }

    if (!per_object.empty()) {
        std::printf("\nPer object (the exponent decides how far from N = H the core still outputs 1 LSB):\n\n"
                    "| object | spans | culled |\n|---|---|---|\n%s", per_object.c_str());
    }
    std::printf("\n2. The paper's test in the same scenes, per drawn triangle, H taken at the triangle's centroid\n"
                "   (normalized mean of the vertex H). Lit: the core outputs >= 1 LSB on one of its pixels; spot: at\n"
                "   least 1 level of 255 of full scale (the visible highlight). The paper's four cases: centre outside\n"
                "   or inside the triangle (exact spherical test), spot crossing its edges or not:\n\n");
    std::printf("| scene | triangles | lit | spot | outside, not touching | outside, crossing edges | "
                "inside, not crossing | inside, crossing | lit but culled by the bound |\n"
                "|---|---|---|---|---|---|---|---|---|\n");
    for (const auto& p : prow) {
        std::printf("| %s | %llu | %llu | %llu | %llu | %llu | %llu | %llu | %llu |\n", p.scene.c_str(),
                    (unsigned long long)p.tris, (unsigned long long)p.lit, (unsigned long long)p.spot,
                    (unsigned long long)p.c_out_free, (unsigned long long)p.c_out_cross,
                    (unsigned long long)p.c_in_free, (unsigned long long)p.c_in_cross,
                    (unsigned long long)p.bound_culled_lit);
    }
    std::printf("\n| scene | plane | test says inside | of which degenerate | centre inside (exact) | misses of a centre | "
                "false positives | spot triangles it rejects | lit triangles it rejects |\n"
                "|---|---|---|---|---|---|---|---|---|\n");
    for (const auto& p : prow) {
        for (int x = 0; x < 2; ++x) {
            std::printf("| %s | %s | %llu | %llu | %llu | %llu | %llu | %llu of %llu (%.1f %%) | %llu of %llu (%.1f %%) |\n",
                        p.scene.c_str(), x ? "XOY (the paper's)" : "dominant axis of H",
                        (unsigned long long)(x ? p.xoy_pos : p.dom_pos), (unsigned long long)(x ? p.xoy_degen : p.dom_degen),
                        (unsigned long long)p.exact_in, (unsigned long long)(x ? p.xoy_miss_centre : p.dom_miss_centre),
                        (unsigned long long)(x ? p.xoy_false : p.dom_false),
                        (unsigned long long)(x ? p.xoy_miss_spot : p.dom_miss_spot), (unsigned long long)p.spot,
                        pct(double(x ? p.xoy_miss_spot : p.dom_miss_spot), double(p.spot)),
                        (unsigned long long)(x ? p.xoy_miss_lit : p.dom_miss_lit), (unsigned long long)p.lit,
                        pct(double(x ? p.xoy_miss_lit : p.dom_miss_lit), double(p.lit)));
        }
    }

    std::printf("\nThe paper's test as the cull (the core only on triangles it says contain the centre; dominant\n"
                "plane), the golden image against no culling:\n\n| scene | spans sent to the core | pixels differing | "
                "max difference (levels of 255) |\n|---|---|---|---|\n");
    for (const auto& p : prow) {
        std::printf("| %s | %llu of %llu (%.1f %%) | %llu | %d |\n", p.scene.c_str(), (unsigned long long)p.paper_spans_kept,
                    (unsigned long long)p.spans, pct(double(p.paper_spans_kept), double(p.spans)),
                    (unsigned long long)p.paper_differing, p.paper_max);
    }
    std::printf("\n3. The paper's test against the exact one on random spherical triangles (vertex normals uniform in a\n"
                "   cap of radius r around a random direction, H uniform in the cap of radius 1.5 r; %lld triangles\n"
                "   per row, seed 1):\n\n", samples);
    std::printf("| r | H inside (exact) | dominant plane: misses of an inside H | false positives | XOY plane: "
                "misses | false positives |\n|---|---|---|---|---|---|\n");
    const double radii[] = {1.0, 3.0, 10.0, 30.0};
    std::vector<std::array<Vec, 4>> bench;
    for (double rdeg : radii) {
        std::mt19937_64 rng(1);
        const double r = rdeg * M_PI / 180.0;
        uint64_t in = 0, dm = 0, dfp = 0, xm = 0, xfp = 0;
        for (long long k = 0; k < samples; ++k) {
            const Vec c = on_sphere(rng);
            const Vec na = in_cap(rng, c, r), nb = in_cap(rng, c, r), nc = in_cap(rng, c, r);
            const Vec h = in_cap(rng, c, 1.5 * r);
            if (bench.size() < 100000) bench.push_back({na, nb, nc, h});
            const bool e = methods::spherical_inside(na, nb, nc, h);
            const bool d = methods::paper_test(na, nb, nc, h, methods::ProjPlane::dominant).inside;
            const bool x = methods::paper_test(na, nb, nc, h, methods::ProjPlane::xoy).inside;
            in += e;
            dm += e && !d;
            dfp += d && !e;
            xm += e && !x;
            xfp += x && !e;
        }
        const double out = double(samples) - double(in);
        std::printf("| %g deg | %.1f %% | %llu (%.3f %%) | %.1f %% | %llu (%.3f %%) | %.1f %% |\n", rdeg,
                    pct(double(in), double(samples)), (unsigned long long)dm, pct(double(dm), double(in)),
                    pct(double(dfp), out), (unsigned long long)xm, pct(double(xm), double(in)), pct(double(xfp), out));
    }
    // cost per triangle (medians of 5 runs over the stored triangles)
    auto time_it = [&](auto fn) {
        std::vector<double> r;
        for (int run = 0; run < 5; ++run) {
            const double t0 = now_s();
            uint64_t acc = 0;
            for (const auto& b : bench) acc += fn(b);
            r.push_back((now_s() - t0) / double(bench.size()) * 1e9);
            if (acc == uint64_t(-1)) std::printf("?");
        }
        return median(r);
    };
    const double ns_paper = time_it([](const std::array<Vec, 4>& b) {
        return uint64_t(methods::paper_test(b[0], b[1], b[2], b[3], methods::ProjPlane::dominant).inside);
    });
    const double ns_exact = time_it(
        [](const std::array<Vec, 4>& b) { return uint64_t(methods::spherical_inside(b[0], b[1], b[2], b[3])); });
    const double ns_bound = time_it([](const std::array<Vec, 4>& b) {
        const Vec n[3] = {b[0], b[1], b[2]};
        const Vec h[3] = {b[3], b[3], b[3]};
        return uint64_t(methods::triangle_bound(n, h).b_host > 0.5);
    });
    std::printf("\nCost per triangle (medians of 5 runs over %zu triangles, this machine): paper's test %.0f ns, exact "
                "spherical test (three triple products) %.0f ns, N.H bound (two cones, five atan2) %.0f ns\n",
                bench.size(), ns_paper, ns_exact, ns_bound);
    return 0;
}

// ---------------------------------------------------------------------------------------------------------
// normalize
// ---------------------------------------------------------------------------------------------------------

bool write_gnuplot(const std::string& dir, const std::string& script) {
    const std::string gp = dir + "/fig.gp";
    {
        std::ofstream o(gp);
        o << script;
        if (!o) throw std::runtime_error("cannot write " + gp);
    }
    const std::string cmd = "gnuplot '" + gp + "' 2>/dev/null";
    return std::system(cmd.c_str()) == 0;
}

int cmd_normalize_impl(int argc, char** argv) {
    int size = 512, runs = 5;
    methods::NormBounds b;
    std::vector<std::string> scenes;
    std::string out_dir;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string f = a.flag();
        if (f == "--size") size = int(parse_int(f, a.value(f), 16, 4096));
        else if (f == "--runs") runs = int(parse_int(f, a.value(f), 3, 15));
        else if (f == "--diffuse-bound" || f == "--specular-bound") {
            const double v = parse_double(f, a.value(f));
            if (!(v > 0 && v < 0.5)) throw UsageError(f + ": must be in (0, 0.5)");
            (f == "--diffuse-bound" ? b.diffuse : b.specular) = v;
        } else if (f == "--extend") {
            const std::string e = a.value(f);
            if (e == "paper") b.slerp_extension = false;
            else if (e == "slerp") b.slerp_extension = true;
            else throw UsageError("--extend: '" + e + "' is not paper or slerp");
        } else if (f == "--scene") scenes.push_back(a.value(f));
        else if (f == "--out-dir") out_dir = a.value(f);
        else throw UsageError("normalize: unknown option " + f);
    }
    std::vector<std::string> dflt = render::scene_names();
    for (const char* s : {"sphere-lo", "torus-lo", "teapot-lo"}) dflt.push_back(s);
    scenes = split_names(scenes, dflt);
    for (const auto& s : scenes) methods::normalize_scene(s);
    if (!out_dir.empty()) make_dir(out_dir);
    const double deg = M_PI / 180.0;

    std::printf("Companion paper B (seeds/003): adaptive normalization of normal vectors\n\n");
    std::printf("1. The paper's figures recomputed. d_(1/2^i) = 1 - cos(psi / 2^i) (eq. 2): the length deficit of the\n"
                "   unnormalized average at halving level i, psi the angle between the span's end normals; z by the\n"
                "   recursion z_(1/2^(i+1)) = sqrt(2 + z_(1/2^i)) (eq. 1) against 2 cos(psi / 2^(i+1)):\n\n");
    std::printf("| psi | d_1/2 | d_1/4 | d_1/8 | d_1/2 / d_1/4 | d_1/4 / d_1/8 | the paper's series for d_1/2 / d_1/4 | "
                "z recursion error (4 levels) |\n|---|---|---|---|---|---|---|---|\n");
    std::ostringstream dat2, dat3;
    for (double p : {5.0, 10.0, 16.0, 16.2, 20.0, 30.0, 32.0, 32.5, 45.0, 60.0, 90.0, 120.0, 150.0, 180.0}) {
        const double psi = p * deg;
        const double d1 = methods::deviation(psi, 1), d2 = methods::deviation(psi, 2), d3 = methods::deviation(psi, 3);
        const double series = 4 - psi * psi / 16 + std::pow(psi, 4) / 3072 - std::pow(psi, 6) / 1474560;
        double zerr = 0;
        for (int i = 1; i <= 4; ++i) {
            zerr = std::max(zerr, std::fabs(methods::z_level(psi, i) - 2 * std::cos(psi / std::ldexp(1.0, i))));
        }
        std::printf("| %g deg | %.4f %% | %.4f %% | %.5f %% | %.4f | %.4f | %.4f | %.1e |\n", p, 100 * d1, 100 * d2,
                    100 * d3, d1 / d2, d2 / d3, series, zerr);
    }
    double rmin = 10, rmin90 = 10, rmax = 0;
    for (int k = 1; k <= 18000; ++k) {
        const double psi = k * 0.01 * deg;
        const double r = methods::deviation(psi, 1) / methods::deviation(psi, 2);
        rmin = std::min(rmin, r);
        rmax = std::max(rmax, r);
        if (k <= 9000) rmin90 = std::min(rmin90, r);
        if (k % 50 == 0) {
            dat2 << k * 0.01 << " " << r << " " << methods::deviation(psi, 2) / methods::deviation(psi, 3) << "\n";
            dat3 << k * 0.01 << " " << 100 * methods::deviation(psi, 1) << "\n";
        }
    }
    std::printf("\nClaims: \"1 %% at 16 deg, 4 %% at 32 deg\": d_1/2 = %.3f %% at 16 deg and %.3f %% at 32 deg; d_1/2 reaches\n"
                "1 %% at psi = %.2f deg and 4 %% at %.2f deg. \"Max 0.293 at cos psi -> 0\": d_1/2(90 deg) = %.4f, but psi\n"
                "can exceed 90 deg: d_1/2(180 deg) = %.3f. \"Shrinks 3.4 to 4 times a level\": d_1/2 / d_1/4 is %.3f .. %.4f\n"
                "over psi in (0, 180] deg (%.3f .. 4 for psi <= 90 deg); deeper levels are closer to 4.\n",
                100 * methods::deviation(16 * deg, 1), 100 * methods::deviation(32 * deg, 1),
                methods::angle_for_deviation(0.01) / deg, methods::angle_for_deviation(0.04) / deg,
                methods::deviation(90 * deg, 1), methods::deviation(M_PI, 1), rmin, rmax, rmin90);
    std::printf("\nSpecular stopping rule cos(chi) >= 2 (1 - ds)^(2/n) - 1 for ds = %.2g (largest end-normal angle chi\n"
                "of a segment that may be lerped without normalization):", b.specular);
    for (unsigned n : {1u, 3u, 10u, 100u, 1000u}) {
        std::printf(" n = %u: %.3f deg;", n, std::acos(methods::specular_cos_bound(b.specular, n)) / deg);
    }
    std::printf("\n(diffuse, dd = %.2g: %.2f deg).\n", b.diffuse, methods::angle_for_deviation(b.diffuse) / deg);

    std::printf("\n2. The Phong path (N and H interpolated along each span, Blinn-Phong per pixel, no core) at %dx%d:\n"
                "   full normalization (every pixel: normalize(lerp), the classic Phong), the paper's halving down to\n"
                "   every pixel, and the paper's adaptive method (bounds: diffuse %.2g, specular %.2g; span extended to\n"
                "   2^k %s). Work per interpolated vector (N and H of every pixel of every span); relative errors\n"
                "   against halving (the same vectors normalized: what the bounds speak of); largest image differences\n"
                "   in levels of 255:\n\n",
                size, size, b.diffuse, b.specular,
                b.slerp_extension ? "on the great circle (--extend slerp)" : "by the paper's linear extrapolation");
    std::printf("| scene | triangles | vectors | full: normalized | adaptive: normalized + halved | lerped | "
                "sqrt per vector: full / adaptive | max 1 - \\|N\\| | max rel. error diffuse / specular | "
                "adaptive vs halving | halving vs full | adaptive vs full |\n"
                "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    struct TimeRow {
        std::string scene;
        double raster = 0, full = 0, halving = 0, adaptive = 0;
        double rf = 0, ra = 0;  // median of the per-run ratios adaptive / full, and their range
    };
    std::vector<TimeRow> times;
    for (const auto& name : scenes) {
        const render::Scene sc = methods::normalize_scene(name);
        sc.validate();
        uint64_t tris = 0;
        for (const auto& o : sc.objects) tris += o.mesh.tri.size();
        const render::Frame fr = render::rasterize(sc, size, size);
        methods::PhongTerms tf, th, ta;
        const methods::PhongRun full = methods::shade_phong(sc, fr, methods::NormMode::full, b, &tf);
        const methods::PhongRun halv = methods::shade_phong(sc, fr, methods::NormMode::halving, b, &th);
        const methods::PhongRun adap = methods::shade_phong(sc, fr, methods::NormMode::adaptive, b, &ta);
        double deficit = 0, rel_d = 0, rel_s = 0;
        std::vector<uint8_t> covered(size_t(fr.w) * size_t(fr.h), 0);
        for (const auto& sp : fr.spans) {
            for (uint32_t i = 0; i <= sp.l; ++i) {
                if (!fr.visible(sp, i)) continue;
                const size_t p = size_t(sp.y) * size_t(fr.w) + size_t(sp.x0) + i;
                covered[p] = 1;
                deficit = std::max(deficit, 1.0 - ta.n_len[p]);
                if (th.diffuse[p] >= 0.05) rel_d = std::max(rel_d, std::fabs(ta.diffuse[p] - th.diffuse[p]) / th.diffuse[p]);
                if (th.specular[p] * 255 >= 1) rel_s = std::max(rel_s, std::fabs(ta.specular[p] - th.specular[p]) / th.specular[p]);
            }
        }
        const render::ImageStats s_ah = render::compare(adap.img, halv.img, covered);
        const render::ImageStats s_hf = render::compare(halv.img, full.img, covered);
        const render::ImageStats s_af = render::compare(adap.img, full.img, covered);
        const double vec = double(full.ops.vectors);
        std::printf("| %s | %llu | %llu | %.1f %% | %.1f %% + %.1f %% | %.1f %% | %.3f / %.3f | %.4f %% | %.3f %% / %.3f %% "
                    "| %d | %d | %d |\n",
                    name.c_str(), (unsigned long long)tris, (unsigned long long)full.ops.vectors,
                    pct(double(full.ops.normalized), vec), pct(double(adap.ops.normalized), vec),
                    pct(double(adap.ops.halved), vec), pct(double(adap.ops.lerped), vec), double(full.ops.sqrts) / vec,
                    double(adap.ops.sqrts) / vec, 100 * deficit, 100 * rel_d, 100 * rel_s, s_ah.max_abs, s_hf.max_abs,
                    s_af.max_abs);
        std::fflush(stdout);
        // time per frame: in each run the three modes back to back (rotating order), each repeating the
        // frame for >= 0.1 s; medians over the runs, and the median of the per-run ratios (less sensitive to
        // the machine's load than a ratio of medians)
        auto one = [&](methods::NormMode mode) {
            double done = 0, spent = 0;
            do {
                spent += methods::shade_phong(sc, fr, mode, b).seconds;
                done += 1;
            } while (spent < 0.1);
            return spent / done;
        };
        TimeRow t;
        t.scene = name;
        std::vector<double> vr, vf, vh, va, ratio;
        for (int k = 0; k < runs; ++k) {
            double tf = 0, thv = 0, tad = 0;
            for (int m = 0; m < 3; ++m) {
                switch ((m + k) % 3) {
                    case 0: tf = one(methods::NormMode::full); break;
                    case 1: thv = one(methods::NormMode::halving); break;
                    default: tad = one(methods::NormMode::adaptive); break;
                }
            }
            vf.push_back(tf);
            vh.push_back(thv);
            va.push_back(tad);
            ratio.push_back(tad / tf);
            double done = 0, spent = 0;
            do {
                const double t0 = cpu_s();
                const render::Frame f2 = render::rasterize(sc, size, size);
                spent += cpu_s() - t0;
                done += double(!f2.spans.empty() || true);
            } while (spent < 0.1);
            vr.push_back(spent / done);
        }
        t.raster = median(vr);
        t.full = median(vf);
        t.halving = median(vh);
        t.adaptive = median(va);
        t.rf = median(ratio);
        t.ra = *std::max_element(ratio.begin(), ratio.end()) - *std::min_element(ratio.begin(), ratio.end());
        times.push_back(t);
        if (!out_dir.empty()) {
            const render::Image em = render::error_map(adap.img, full.img, 16);
            char sub[64];
            std::snprintf(sub, sizeof sub, "bounds %.3g / %.3g", b.diffuse, b.specular);
            const render::Image panel = render::make_panel(
                {{&full.img, "full normalization", "classic Phong"},
                 {&adap.img, "adaptive", sub},
                 {&em, "difference x16", "max " + std::to_string(s_af.max_abs) + " levels of 255"}},
                "Companion paper B: adaptive normalization, scene " + name);
            render::write_png(out_dir + "/panel_" + name + ".png", panel);
        }
    }
    std::printf("\n3. CPU time per frame at %dx%d (this machine; %d runs, in each the three modes back to back, each\n"
                "   repeating the frame for at least 0.1 s; the shading loop alone, and with the rasterization in front\n"
                "   of it; medians):\n\n"
                "| scene | shading ms: full / halving / adaptive | adaptive / full (median of the runs' ratios) | "
                "range of the ratios | adaptive faster by | frame ms (raster + shading): full / adaptive | "
                "frame faster by |\n|---|---|---|---|---|---|---|\n",
                size, size, runs);
    for (const auto& t : times) {
        std::printf("| %s | %.2f / %.2f / %.2f | %.3f | %.3f | %.1f %% | %.1f / %.1f | %.1f %% |\n", t.scene.c_str(),
                    1e3 * t.full, 1e3 * t.halving, 1e3 * t.adaptive, t.rf, t.ra, 100 * (1 - t.rf),
                    1e3 * (t.raster + t.full), 1e3 * (t.raster + t.full * t.rf),
                    pct(t.full * (1 - t.rf), t.raster + t.full));
    }
    if (!out_dir.empty()) {
        for (const auto& kv : {std::make_pair("fig2.dat", dat2.str()), std::make_pair("fig3.dat", dat3.str())}) {
            std::ofstream o(out_dir + "/" + kv.first);
            o << kv.second;
            if (!o) throw std::runtime_error("cannot write " + out_dir + "/" + kv.first);
        }
        const std::string gp =
            "set terminal pngcairo size 640,420 font ',10'\n"
            "set grid\nset key top right\n"
            "set output '" + out_dir + "/fig2.png'\n"
            "set title 'Fig. 2 recomputed: d_{1/2^i} / d_{1/2^{i+1}} against psi'\n"
            "set xlabel 'psi, degrees'\nset ylabel 'ratio'\nset xrange [0:180]\n"
            "plot '" + out_dir + "/fig2.dat' u 1:2 w l lw 2 t 'd_{1/2} / d_{1/4}', '' u 1:3 w l lw 2 t 'd_{1/4} / d_{1/8}'\n"
            "set output '" + out_dir + "/fig3.png'\n"
            "set title 'Fig. 3 recomputed: largest relative diffuse error d_{1/2} against psi'\n"
            "set ylabel 'd_{1/2}, %'\nset key top left\n"
            "set arrow from 16.2,0 to 16.2,1 nohead dt 2\nset arrow from 0,1 to 16.2,1 nohead dt 2\n"
            "set arrow from 32.5,0 to 32.5,4 nohead dt 2\nset arrow from 0,4 to 32.5,4 nohead dt 2\n"
            "plot '" + out_dir + "/fig3.dat' u 1:2 w l lw 2 t '1 - cos(psi/2)'\n";
        if (!write_gnuplot(out_dir, gp)) throw std::runtime_error("gnuplot failed (is gnuplot installed?)");
        std::printf("\nimages: %s/fig2.png, fig3.png, panel_SCENE.png\n", out_dir.c_str());
    }
    return 0;
}

}  // namespace

int cmd_highlight(int argc, char** argv) { return cmd_highlight_impl(argc, argv); }
int cmd_normalize(int argc, char** argv) { return cmd_normalize_impl(argc, argv); }

}  // namespace spec
