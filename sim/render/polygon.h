// polygon.h - triangulation of one polygonal face (an OBJ face with more than three vertices).
//
// tinyobjloader 2.0.0~rc10 (Debian 12) can triangulate, but it splits a quad by its shorter diagonal (outside
// the quad when the quad is concave) and clips ears of an n-gon in a projection whose convexity test takes the
// wrong sign when the polygon winds clockwise there: the 'U' of tests/test_obj.cpp, seen from behind, comes out
// as a fan of overlapping triangles (area 11 where the polygon has 7). So the renderer reads faces untriangulated
// and clips ears itself, in the plane of the face's Newell normal, where the polygon always winds
// counter-clockwise (docs/renderer.md).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace spec {
namespace render {

// The polygon's normal by Newell's method: the sum of (p_i - c) x (p_{i+1} - c) over the edges, twice the
// vector area; zero for a polygon without area (all points on a line).
glm::dvec3 newell_normal(const std::vector<glm::dvec3>& pts);

// Triangles (indices into pts) covering a simple polygon, convex or concave, planar or nearly so; each wound
// like the polygon (counter-clockwise about its Newell normal); n - 2 of them for n vertices in general
// position, fewer when points repeat or lie on a line (those add no area and make no triangle). Empty when the
// polygon has no area. A self-intersecting polygon gets triangles too (ear clipping, then a fan of what is
// left), never an error.
std::vector<std::array<uint32_t, 3>> triangulate_polygon(const std::vector<glm::dvec3>& pts);

}  // namespace render
}  // namespace spec
