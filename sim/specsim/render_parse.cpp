// render_parse.cpp - specsim render's options: argv -> RenderOptions -> the scene.
#include <string>
#include <vector>

#include "cli.h"
#include "cmd_render.h"
#include "commands.h"

namespace spec {

const char* const kRenderUsage =
    "  render   a scene rendered by scanline spans, the specular term from the chosen model; PNG output\n"
    "           --scene NAME   default | sphere | torus | teapot (default: default)\n"
    "           --obj FILE     an OBJ file instead: polygons triangulated, smooth normals where 'vn' is missing,\n"
    "                          zero or not finite; scaled into the unit sphere at the origin and framed\n"
    "           --size N       image N x N pixels, 16..4096 (default 512)\n"
    "           --model M      rtl (Verilated spec_unit, default) | golden (bit-exact model) |\n"
    "                          ref (double, exact Blinn-Phong for the interpolated vectors) |\n"
    "                          prototype (cos^2(sqrt(n/2) zeta), Abbas et al.) | host (host angles, exact cos^n) |\n"
    "                          shader (Verilated spec_shader: span ends in, setup and core in RTL; docs/setup.md)\n"
    "           --shader-config C  ecp5 (default) | up5k: the shader's configuration (--model shader, docs/setup.md)\n"
    "           --mode M       patent (default) | tuned | pow: the rtl and golden models' mode (docs/tuned.md,\n"
    "                          docs/pow.md)\n"
    "           --out FILE     the rendered PNG (required)\n"
    "           --panel FILE   also render ref and prototype: PNG of ref | model | prototype | error maps\n"
    "           --stats FILE   also render ref, prototype, host: errors against ref as JSON\n"
    "           --amp A        error-map amplification (default 16: 16 levels of error = full scale)\n"
    "           --rgb MODE     once (core run once per span, colour applied on the host; default) |\n"
    "                          per-channel (three runs per span, C per channel)\n"
    "           --host RULE    patent (gamma = angle(H1, H2'), eq. 4; default) | midpoint (gamma fitted to\n"
    "                          N.H at the span's middle too: exact when N.H is a sinusoid, docs/host.md)\n"
    "           --progress / --quiet   progress bar on stderr (default: when stderr is a terminal)\n"
    "           --cull-specular  the chosen model skips triangles where a bound on N.H shows the core would output\n"
    "                          0 (companion paper A; the image is unchanged; docs/methods.md)\n"
    "           light:    --light-dir X,Y,Z (toward the light)  --light-color R,G,B  --light-intensity Is\n"
    "                     --ambient R,G,B\n"
    "           material (every object; an OBJ gets these): --n N (0..1023)  --ks K  --kd K  --ka K\n"
    "                     --color R,G,B  --spec-color R,G,B   (coefficients and channels in [0, 1])\n"
    "           camera:   --view X,Y,Z (direction from the target toward the eye: turns the camera about\n"
    "                     the model; default for an OBJ 0,0.35,1)  --eye X,Y,Z  --target X,Y,Z  --up X,Y,Z\n"
    "                     --fov DEGREES (vertical)\n"
    "  render-bench  speed of the render: host spans/s, golden and rtl pixels/s (medians, ratios)\n"
    "           --size N (default 512)  --runs R (3..15, default 5)  --scene NAME\n"
    "           --json FILE (also write the figures as JSON: medians and ranges of the runs)\n"
    "  plots    the patent's Fig. 5 and Fig. 9 redrawn (gnuplot): --out-dir DIR (fig5.png, fig9.png, .dat)\n"
    "  export-obj  a built-in scene's meshes as one OBJ file: --scene NAME --out FILE.obj\n";

namespace {
using render::dvec3;

dvec3 parse_vec3(const std::string& flag, const std::string& s) {
    std::vector<double> v;
    size_t a = 0;
    for (;;) {
        const size_t b = s.find(',', a);
        v.push_back(parse_double(flag, s.substr(a, b == std::string::npos ? std::string::npos : b - a)));
        if (b == std::string::npos) break;
        a = b + 1;
    }
    if (v.size() != 3) throw UsageError(flag + ": expected three comma-separated numbers X,Y,Z, got '" + s + "'");
    return dvec3(v[0], v[1], v[2]);
}
}  // namespace

RenderOptions parse_render(int argc, char** argv) {
    RenderOptions r;
    bool have_scene = false;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string f = a.flag();
        if (f == "--scene") { r.scene = a.value(f); have_scene = true; }
        else if (f == "--obj") r.obj = a.value(f);
        else if (f == "--size") r.size = int(parse_int(f, a.value(f), 16, 4096));
        else if (f == "--model") r.model = render::parse_model(a.value(f));
        else if (f == "--shader-config") {
            try {
                r.shader_config = parse_setup_config(a.value(f));
            } catch (const std::invalid_argument& e) {
                throw UsageError(std::string("--shader-config: ") + e.what());
            }
        }
        else if (f == "--mode") {
            const std::string m = a.value(f);
            if (m == "patent") r.mode = Mode::patent;
            else if (m == "tuned") r.mode = Mode::tuned;
            else if (m == "pow") r.mode = Mode::pow;
            else throw UsageError("--mode: '" + m + "' is not patent, tuned or pow");
        }
        else if (f == "--out") r.out = a.value(f);
        else if (f == "--panel") r.panel = a.value(f);
        else if (f == "--stats") r.stats = a.value(f);
        else if (f == "--amp") {
            r.amp = parse_double(f, a.value(f));
            if (r.amp < 1 || r.amp > 255) throw UsageError("--amp: must be in [1, 255]");
        } else if (f == "--rgb") {
            const std::string m = a.value(f);
            if (m == "once") r.rgb = render::RgbMode::once;
            else if (m == "per-channel") r.rgb = render::RgbMode::per_channel;
            else throw UsageError("--rgb: '" + m + "' is not once or per-channel");
        } else if (f == "--host") {
            const std::string m = a.value(f);
            if (m == "patent") r.gamma = host::GammaRule::patent;
            else if (m == "midpoint") r.gamma = host::GammaRule::midpoint;
            else throw UsageError("--host: '" + m + "' is not patent or midpoint");
        } else if (f == "--progress") r.progress = 1;
        else if (f == "--quiet") r.progress = 0;
        else if (f == "--cull-specular") r.cull = true;
        else if (f == "--light-dir") { r.light_dir = parse_vec3(f, a.value(f)); r.has_light_dir = true; }
        else if (f == "--light-color") { r.light_color = parse_vec3(f, a.value(f)); r.has_light_color = true; }
        else if (f == "--light-intensity") { r.intensity = parse_double(f, a.value(f)); r.has_intensity = true; }
        else if (f == "--ambient") { r.ambient = parse_vec3(f, a.value(f)); r.has_ambient = true; }
        else if (f == "--n") { r.n = parse_int(f, a.value(f), 0, 1023); r.has_n = true; }
        else if (f == "--ks") { r.ks = parse_double(f, a.value(f)); r.has_ks = true; }
        else if (f == "--kd") { r.kd = parse_double(f, a.value(f)); r.has_kd = true; }
        else if (f == "--ka") { r.ka = parse_double(f, a.value(f)); r.has_ka = true; }
        else if (f == "--color") { r.color = parse_vec3(f, a.value(f)); r.has_color = true; }
        else if (f == "--spec-color") { r.spec_color = parse_vec3(f, a.value(f)); r.has_spec_color = true; }
        else if (f == "--eye") { r.eye = parse_vec3(f, a.value(f)); r.has_eye = true; }
        else if (f == "--target") { r.target = parse_vec3(f, a.value(f)); r.has_target = true; }
        else if (f == "--up") { r.up = parse_vec3(f, a.value(f)); r.has_up = true; }
        else if (f == "--fov") { r.fov = parse_double(f, a.value(f)); r.has_fov = true; }
        else if (f == "--view") { r.view = parse_vec3(f, a.value(f)); r.has_view = true; }
        else throw UsageError("render: unknown option " + f);
    }
    if (have_scene && !r.obj.empty()) throw UsageError("render: --scene and --obj exclude each other");
    if (r.out.empty()) throw UsageError("render: --out FILE.png is required");
    return r;
}

render::Scene build_scene(const RenderOptions& r) {
    render::Material m;
    auto apply = [&](render::Material& x) {
        if (r.has_n) x.n = unsigned(r.n);
        if (r.has_ks) x.ks = r.ks;
        if (r.has_kd) x.kd = r.kd;
        if (r.has_ka) x.ka = r.ka;
        if (r.has_color) x.color = r.color;
        if (r.has_spec_color) x.spec_color = r.spec_color;
    };
    apply(m);
    render::Scene s = r.obj.empty() ? render::make_scene(r.scene)
                                    : render::scene_from_obj(r.obj, m, r.has_view ? r.view : render::default_view(),
                                                             r.has_fov ? r.fov : 40.0);
    if (r.obj.empty()) {
        for (auto& o : s.objects) apply(o.mat);
    }
    if (r.has_light_dir) s.light.dir = r.light_dir;
    if (r.has_light_color) s.light.color = r.light_color;
    if (r.has_intensity) s.light.intensity = r.intensity;
    if (r.has_ambient) s.ambient = r.ambient;
    if (r.has_eye) s.camera.eye = r.eye;
    if (r.has_target) s.camera.target = r.target;
    if (r.has_up) s.camera.up = r.up;
    if (r.has_fov) s.camera.fov_deg = r.fov;
    if (r.has_view && r.obj.empty()) render::set_view(s.camera, r.view);   // an OBJ is framed from the view already
    s.validate();
    return s;
}

}  // namespace spec
