// fuzz_obj - the renderer's OBJ reader (sim/render/mesh.h, load_obj, through tinyobjloader) on any file
// contents. Promise: a mesh of triangles (polygons triangulated, polygon.h) with finite positions, unit-length
// finite normals (computed where the file has none or an unusable one) and indices in range, or an InputError
// with a one-line message (specsim render --obj: exit 2); no other exception.
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>

#include "fuzz_input.h"
#include "mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string path = "/tmp/fuzz_obj_" + std::to_string(::getpid()) + ".obj";
    {
        std::ofstream f(path, std::ios::binary | std::ios::trunc);
        f.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    }
    try {
        const spec::render::Mesh mesh = spec::render::load_obj(path);
        fuzz::check(mesh.pos.size() == mesh.nrm.size(), "positions and normals differ in number");
        for (size_t k = 0; k < mesh.pos.size(); ++k) {
            const auto& p = mesh.pos[k];
            const auto& n = mesh.nrm[k];
            fuzz::check(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z), "position not finite");
            const double len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
            fuzz::check(std::isfinite(len) && std::fabs(len - 1.0) < 1e-6, "normal not unit length");
        }
        for (const auto& t : mesh.tri)
            for (uint32_t i : t) fuzz::check(i < mesh.pos.size(), "index out of range");
    } catch (const spec::render::InputError& x) {   // the reader's one kind of rejection; any other escapes
        fuzz::one_line(x.what());
    }
    ::unlink(path.c_str());
    return 0;
}
