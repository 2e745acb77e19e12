// obj.cpp - OBJ files in and out (mesh.h: load_obj, write_obj): a line-by-line check tinyobjloader does not
// make, tinyobjloader's reading of the records, polygons triangulated here (polygon.h), smooth normals where the
// file has none or an unusable one.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include <glm/geometric.hpp>
#include <tiny_obj_loader.h>

#include "fileutil.h"
#include "mesh.h"
#include "polygon.h"

namespace spec {
namespace render {

namespace {
std::string trim(const std::string& s) {
    const size_t a = s.find_first_not_of(" \t\r");
    if (a == std::string::npos) return "";
    const size_t b = s.find_last_not_of(" \t\r");
    return s.substr(a, b - a + 1);
}

bool parse_real(const std::string& s, double* v) {
    errno = 0;
    char* end = nullptr;
    *v = std::strtod(s.c_str(), &end);
    return end != s.c_str() && *end == '\0';
}

bool parse_index(const std::string& s) {
    if (s.empty()) return false;
    char* end = nullptr;
    const long v = std::strtol(s.c_str(), &end, 10);
    return *end == '\0' && v != 0;
}

// The checks tinyobjloader does not make (it reads "v 1 x 2" as (1, 0, 2)): every v / vn / vt / f record well
// formed, positions finite, faces of three or more vertices. Returns per 'vn' record (in file order) 0 for a
// usable normal, 1 for a zero-length one, 2 for a non-finite one: those are computed instead (load_obj).
std::vector<uint8_t> check_obj_syntax(const std::string& path, std::istream& in) {
    std::vector<uint8_t> vn_bad;
    std::string line;
    int no = 0;
    auto fail = [&](const std::string& why) {
        throw InputError(path + ":" + std::to_string(no) + ": " + why);
    };
    while (std::getline(in, line)) {
        ++no;
        const size_t hash = line.find('#');
        if (hash != std::string::npos) line.resize(hash);
        line = trim(line);
        if (line.empty()) continue;
        std::istringstream is(line);
        std::string key, tok;
        is >> key;
        std::vector<std::string> toks;
        while (is >> tok) toks.push_back(tok);
        if (key == "v" || key == "vn" || key == "vt") {
            std::vector<double> x;
            for (const auto& t : toks) {
                double v;
                if (!parse_real(t, &v)) fail("malformed '" + key + "' record: '" + t + "' is not a number");
                x.push_back(v);
            }
            const size_t k = x.size();
            if (key == "v" && !(k == 3 || k == 4 || k == 6 || k == 7)) fail("a vertex needs 3 coordinates");
            if (key == "vn" && k != 3) fail("a normal needs 3 coordinates");
            if (key == "vt" && (k < 1 || k > 3)) fail("a texture coordinate needs 1 to 3 numbers");
            bool finite_all = true;
            for (double v : x) finite_all = finite_all && std::isfinite(v);
            if (key == "vn") {
                vn_bad.push_back(!finite_all ? 2 : (x[0] == 0.0 && x[1] == 0.0 && x[2] == 0.0) ? 1 : 0);
            } else if (!finite_all) {
                fail("'" + key + "' record is not finite (" + line + ")");
            }
        } else if (key == "f") {
            if (toks.size() < 3) fail("a face needs 3 vertices");
            for (const auto& t : toks) {
                // v, v/vt, v//vn, v/vt/vn
                std::vector<std::string> parts;
                size_t a = 0;
                for (size_t b; (b = t.find('/', a)) != std::string::npos; a = b + 1) parts.push_back(t.substr(a, b - a));
                parts.push_back(t.substr(a));
                bool ok = parts.size() <= 3 && parse_index(parts[0]);
                if (ok && parts.size() >= 2 && !parts[1].empty()) ok = parse_index(parts[1]);
                if (ok && parts.size() == 3) ok = parse_index(parts[2]);
                if (ok && parts.size() == 2 && parts[1].empty()) ok = false;
                if (!ok) fail("malformed face vertex '" + t + "'");
            }
        }
        // other records (o, g, s, usemtl, mtllib, l, p, ...) do not affect the triangles
    }
    return vn_bad;
}
}  // namespace

Mesh load_obj(const std::string& path, ObjStats* stats) {
    std::vector<uint8_t> vn_bad;
    {
        std::ifstream in(path);
        if (!in) throw InputError("cannot read OBJ file '" + path + "'");
        vn_bad = check_obj_syntax(path, in);
    }
    tinyobj::ObjReaderConfig cfg;
    cfg.triangulate = false;   // polygons are clipped here (polygon.h says why)
    cfg.vertex_color = false;
    const size_t slash = path.find_last_of('/');
    cfg.mtl_search_path = slash == std::string::npos ? "./" : path.substr(0, slash + 1);
    tinyobj::ObjReader r;
    if (!r.ParseFromFile(path, cfg)) {
        std::string e = r.Error();
        while (!e.empty() && (e.back() == '\n' || e.back() == '\r')) e.pop_back();
        const size_t nl = e.find('\n');
        throw InputError(path + ": " + (nl == std::string::npos ? e : e.substr(0, nl)));
    }
    const auto& at = r.GetAttrib();
    const size_t nv = at.vertices.size() / 3, nn = at.normals.size() / 3;
    // positions divided by their largest magnitude for the geometry below: huge and tiny models alike
    double big = 0;
    for (double c : at.vertices) big = std::max(big, std::fabs(c));
    if (!(big > 0)) big = 1;
    auto scaled = [&](int v) {
        const auto* p = &at.vertices[3 * size_t(v)];
        return dvec3(p[0] / big, p[1] / big, p[2] / big);
    };
    ObjStats st;
    st.loaded = true;
    Mesh m;
    std::map<std::pair<int, int>, uint32_t> index;  // (position, usable normal or -1) -> vertex
    std::vector<int> pos_of;                          // vertex -> position index
    std::vector<bool> given;                          // vertex has a usable OBJ normal
    std::vector<dvec3> poly;
    std::vector<uint32_t> corner;
    for (const auto& sh : r.GetShapes()) {
        size_t k = 0;
        for (size_t f = 0; f < sh.mesh.num_face_vertices.size(); ++f) {
            const int fv = sh.mesh.num_face_vertices[f];
            ++st.faces;
            if (fv > 3) ++st.polygons;
            poly.clear();
            corner.clear();
            for (int c = 0; c < fv; ++c) {
                const auto& ix = sh.mesh.indices[k++];
                if (ix.vertex_index < 0 || size_t(ix.vertex_index) >= nv) {
                    throw InputError(path + ": face " + std::to_string(st.faces) + " refers to a vertex that does not exist");
                }
                if (ix.normal_index >= 0 && (size_t(ix.normal_index) >= nn || size_t(ix.normal_index) >= vn_bad.size())) {
                    throw InputError(path + ": face " + std::to_string(st.faces) + " refers to a normal that does not exist");
                }
                const uint8_t bad = ix.normal_index >= 0 ? vn_bad[size_t(ix.normal_index)] : 0;
                const int normal = ix.normal_index >= 0 && bad == 0 ? ix.normal_index : -1;
                const auto key = std::make_pair(ix.vertex_index, normal);
                auto it = index.find(key);
                if (it == index.end()) {
                    const auto* p = &at.vertices[3 * size_t(ix.vertex_index)];
                    m.pos.emplace_back(p[0], p[1], p[2]);
                    if (normal >= 0) {
                        const auto* q = &at.normals[3 * size_t(normal)];
                        const dvec3 nq(q[0], q[1], q[2]);
                        const double l = std::max({std::fabs(nq.x), std::fabs(nq.y), std::fabs(nq.z)});
                        m.nrm.push_back(glm::normalize(nq / l));
                    } else {
                        m.nrm.emplace_back(0.0);
                        if (ix.normal_index < 0) ++st.normals_missing;
                        else if (bad == 1) ++st.normals_zero;
                        else ++st.normals_not_finite;
                    }
                    pos_of.push_back(ix.vertex_index);
                    given.push_back(normal >= 0);
                    it = index.emplace(key, uint32_t(m.pos.size() - 1)).first;
                }
                corner.push_back(it->second);
                poly.push_back(scaled(ix.vertex_index));
            }
            const auto tris = fv == 3 ? std::vector<std::array<uint32_t, 3>>{{0, 1, 2}} : triangulate_polygon(poly);
            for (const auto& t : tris) {
                const dvec3 e = glm::cross(poly[t[1]] - poly[t[0]], poly[t[2]] - poly[t[0]]);
                if (!(glm::length(e) > 0)) {   // no area: nothing to draw, no direction to give a normal
                    ++st.degenerate;
                    continue;
                }
                m.tri.push_back({corner[t[0]], corner[t[1]], corner[t[2]]});
            }
            if (tris.size() < size_t(fv - 2)) st.degenerate += size_t(fv - 2) - tris.size();
        }
    }
    if (m.tri.empty()) {
        throw InputError(path + (st.faces ? ": no face has an area" : ": no triangles"));
    }
    st.triangles = m.tri.size();
    // Smooth normals where the file gives none or an unusable one: the angle-weighted average of the unit normals
    // of the faces around the position (Thuermer and Wuethrich), in the scaled coordinates.
    std::vector<dvec3> acc(nv, dvec3(0));
    std::vector<dvec3> any(nv, dvec3(0));   // a face normal at the position, for sums that cancel
    if (st.normals_missing + st.normals_zero + st.normals_not_finite > 0) {
        for (const auto& t : m.tri) {
            const dvec3 p[3] = {scaled(pos_of[t[0]]), scaled(pos_of[t[1]]), scaled(pos_of[t[2]])};
            const dvec3 fn = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
            for (int c = 0; c < 3; ++c) {
                const dvec3 e1 = p[(c + 1) % 3] - p[c], e2 = p[(c + 2) % 3] - p[c];
                const double l1 = glm::length(e1), l2 = glm::length(e2);
                if (!(l1 > 0) || !(l2 > 0)) continue;
                const double ang = std::acos(std::max(-1.0, std::min(1.0, glm::dot(e1, e2) / (l1 * l2))));
                acc[size_t(pos_of[t[c]])] += ang * fn;
                any[size_t(pos_of[t[c]])] = fn;
            }
        }
        for (size_t v = 0; v < m.pos.size(); ++v) {
            if (given[v]) continue;
            const dvec3 a = acc[size_t(pos_of[v])];
            const double l = glm::length(a);
            m.nrm[v] = l > 1e-12 ? a / l : any[size_t(pos_of[v])];
            if (!(glm::length(m.nrm[v]) > 0.5)) m.nrm[v] = dvec3(0, 0, 1);   // only on slivers of no area
        }
    }
    m.validate(path);
    if (stats) *stats = st;
    return m;
}

void write_obj(const Mesh& m, const std::string& path) {
    write_atomic(path, [&](const std::string& tmp) {
        std::ofstream o(tmp);
        char buf[128];
        o << "# written by specsim\n";
        for (const auto& p : m.pos) {
            std::snprintf(buf, sizeof buf, "v %.17g %.17g %.17g\n", p.x, p.y, p.z);
            o << buf;
        }
        for (const auto& n : m.nrm) {
            std::snprintf(buf, sizeof buf, "vn %.17g %.17g %.17g\n", n.x, n.y, n.z);
            o << buf;
        }
        for (const auto& t : m.tri) o << "f " << t[0] + 1 << "//" << t[0] + 1 << " " << t[1] + 1 << "//" << t[1] + 1
                                      << " " << t[2] + 1 << "//" << t[2] + 1 << "\n";
        o.close();
        if (!o) throw InputError("cannot write " + path);
    });
}

}  // namespace render
}  // namespace spec
