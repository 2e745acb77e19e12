// highlight_eval.h - companion paper A measured (`specsim highlight`, docs/methods.md; the verdict tests call
// these functions with the document's parameters): the --cull-specular bound on a scene, the paper's test per
// triangle against brute force, the two readings of what the test gates, the test against the exact one on
// random spherical triangles, and operation counts.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "highlight.h"
#include "opcount.h"
#include "shade.h"

namespace spec {
namespace methods {

// The bound's cull (render --cull-specular) on one scene: what it saves and that no pixel changes.
struct CullRow {
    std::string scene;
    uint64_t triangles = 0, triangles_culled = 0, spans = 0, spans_culled = 0, pixels = 0, pixels_culled = 0;
    uint64_t cycles_all = 0, cycles_culled = 0;  // core clock cycles (rtl model only)
    uint64_t culled_nonzero = 0;                 // culled spans on which the core outputs something (must be 0)
    uint64_t differing = 0;                      // pixels differing with and without the cull (must be 0)
    int max_abs = 0;
    uint64_t spans_culled_centroid = 0;          // spans culled with the cheaper centroid cones instead
};
struct ObjectCull {
    std::string object;
    uint64_t spans = 0, culled = 0;
};
// Per drawn triangle: the paper's four cases (centre inside or not by the exact test; the visible spot
// crossing the triangle's edges or not), judged by the core's output (brute force).
struct CaseRow {
    uint64_t triangles = 0, lit = 0, spot = 0;
    uint64_t out_free = 0, out_cross = 0, in_free = 0, in_cross = 0;
    uint64_t lit_culled_by_bound = 0;  // must be 0
};
// The paper's test on the same triangles, by projection plane.
struct PlaneRow {
    std::string plane;
    uint64_t says_inside = 0, degenerate = 0, centre_inside = 0, centre_missed = 0, false_positive = 0;
    uint64_t spot_rejected = 0, lit_rejected = 0;
};
// One reading of what the test gates, for one test: "cull" (no specular outside the triangles it accepts) or
// "gouraud" (per-pixel specular where it accepts, Gouraud specular from the three vertices elsewhere).
struct ReadingRow {
    std::string test, reading;
    uint64_t spans_to_core = 0, spans = 0;
    uint64_t core_pixels_skipped = 0, core_pixels = 0;
    uint64_t vertex_evaluations = 0;  // Gouraud: pow() at the vertices of the rejected triangles
    uint64_t differing = 0;           // pixels against the core everywhere
    int max_abs = 0;                  // levels of 255
};
struct SceneEval {
    std::string scene;
    CullRow cull;
    std::vector<ObjectCull> objects;
    CaseRow cases;
    std::vector<PlaneRow> planes;        // dominant axis of H, XOY
    std::vector<ReadingRow> readings;    // paper (dominant), paper (XOY), exact test; cull and gouraud each
    std::vector<uint8_t> culled_triangle;  // per triangle id: culled by the bound (for the picture)
    render::Image image;                 // the scene through the core, no culling
    render::Frame frame;
};
// core: what runs the spans of render::SpecModel::rtl (the renderer takes it, sim/model/span_core.h: specsim
// passes the Verilated spec_unit); golden needs none.
SceneEval evaluate_scene(const std::string& label, const render::Scene& sc, int size, render::SpecModel model,
                         SpanCore* core = nullptr);

// The paper's test against the exact one on random spherical triangles: vertex normals uniform in a cap of
// radius r around a random direction, H uniform in the cap of radius 1.5 r, seed 1.
struct SyntheticRow {
    double r_deg = 0;
    uint64_t samples = 0, inside = 0;
    uint64_t dom_miss = 0, dom_false = 0, xoy_miss = 0, xoy_false = 0;
};
std::vector<SyntheticRow> synthetic_rows(uint64_t samples, const std::vector<double>& radii_deg);

// Operations per triangle (mean over random triangles, counted with opcount.h): the paper's test, the exact
// test, the N.H cone bound (nh_bound.h) per triangle, and per cluster of k unit vectors.
struct OpRow {
    std::string what;
    OpTally ops;        // totals over `count` calls
    uint64_t count = 0;
};
std::vector<OpRow> op_counts(uint64_t samples);

}  // namespace methods
}  // namespace spec
