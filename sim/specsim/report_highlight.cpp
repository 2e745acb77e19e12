// report_highlight.cpp - specsim highlight's tables and pictures (cmd_highlight.h).
#include <algorithm>
#include <cstdio>
#include <string>

#include "cmd_highlight.h"
#include "image.h"
#include "methods_util.h"

namespace spec {

using methods_cli::pct;
using methods_cli::strf;

namespace {
using ull = unsigned long long;

std::string share(uint64_t a, uint64_t b) { return strf("%llu (%.1f %%)", ull(a), pct(double(a), double(b))); }
}  // namespace

void report_highlight_scenes(const std::vector<methods::SceneEval>& ev, bool rtl, methods_cli::DocTables* doc) {
    std::string t = "| scene | triangles drawn | culled | spans culled | core pixels culled | core cycles saved | "
                    "culled spans with a non-zero core pixel | pixels changed | spans culled with centroid cones |\n"
                    "|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& e : ev) {
        const auto& c = e.cull;
        const std::string cyc = rtl ? strf("%.1f %% (%llu -> %llu)", pct(double(c.cycles_all - c.cycles_culled), double(c.cycles_all)),
                                           ull(c.cycles_all), ull(c.cycles_culled))
                                    : std::string("(golden: no cycles)");
        t += strf("| %s | %llu | %.1f %% | %.1f %% | %.1f %% | %s | %llu | %llu | %.1f %% |\n", c.scene.c_str(),
                  ull(c.triangles), pct(double(c.triangles_culled), double(c.triangles)),
                  pct(double(c.spans_culled), double(c.spans)), pct(double(c.pixels_culled), double(c.pixels)), cyc.c_str(),
                  ull(c.culled_nonzero), ull(c.differing), pct(double(c.spans_culled_centroid), double(c.spans)));
    }
    std::printf("1. --cull-specular: a triangle goes to the core only if the bound on max N.H over it lets the core\n"
                "   output at least 1 LSB. Images with and without culling compared byte for byte; every culled span\n"
                "   checked against the core (brute force):\n\n%s\n", t.c_str());
    doc->add("highlight-cull", t);
    std::string o = "| scene: object | spans | culled |\n|---|---|---|\n";
    for (const auto& e : ev) {
        for (const auto& ob : e.objects) {
            o += strf("| %s: %s | %llu | %s |\n", e.scene.c_str(), ob.object.c_str(), ull(ob.spans),
                      share(ob.culled, ob.spans).c_str());
        }
    }
    std::printf("Per object (the exponent decides how far from N = H the core still outputs 1 LSB):\n\n%s\n", o.c_str());
    doc->add("highlight-objects", o);

    std::string cs = "| scene | triangles | lit | spot | outside, not touching | outside, crossing edges | "
                     "inside, not crossing | inside, crossing | lit but culled by the bound |\n"
                     "|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& e : ev) {
        const auto& c = e.cases;
        cs += strf("| %s | %llu | %llu | %llu | %llu | %llu | %llu | %llu | %llu |\n", e.scene.c_str(), ull(c.triangles),
                   ull(c.lit), ull(c.spot), ull(c.out_free), ull(c.out_cross), ull(c.in_free), ull(c.in_cross),
                   ull(c.lit_culled_by_bound));
    }
    std::printf("2. The paper's four cases per drawn triangle: the centre outside or inside it (exact spherical test,\n"
                "   H at the triangle's centroid), the visible spot (>= 1 level of 255 from the core) crossing its\n"
                "   edges or not. Lit: the core outputs >= 1 LSB on one of its pixels:\n\n%s\n", cs.c_str());
    doc->add("highlight-cases", cs);

    std::string pl = "| scene | plane | test says inside | of which degenerate | centre inside (exact) | "
                     "centres missed | false positives | spot triangles rejected | lit triangles rejected |\n"
                     "|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& e : ev) {
        for (const auto& p : e.planes) {
            pl += strf("| %s | %s | %llu | %llu | %llu | %llu | %llu | %s | %s |\n", e.scene.c_str(), p.plane.c_str(),
                       ull(p.says_inside), ull(p.degenerate), ull(p.centre_inside), ull(p.centre_missed),
                       ull(p.false_positive), share(p.spot_rejected, e.cases.spot).c_str(),
                       share(p.lit_rejected, e.cases.lit).c_str());
        }
    }
    std::printf("The paper's test on the same triangles:\n\n%s\n", pl.c_str());
    doc->add("highlight-planes", pl);

    std::string rd = "| scene | test | reading | spans to the core | core pixels skipped | vertex pow() | "
                     "pixels changed | max change (levels) |\n|---|---|---|---|---|---|---|---|\n";
    for (const auto& e : ev) {
        for (const auto& r : e.readings) {
            rd += strf("| %s | %s | %s | %s | %.1f %% | %llu | %llu | %d |\n", e.scene.c_str(), r.test.c_str(),
                       r.reading.c_str(), share(r.spans_to_core, r.spans).c_str(),
                       pct(double(r.core_pixels_skipped), double(r.core_pixels)), ull(r.vertex_evaluations),
                       ull(r.differing), r.max_abs);
        }
    }
    std::printf("3. The two readings of what the test gates: cull (no specular on the triangles it rejects) and\n"
                "   gouraud (the core where it accepts, Gouraud specular from the vertices elsewhere), against the\n"
                "   core on every triangle:\n\n%s\n", rd.c_str());
    doc->add("highlight-readings", rd);
}

void report_highlight_synthetic(const std::vector<methods::SyntheticRow>& rows, const std::vector<methods::OpRow>& ops,
                                methods_cli::DocTables* doc) {
    std::string t = "| r | H inside (exact) | dominant plane: centres missed | false positives | XOY plane: centres "
                    "missed | false positives |\n|---|---|---|---|---|---|\n";
    for (const auto& r : rows) {
        const double out = double(r.samples - r.inside);
        t += strf("| %g° | %.1f %% | %llu (%.2f %%) | %.1f %% | %llu (%.2f %%) | %.1f %% |\n", r.r_deg,
                  pct(double(r.inside), double(r.samples)), ull(r.dom_miss), pct(double(r.dom_miss), double(r.inside)),
                  pct(double(r.dom_false), out), ull(r.xoy_miss), pct(double(r.xoy_miss), double(r.inside)),
                  pct(double(r.xoy_false), out));
    }
    std::printf("4. The paper's test against the exact one on random spherical triangles (vertex normals uniform in a\n"
                "   cap of radius r around a random direction, H uniform in the cap of radius 1.5 r; %llu triangles\n"
                "   per row, seed 1):\n\n%s\n",
                ull(rows.empty() ? 0 : rows[0].samples), t.c_str());
    doc->add("highlight-synthetic", t);
    std::string o = "| per call | add | mul | div | sqrt | compare |\n|---|---|---|---|---|---|\n";
    for (const auto& r : ops) {
        const double n = double(std::max<uint64_t>(1, r.count));
        o += strf("| %s | %.1f | %.1f | %.1f | %.1f | %.1f |\n", r.what.c_str(), double(r.ops.add) / n,
                  double(r.ops.mul) / n, double(r.ops.div) / n, double(r.ops.sqrt) / n, double(r.ops.cmp) / n);
    }
    std::printf("5. Operations per call, counted (sim/methods/opcount.h) and averaged over random triangles of the\n"
                "   10-degree row (the tests exit early on some):\n\n%s\n", o.c_str());
    doc->add("highlight-ops", o);
}

void write_highlight_picture(const methods::SceneEval& ev, const std::string& out_dir) {
    render::Image v = ev.image;
    const render::Frame& fr = ev.frame;
    for (int y = 0; y < fr.h; ++y) {
        for (int x = 0; x < fr.w; ++x) {
            const int32_t id = fr.tri_id[size_t(y) * size_t(fr.w) + size_t(x)];
            if (id < 0 || !ev.culled_triangle[size_t(id)]) continue;
            uint8_t* p = v.at(x, y);
            p[0] = uint8_t(p[0] / 2);
            p[1] = uint8_t(p[1] / 2);
            p[2] = uint8_t(std::min(255, p[2] / 2 + 110));
        }
    }
    render::write_png(out_dir + "/cull_" + ev.scene + ".png", v);
}

}  // namespace spec
