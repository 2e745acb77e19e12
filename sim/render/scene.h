// scene.h - what is rendered: objects (mesh + material), one directional light, a perspective camera.
#pragma once

#include <string>
#include <vector>

#include "mesh.h"

namespace spec {
namespace render {

struct Material {
    dvec3 color{0.8, 0.8, 0.8};       // diffuse and ambient colour, channels in [0, 1]
    double ka = 0.15;                  // ambient coefficient
    double kd = 0.6;                   // diffuse coefficient
    double ks = 0.8;                   // specular coefficient
    dvec3 spec_color{1.0, 1.0, 1.0};   // specular colour, channels in [0, 1]
    unsigned n = 10;                   // specular exponent, 0..1023
};

struct Object {
    std::string name;
    Mesh mesh;  // world coordinates
    Material mat;
};

// A light at infinity: L is the same at every point (the patent's assumption). The viewer is local:
// V = normalize(eye - P) per vertex, so H = normalize(L + V) changes over the picture.
struct Light {
    dvec3 dir{0.4, 0.7, 0.6};         // toward the light (normalized when the scene is built)
    dvec3 color{1.0, 1.0, 1.0};       // channels in [0, 1]
    double intensity = 1.0;           // Is
};

struct Camera {
    dvec3 eye{0.0, 0.0, 6.0};
    dvec3 target{0.0, 0.0, 0.0};
    dvec3 up{0.0, 1.0, 0.0};
    double fov_deg = 40.0;            // vertical field of view
};

struct Scene {
    std::string name;
    std::vector<Object> objects;
    Light light;
    dvec3 ambient{1.0, 1.0, 1.0};     // ambient light colour
    dvec3 background{0.05, 0.06, 0.09};
    Camera camera;
    ObjStats obj;                     // an OBJ scene: what the reader met (loaded = false otherwise)

    // Throws InputError on what cannot be rendered: a zero-length or non-finite light direction or camera
    // vector, eye = target, up parallel to the view direction, fov outside (0, 180), colours or coefficients
    // outside their ranges, n > 1023, Is * ks >= 1 is allowed (C saturates and is counted).
    void validate() const;
};

// The built-in scenes: "default" (five objects, n = 1, 3, 10, 100, 1000, one per BRDF range of Fig. 10
// and beyond), "sphere", "torus", "teapot". Throws InputError for another name.
Scene make_scene(const std::string& name);
std::vector<std::string> scene_names();
// The default direction from a model's centre toward the camera (slightly from above).
inline dvec3 default_view() { return dvec3(0.0, 0.35, 1.0); }
// One object from an OBJ file (load_obj), with material m, moved and scaled so that its bounding sphere is the
// unit sphere at the origin (any model size renders: the rasterizer's near and far planes are fixed), and
// the camera framing that sphere from direction `view` (toward the camera, any length > 0): the whole model
// is in the picture. Throws InputError for a bad file or a zero or non-finite view.
// fov_deg: the vertical field of view the framing is for (outside (0, 180): the default's 40 degrees).
Scene scene_from_obj(const std::string& path, const Material& m, const dvec3& view = default_view(),
                     double fov_deg = 40.0);
// Turns the camera about its target: the eye moves to the target + |eye - target| * normalize(view); the up
// vector changes only when it would be parallel to the view. Throws InputError for a zero or non-finite view.
void set_view(Camera& c, const dvec3& view);

}  // namespace render
}  // namespace spec
