// highlight.h - companion paper A (seeds/004): is the highlight's centre on a triangle? And, what the paper
// lacks for skipping work safely, a conservative bound on max N.H over a triangle that decides whether the
// specular core can output anything there at all (`specsim render --cull-specular`, `specsim highlight`).
//
// The paper: the unit vertex normals NA, NB, NC end on the unit sphere and span a spherical triangle; the
// highlight's centre (N collinear with H) is on the triangle iff H ends inside it. Project the sphere onto a
// coordinate plane; through the projections M of the arc midpoints (NA + NB) / (2 cos(psi/2)) draw lines
// parallel to the projected chords; H' is "inside" iff it lies on the opposite vertex's side of all three.
// docs/methods.md discusses where that is and is not conservative (it is not, in general).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "raster.h"
#include "scene.h"
#include "spec_model.h"

namespace spec {
namespace methods {

using Vec = glm::dvec3;

// Projection plane of the paper's test.
enum class ProjPlane {
    xoy,       // the paper's XOY (drop z), whatever H is
    dominant,  // drop the coordinate in which |H| is largest (the robust choice the digest suggests)
};

struct PaperTestResult {
    bool inside = false;      // H' inside the triangle abc of the three lines
    bool degenerate = false;  // a projected vertex lies on a line (zero-area projection): reported inside
};

// The paper's test for unit vectors na, nb, nc, h.
PaperTestResult paper_test(const Vec& na, const Vec& nb, const Vec& nc, const Vec& h, ProjPlane plane);

// Exact answer for comparison: h inside the spherical triangle na nb nc (or on its boundary), by the signs of
// the three triple products. Normals not within an open hemisphere (no proper spherical triangle): true.
bool spherical_inside(const Vec& na, const Vec& nb, const Vec& nc, const Vec& h);

// A cap (axis, angular radius) containing the three unit vectors, hence their whole spherical triangle when
// radius < pi/2 (a cap smaller than a hemisphere is geodesically convex). Not always the smallest one.
struct Cone {
    Vec axis{0, 0, 1};
    double radius = 0;
    bool valid = false;  // radius < pi/2
};
Cone bounding_cone(const Vec& a, const Vec& b, const Vec& c);
// The largest angle between two of the three unit vectors (the spherical triangle's diameter).
double diameter(const Vec& a, const Vec& b, const Vec& c);

// Bound on what the host sees on a triangle whose vertex normals n[3] and halfway vectors h[3] are
// interpolated spherically (along the edges, then along each span, as the renderer does).
struct TriangleBound {
    bool valid = false;   // both cones smaller than a hemisphere (else nothing is bounded: b_host = 1)
    double nh_max = 1;    // >= N.H at every point of the triangle: cos(max(0, angle(axes) - rN - rH))
    double slack = 0;     // (psi + phi)^2 / 4 for the largest span angles psi, phi the triangle allows
    double b_host = 1;    // >= the host's sinusoid A cos(zeta) anywhere on any span: nh_max + slack
};
// tight: each cone the tightest of five (nhb::cone_of_triangle); false: around the centroid direction
// (nhb::cone_of_cluster, cheaper and looser).
TriangleBound triangle_bound(const Vec n[3], const Vec h[3], bool tight = true);

// The largest output code of the core (bit-exact model = RTL) for any span whose host sinusoid never exceeds
// b_host, with Is*ks = strength and exponent n. Uses the core's monotonicity (output non-increasing in
// |angle|, non-decreasing in C; tested) over a grid of amplitudes A, and an angle margin for the
// quantization of zeta0, dzeta and their accumulation over up to max_len intervals.
uint32_t core_output_sup(const Model& m, unsigned n, double strength, double b_host, uint32_t max_len);

// Per material: the largest b_host for which core_output_sup is 0 (bisection). Spans of a triangle with
// b_host < threshold get only zeros from the core: skipping them changes no pixel.
double cull_threshold(const Model& m, unsigned n, double strength, uint32_t max_len);

// The renderer's triangle (object o, triangle t) with the vectors the rasterizer interpolates: vertex
// normals (reversed when the frame drew it from behind) and H = normalize(L + normalize(eye - P)).
void triangle_vectors(const render::Scene& sc, const render::Frame& f, uint32_t tri_id, Vec n[3], Vec h[3]);

struct CullResult {
    std::vector<uint8_t> keep;        // per span of the frame: 1 = send to the core
    uint64_t triangles = 0;           // triangles with at least one span in the frame
    uint64_t triangles_culled = 0;
    uint64_t spans = 0, spans_culled = 0;
    uint64_t pixels = 0, pixels_culled = 0;  // core pixels (whole spans)
    uint64_t unbounded = 0;           // triangles whose normals or H span a hemisphere or more (never culled)
};
// The --cull-specular decision for every span of the frame (spans of a triangle share it).
CullResult cull_spans(const render::Scene& sc, const render::Frame& f, const Model& m, bool tight = true);
// The frame with only the kept spans (the specular pass runs on it; diffuse uses the whole frame).
render::Frame kept_frame(const render::Frame& f, const CullResult& c);

}  // namespace methods
}  // namespace spec
