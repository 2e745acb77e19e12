#include "scene.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace spec {
namespace render {

namespace {
constexpr double kPi = 3.14159265358979323846;

bool finite(const dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void check_vec(const dvec3& v, const std::string& what) {
    if (!finite(v)) throw InputError(what + " is not finite");
    if (glm::length(v) < 1e-12) throw InputError(what + " has zero length");
}

void check_color(const dvec3& c, const std::string& what) {
    if (!finite(c) || c.x < 0 || c.y < 0 || c.z < 0 || c.x > 1 || c.y > 1 || c.z > 1) {
        throw InputError(what + " must have channels in [0, 1]");
    }
}

void check_coef(double k, const std::string& what) {
    if (!std::isfinite(k) || k < 0.0 || k > 1.0) throw InputError(what + " must be in [0, 1]");
}

Object object(const std::string& name, Mesh mesh, const glm::dmat4& place, const Material& mat) {
    mesh.transform(place);
    return Object{name, std::move(mesh), mat};
}

glm::dmat4 at(double x, double y, double z, double scale, double yaw_deg = 0, double pitch_deg = 0) {
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), dvec3(x, y, z));
    m = glm::rotate(m, glm::radians(yaw_deg), dvec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(pitch_deg), dvec3(1, 0, 0));
    return glm::scale(m, dvec3(scale));
}

Material mat(dvec3 color, double ks, unsigned n, double kd = 0.6, double ka = 0.15) {
    Material m;
    m.color = color;
    m.ks = ks;
    m.n = n;
    m.kd = kd;
    m.ka = ka;
    return m;
}

// The teapot centred on the origin horizontally, base at y = 0.
Mesh centred_teapot(int subdiv) {
    Mesh t = make_teapot(subdiv);
    t.transform(glm::translate(glm::dmat4(1.0), dvec3(-0.2625, 0.0, 0.0)));
    return t;
}
}  // namespace

void Scene::validate() const {
    if (objects.empty()) throw InputError("the scene has no objects");
    check_vec(light.dir, "light direction");
    check_color(light.color, "light colour");
    if (!std::isfinite(light.intensity) || light.intensity < 0) throw InputError("light intensity must be >= 0");
    check_color(ambient, "ambient light");
    check_color(background, "background");
    if (!finite(camera.eye) || !finite(camera.target)) throw InputError("camera position is not finite");
    check_vec(camera.target - camera.eye, "view direction (target - eye)");
    check_vec(camera.up, "camera up vector");
    if (glm::length(glm::cross(glm::normalize(camera.target - camera.eye), glm::normalize(camera.up))) < 1e-6) {
        throw InputError("camera up vector is parallel to the view direction");
    }
    if (!std::isfinite(camera.fov_deg) || camera.fov_deg <= 0 || camera.fov_deg >= 180) {
        throw InputError("field of view must be in (0, 180) degrees");
    }
    for (const auto& o : objects) {
        check_color(o.mat.color, o.name + ": colour");
        check_color(o.mat.spec_color, o.name + ": specular colour");
        check_coef(o.mat.ka, o.name + ": ka");
        check_coef(o.mat.kd, o.name + ": kd");
        check_coef(o.mat.ks, o.name + ": ks");
        if (o.mat.n > 1023) throw InputError(o.name + ": n must be in 0..1023");
        o.mesh.validate(o.name);
    }
}

std::vector<std::string> scene_names() { return {"default", "sphere", "torus", "teapot"}; }

Scene make_scene(const std::string& name) {
    Scene s;
    s.name = name;
    s.light.dir = glm::normalize(dvec3(-0.45, 0.75, 0.5));
    if (name == "default") {
        // One object per BRDF range of Fig. 10 (n = 1: cos, 3: cos^4, 10: cos^16, and the sharp end of
        // cos^16 at 100 and 1000). ks keeps Is*ks*a(n)*255 (the core's worst absolute error) under 3 levels.
        s.camera.eye = dvec3(0.0, 3.3, 8.2);
        s.camera.target = dvec3(0.0, 1.3, 0.0);
        s.camera.fov_deg = 36.0;
        s.objects.push_back(object("sphere n=1", make_sphere(64, 32), at(-1.85, 0.6, 0.9, 0.6),
                                   mat({0.25, 0.45, 0.85}, 0.5, 1)));
        s.objects.push_back(object("torus n=3", make_torus(1.0, 0.36, 64, 32), at(-1.25, 2.1, -1.6, 0.75, 15, 60),
                                   mat({0.25, 0.7, 0.35}, 0.5, 3)));
        s.objects.push_back(object("teapot n=10", centred_teapot(10), at(0.0, 0.0, 0.4, 0.42, -20),
                                   mat({0.85, 0.3, 0.2}, 0.6, 10)));
        s.objects.push_back(object("sphere n=100", make_sphere(64, 32), at(1.85, 0.6, 0.9, 0.6),
                                   mat({0.85, 0.65, 0.2}, 0.7, 100)));
        s.objects.push_back(object("torus n=1000", make_torus(1.0, 0.36, 64, 32), at(1.25, 2.1, -1.6, 0.75, -15, 60),
                                   mat({0.6, 0.6, 0.65}, 0.8, 1000)));
        return s;
    }
    if (name == "sphere") {
        s.camera.eye = dvec3(0.0, 0.0, 4.0);
        s.objects.push_back(object("sphere", make_sphere(96, 48), glm::dmat4(1.0), mat({0.8, 0.3, 0.25}, 0.7, 30)));
        return s;
    }
    if (name == "torus") {
        s.camera.eye = dvec3(0.0, 1.6, 4.2);
        s.objects.push_back(object("torus", make_torus(1.0, 0.4, 96, 48), at(0, 0, 0, 1.0, 0, 35),
                                   mat({0.3, 0.6, 0.8}, 0.7, 60)));
        return s;
    }
    if (name == "teapot") {
        s.camera.eye = dvec3(0.0, 2.2, 5.6);
        s.camera.target = dvec3(0.0, 0.75, 0.0);
        s.objects.push_back(object("teapot", centred_teapot(14), at(0, 0, 0, 0.55, -30), mat({0.8, 0.75, 0.7}, 0.7, 50)));
        return s;
    }
    std::string names;
    for (const auto& n : scene_names()) names += (names.empty() ? "" : ", ") + n;
    throw InputError("unknown scene '" + name + "' (one of " + names + ")");
}

void set_view(Camera& c, const dvec3& view) {
    check_vec(view, "view direction");
    const double l = std::max({std::fabs(view.x), std::fabs(view.y), std::fabs(view.z)});
    const dvec3 dir = glm::normalize(view / l);
    const double dist = glm::length(c.eye - c.target);
    c.eye = c.target + dir * dist;
    const dvec3 up = glm::normalize(c.up);
    if (std::fabs(glm::dot(up, dir)) > 0.999) {   // looking along up: take the world axis most across the view
        const dvec3 axes[3] = {dvec3(0, 1, 0), dvec3(0, 0, -1), dvec3(1, 0, 0)};
        dvec3 best = axes[0];
        for (const dvec3& ax : axes) {
            if (std::fabs(glm::dot(ax, dir)) < std::fabs(glm::dot(best, dir))) best = ax;
        }
        c.up = best;
    }
}

Scene scene_from_obj(const std::string& path, const Material& m, const dvec3& view, double fov_deg) {
    Scene s;
    s.name = path;
    s.light.dir = glm::normalize(dvec3(-0.45, 0.75, 0.5));
    Object o{path, load_obj(path, &s.obj), m};
    // bounding sphere: the box's centre and the farthest vertex, in coordinates divided by the largest magnitude
    // (no overflow for huge models, no underflow for tiny ones)
    Mesh& mesh = o.mesh;
    double big = 0;
    for (const dvec3& p : mesh.pos) big = std::max({big, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
    if (!(big > 0)) big = 1;
    dvec3 lo(INFINITY), hi(-INFINITY);
    for (const dvec3& p : mesh.pos) {
        lo = glm::min(lo, p / big);
        hi = glm::max(hi, p / big);
    }
    const dvec3 c = 0.5 * lo + 0.5 * hi;
    double r = 0;
    for (const dvec3& p : mesh.pos) r = std::max(r, glm::length(p / big - c));
    if (!(r > 0)) throw InputError(path + ": every vertex is at the same point");
    for (dvec3& p : mesh.pos) p = (p / big - c) / r;   // normals unchanged: a uniform scale and a shift
    s.camera.target = dvec3(0.0);
    if (fov_deg > 0 && fov_deg < 180) s.camera.fov_deg = fov_deg;
    // the unit sphere seen under the vertical field of view (the image is square), with 15 % to spare
    s.camera.eye = dvec3(0.0, 0.0, 1.15 / std::sin(0.5 * s.camera.fov_deg * kPi / 180.0));
    set_view(s.camera, view);
    s.objects.push_back(std::move(o));
    return s;
}

}  // namespace render
}  // namespace spec
