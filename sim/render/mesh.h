// mesh.h - triangle meshes with per-vertex normals: procedural sphere and torus, Newell's teapot
// tessellated from its Bezier patches, OBJ files read with tinyobjloader (and written back).
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "cli.h"

namespace spec {
namespace render {

using glm::dvec3;

// Bad input (a file, an option): one-line message; specsim prints it and exits 2.
// Control characters from the input (an OBJ token, a name) are escaped (spec::printable, rom/gen/cli.h).
using spec::InputError;

struct Mesh {
    std::vector<dvec3> pos;                      // vertex positions
    std::vector<dvec3> nrm;                      // unit vertex normals, same count
    std::vector<std::array<uint32_t, 3>> tri;    // counter-clockwise seen from the front (outside)

    // Positions by m, normals by its inverse transpose (renormalized).
    void transform(const glm::dmat4& m);
    // Throws InputError (naming `what`) on an empty mesh, a bad index, or a non-finite or zero-length
    // position / normal.
    void validate(const std::string& what) const;
    void bounds(dvec3* lo, dvec3* hi) const;
};

// Unit sphere at the origin, `slices` around the y axis, `stacks` from pole to pole.
Mesh make_sphere(int slices, int stacks);
// Torus around the y axis: ring radius R, tube radius r.
Mesh make_torus(double R, double r, int major, int minor);
// Newell's teapot, y up, base at y = 0, as in the data (height 3.15 units); each patch a grid of
// `subdiv` x `subdiv` quads, normals from the patch derivatives.
Mesh make_teapot(int subdiv);

// What load_obj met in an OBJ file (specsim render prints it and puts it in the statistics JSON).
struct ObjStats {
    bool loaded = false;
    uint64_t faces = 0;               // 'f' records
    uint64_t polygons = 0;            // faces of more than three vertices, triangulated (polygon.h)
    uint64_t triangles = 0;           // triangles made
    uint64_t degenerate = 0;          // triangles of no area left out (collinear or repeated points)
    uint64_t normals_missing = 0;     // vertices without a 'vn': smooth normal computed
    uint64_t normals_zero = 0;        // vertices whose 'vn' has zero length: computed
    uint64_t normals_not_finite = 0;  // vertices whose 'vn' is not finite (nan, inf): computed
    uint64_t normals_computed() const { return normals_missing + normals_zero + normals_not_finite; }
};

// An OBJ file: faces of three or more vertices (convex or concave polygons are triangulated, polygon.h),
// positions finite. Where a vertex has no 'vn', or a zero-length or non-finite one, its normal is the angle-
// weighted average of the unit normals of the faces around its position (smooth shading); given normals are
// normalized. Throws InputError (one line) for a malformed file, a face that refers to a missing vertex or
// normal, or a file without a face of non-zero area. stats (optional) receives the counts.
Mesh load_obj(const std::string& path, ObjStats* stats = nullptr);
// Writes v / vn / f records (positions and normals with 17 significant digits), atomically.
void write_obj(const Mesh& m, const std::string& path);

extern const int kTeapotPatches[32][16];
extern const double kTeapotVertices[306][3];

}  // namespace render
}  // namespace spec
