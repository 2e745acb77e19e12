// heightmap.h - the height maps of companion paper C's measurements (sim/methods/parallax.h): generated,
// deterministic (no library distribution), repeating, bilinear between texel centres.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace spec {
namespace methods {

struct HeightMap {
    std::string name;
    int size = 0;                 // size x size texels, repeating
    std::vector<float> texel;     // [0, 1], row-major (v rows, u columns)
    double lipschitz = 0;         // bound on |grad h| in texture units (h per unit of u, v)

    // Bilinear between texel centres ((i + 0.5) / size), repeating.
    double at(double u, double v) const;
    // The gradient of the bilinear interpolant (texture units), for normals.
    void gradient(double u, double v, double* du, double* dv) const;
    float tex(int i, int j) const;  // texel (column i, row j), wrapped
};

// "waves" (smooth sines), "bumps" (round domes), "bricks" (bevelled bricks, steep), "rocks" (cobblestones
// from a seeded Voronoi pattern plus value noise: the real-looking one). size: 16..2048. Throws
// std::invalid_argument for another name.
HeightMap make_heightmap(const std::string& name, int size);
std::vector<std::string> heightmap_names();

// Periodic fractal value noise on [0, 1)^2 (base frequency f0, octaves), in [0, 1]: the maps' grain, and the
// albedo of the rendered quad.
double fbm(double u, double v, int f0, int octaves, uint32_t seed);

}  // namespace methods
}  // namespace spec
