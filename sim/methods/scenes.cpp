// scenes.cpp - the companion papers' scenes (scenes.h).
#include "scenes.h"

#include <glm/gtc/matrix_transform.hpp>

namespace spec {
namespace methods {

render::Scene methods_scene(const std::string& name) {
    using render::dvec3;
    auto place = [](double scale, double yaw, double pitch) {
        glm::dmat4 m = glm::rotate(glm::dmat4(1.0), glm::radians(yaw), dvec3(0, 1, 0));
        m = glm::rotate(m, glm::radians(pitch), dvec3(1, 0, 0));
        return glm::scale(m, dvec3(scale));
    };
    if (name == "sphere-lo") {
        render::Scene s = render::make_scene("sphere");
        s.name = name;
        s.objects[0].mesh = render::make_sphere(24, 12);
        return s;
    }
    if (name == "torus-lo") {
        render::Scene s = render::make_scene("torus");
        s.name = name;
        render::Mesh m = render::make_torus(1.0, 0.4, 32, 16);
        m.transform(place(1.0, 0, 35));  // as the built-in torus scene
        s.objects[0].mesh = m;
        return s;
    }
    if (name == "teapot-lo") {
        render::Scene s = render::make_scene("teapot");
        s.name = name;
        render::Mesh m = render::make_teapot(3);
        m.transform(glm::translate(glm::dmat4(1.0), dvec3(-0.2625, 0.0, 0.0)));  // centred, as the built-in one
        m.transform(place(0.55, -30, 0));
        s.objects[0].mesh = m;
        return s;
    }
    return render::make_scene(name);
}

std::vector<std::string> coarse_scene_names() { return {"sphere-lo", "torus-lo", "teapot-lo"}; }

std::vector<std::string> methods_scene_names() {
    std::vector<std::string> v = render::scene_names();
    for (const auto& s : coarse_scene_names()) v.push_back(s);
    return v;
}

void set_exponent(render::Scene* sc, unsigned n) {
    for (auto& o : sc->objects) o.mat.n = n;
}

}  // namespace methods
}  // namespace spec
