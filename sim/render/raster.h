// raster.h - scanline rasterization with a z-buffer, producing the spans the host sends to the core.
//
// As in the patent's Fig. 4: the vertex normals N and halfway vectors H are interpolated along the triangle's
// edges (spherically, by the scanline's position between the edge's end points), then along the scanline
// between the two edge points. A span is the run of pixels of one triangle on one scanline; its end vectors
// are those at its first and last pixel centre, and pixel i of l + 1 has t = i / l. Interpolation is linear
// in screen space (as a scanline device does), not perspective-corrected.
#pragma once

#include <cstdint>
#include <vector>

#include "scene.h"
#include "span_host.h"

namespace spec {
namespace render {

struct Span {
    int32_t y = 0, x0 = 0;   // first pixel
    uint32_t l = 0;          // intervals: pixels x0 .. x0 + l
    uint32_t tri = 0;        // triangle id (over all objects)
    uint32_t obj = 0;        // object index
    host::SpanEnds ends;     // N1, N2, H1, H2 (world space, unit)
};

struct Frame {
    int w = 0, h = 0;
    std::vector<int32_t> tri_id;   // per pixel: the visible triangle, -1 for background
    std::vector<double> depth;     // per pixel: NDC depth of the visible surface
    std::vector<Span> spans;       // every span with at least one visible pixel, in raster order
    dvec3 light_dir;               // unit, toward the light
    uint64_t triangles = 0;        // triangles set up
    uint64_t skipped_near = 0;     // triangles with a vertex behind the camera's near plane (not drawn)
    uint64_t back_facing = 0;      // triangles seen from behind (drawn with their normals reversed)
    uint64_t hidden_spans = 0;     // spans entirely behind other surfaces (not sent to the core)
    std::vector<uint8_t> flipped;  // per triangle id: 1 if drawn from behind (normals reversed)

    bool visible(const Span& s, uint32_t i) const {
        return tri_id[size_t(s.y) * size_t(w) + size_t(s.x0) + i] == int32_t(s.tri);
    }
};

// Rasterizes every object of the scene into a w x h frame. The scene must be valid (Scene::validate).
Frame rasterize(const Scene& sc, int w, int h);

}  // namespace render
}  // namespace spec
