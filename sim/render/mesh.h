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

// An OBJ file: triangles only (a face with more than three vertices is an error, not triangulated
// silently), positions and normals finite, normals non-zero. Without 'vn' records the normals are the
// angle-weighted averages of the faces around each position.
Mesh load_obj(const std::string& path);
// Writes v / vn / f records (positions and normals with 17 significant digits), atomically.
void write_obj(const Mesh& m, const std::string& path);

extern const int kTeapotPatches[32][16];
extern const double kTeapotVertices[306][3];

}  // namespace render
}  // namespace spec
