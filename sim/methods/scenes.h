// scenes.h - the scenes the companion papers are measured on: the renderer's built-in scenes, and coarse
// versions of the sphere, torus and teapot of the size companion paper B speaks of (300-1500 triangles).
#pragma once

#include <string>
#include <vector>

#include "scene.h"

namespace spec {
namespace methods {

// "sphere-lo" (528 triangles), "torus-lo" (1024), "teapot-lo" (552), or a built-in scene (render::make_scene,
// which throws InputError for an unknown name).
render::Scene methods_scene(const std::string& name);
std::vector<std::string> coarse_scene_names();
std::vector<std::string> methods_scene_names();  // the built-in ones, then the coarse ones
// Every material's exponent set to n (the highlight test's coarse rows).
void set_exponent(render::Scene* sc, unsigned n);

}  // namespace methods
}  // namespace spec
