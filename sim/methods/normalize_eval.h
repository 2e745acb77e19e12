// normalize_eval.h - companion paper B measured (`specsim normalize`, docs/methods.md; the verdict tests call
// these functions with the document's parameters): every interpolation method on a scene, its operation
// counts and its error against classic Phong (full).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "normalize.h"

namespace spec {
namespace methods {

struct NormRow {
    std::string scene;
    NormMode mode = NormMode::full;
    uint64_t triangles = 0;
    NormOps ops;
    double max_deficit = 0;     // largest 1 - |N| over the visible pixels
    double rel_diffuse = 0;     // largest relative error of the diffuse term against full (where it is >= 0.05)
    double rel_specular = 0;    // ... of the specular term (where full's is >= 1 level of 255)
    int image_max = 0;          // largest difference against full's image, levels of 255
    uint64_t image_differing = 0;
    // against halving (the same directions normalized: what the paper's bounds speak of)
    double rel_diffuse_h = 0, rel_specular_h = 0;
    int image_max_h = 0;
    double seconds = 0;         // CPU time of the shading loop (not reproducible: --timing only)
    uint64_t pixels() const { return ops.vectors / 2; }
    uint64_t spans() const { return ops.spans / 2; }
};
// Every mode of norm_modes() on the scene at size x size, in that order.
std::vector<NormRow> evaluate_normalize(const std::string& label, const render::Scene& sc, int size,
                                        const NormBounds& b);

}  // namespace methods
}  // namespace spec
