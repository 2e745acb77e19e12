// normalize_eval.cpp - the measurements of companion paper B (normalize_eval.h).
#include "normalize_eval.h"

#include <algorithm>
#include <cmath>

#include "raster.h"
#include "stats.h"

namespace spec {
namespace methods {

std::vector<NormRow> evaluate_normalize(const std::string& label, const render::Scene& sc, int size,
                                        const NormBounds& b) {
    sc.validate();
    uint64_t tris = 0;
    for (const auto& o : sc.objects) tris += o.mesh.tri.size();
    const render::Frame fr = render::rasterize(sc, size, size);
    std::vector<uint8_t> covered(size_t(fr.w) * size_t(fr.h), 0);
    for (const auto& sp : fr.spans) {
        for (uint32_t i = 0; i <= sp.l; ++i) {
            if (fr.visible(sp, i)) covered[size_t(sp.y) * size_t(fr.w) + size_t(sp.x0) + i] = 1;
        }
    }
    PhongTerms tf, th;
    const PhongRun full = shade_phong(sc, fr, NormMode::full, b, &tf);
    const PhongRun halv = shade_phong(sc, fr, NormMode::halving, b, &th);
    std::vector<NormRow> rows;
    for (NormMode mode : norm_modes()) {
        PhongTerms t;
        const PhongRun run = mode == NormMode::full ? full : shade_phong(sc, fr, mode, b, &t);
        const PhongTerms& tm = mode == NormMode::full ? tf : t;
        NormRow r;
        r.scene = label;
        r.mode = mode;
        r.triangles = tris;
        r.ops = run.ops;
        r.seconds = run.seconds;
        for (size_t p = 0; p < covered.size(); ++p) {
            if (!covered[p]) continue;
            r.max_deficit = std::max(r.max_deficit, 1.0 - tm.n_len[p]);
            auto rel = [](double x, double ref) { return std::fabs(x - ref) / ref; };
            if (tf.diffuse[p] >= 0.05) r.rel_diffuse = std::max(r.rel_diffuse, rel(tm.diffuse[p], tf.diffuse[p]));
            if (tf.specular[p] * 255 >= 1) r.rel_specular = std::max(r.rel_specular, rel(tm.specular[p], tf.specular[p]));
            if (th.diffuse[p] >= 0.05) r.rel_diffuse_h = std::max(r.rel_diffuse_h, rel(tm.diffuse[p], th.diffuse[p]));
            if (th.specular[p] * 255 >= 1) {
                r.rel_specular_h = std::max(r.rel_specular_h, rel(tm.specular[p], th.specular[p]));
            }
        }
        const render::ImageStats sf = render::compare(run.img, full.img, covered);
        const render::ImageStats sh = render::compare(run.img, halv.img, covered);
        r.image_max = sf.max_abs;
        r.image_differing = sf.differing;
        r.image_max_h = sh.max_abs;
        rows.push_back(r);
    }
    return rows;
}

}  // namespace methods
}  // namespace spec
