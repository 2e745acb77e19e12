// cmd_plots.cpp - specsim plots (the patent's Fig. 5 and Fig. 9 redrawn, sim/render/plots.cpp computes and
// draws) and specsim export-obj (a built-in scene's meshes as one OBJ file).
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

#include "cli.h"
#include "commands.h"
#include "mesh.h"
#include "plots.h"
#include "scene.h"

namespace spec {

int cmd_plots(int argc, char** argv) {
    std::string dir;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string f = a.flag();
        if (f == "--out-dir") dir = a.value(f);
        else throw UsageError("plots: unknown option " + f);
    }
    if (dir.empty()) throw UsageError("plots: --out-dir DIR is required");
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw InputError("cannot create " + dir + ": " + ec.message());
    std::cout << render::make_plots(dir);
    std::cout << "plots: " << dir << "/fig5.png, " << dir << "/fig9.png (data: fig5.dat, fig9.dat, script fig.gp)\n";
    return 0;
}

namespace {
// All objects of a scene in one mesh (world coordinates), as export-obj writes it.
render::Mesh scene_mesh(const render::Scene& s) {
    render::Mesh all;
    for (const auto& o : s.objects) {
        const uint32_t base = uint32_t(all.pos.size());
        all.pos.insert(all.pos.end(), o.mesh.pos.begin(), o.mesh.pos.end());
        all.nrm.insert(all.nrm.end(), o.mesh.nrm.begin(), o.mesh.nrm.end());
        for (auto t : o.mesh.tri) all.tri.push_back({t[0] + base, t[1] + base, t[2] + base});
    }
    return all;
}
}  // namespace

int cmd_export_obj(int argc, char** argv) {
    std::string scene, out;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string f = a.flag();
        if (f == "--scene") scene = a.value(f);
        else if (f == "--out") out = a.value(f);
        else throw UsageError("export-obj: unknown option " + f);
    }
    if (scene.empty() || out.empty()) throw UsageError("export-obj: --scene NAME and --out FILE are required");
    const render::Mesh all = scene_mesh(render::make_scene(scene));
    render::write_obj(all, out);
    std::printf("%s: %zu vertices, %zu triangles\n", out.c_str(), all.pos.size(), all.tri.size());
    return 0;
}

}  // namespace spec
