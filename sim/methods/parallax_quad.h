// parallax_quad.h - a relief-mapped quad ray-cast per pixel, one image per parallax method (the pictures of
// `specsim parallax --out-dir`).
#pragma once

#include <vector>

#include "image.h"
#include "parallax.h"

namespace spec {
namespace methods {

struct QuadView {
    int width = 256, height = 192;
    double elevation_deg = 30;  // camera elevation over the quad
    double s = 0.06;            // relief depth (texture units)
    double repeats = 2;         // texture repeats across the quad
    double threshold = 0;       // the iterations' threshold (0: s / 512)
    int budget = 8;             // height fetches
};
// Renders the quad with the method's texture coordinates: albedo and normal (from the height map's gradient)
// at (u', v'), Blinn-Phong with one light. uv_err (optional): per pixel |(u', v') - exact| in texels.
render::Image render_quad(const HeightMap& m, const QuadView& q, Pm method, std::vector<double>* uv_err = nullptr);

}  // namespace methods
}  // namespace spec
