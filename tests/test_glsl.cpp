// The GLSL versions of the companion methods (sim/methods/glsl/) run for real on Mesa's software rasterizer
// (llvmpipe through OSMesa: no GPU, no display) as compute shaders over the test grids, against the C++
// references in double precision. The tolerances are float's, stated per test; ctest glsl_validate checks the
// same sources with glslangValidator.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "nh_bound.h"
#include "highlight.h"
#include "highlight_tests.h"
#include "normalize.h"
#include "parallax_eval.h"

using namespace spec::methods;

namespace {
std::string read_file(const std::string& p) {
    std::ifstream f(p);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

// The harness tests/glsl/NAME.comp with the library sim/methods/glsl/NAME.glsl in place of its pragma line.
std::string shader_source(const std::string& name) {
    const std::string dir = SPEC_SOURCE_DIR;
    std::string h = read_file(dir + "/tests/glsl/" + name + ".comp");
    const std::string lib = read_file(dir + "/sim/methods/glsl/" + name + ".glsl");
    const std::string tag = "#pragma methods_library";
    const size_t at = h.find(tag);
    if (at == std::string::npos || lib.empty()) return "";
    return h.replace(at, tag.size(), lib);
}

class Gl : public ::testing::Test {
protected:
    void SetUp() override {
        const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                               OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
        ctx_ = OSMesaCreateContextAttribs(attribs, nullptr);
        ASSERT_NE(ctx_, nullptr) << "OSMesa: no OpenGL 4.3 core context";
        pixels_.resize(16 * 16 * 4);
        ASSERT_TRUE(OSMesaMakeCurrent(ctx_, pixels_.data(), GL_UNSIGNED_BYTE, 16, 16));
        const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
        ASSERT_NE(renderer, nullptr);
        std::printf("OpenGL %s on %s\n", glGetString(GL_VERSION), renderer);
    }
    void TearDown() override {
        for (GLuint b : buffers_) glDeleteBuffers(1, &b);
        if (program_) glDeleteProgram(program_);
        if (ctx_) OSMesaDestroyContext(ctx_);
    }
    // Compiles and links the harness; fails the test with the driver's log.
    void build(const std::string& name) {
        const std::string src = shader_source(name);
        ASSERT_FALSE(src.empty()) << name;
        const GLuint sh = glCreateShader(GL_COMPUTE_SHADER);
        const char* p = src.c_str();
        glShaderSource(sh, 1, &p, nullptr);
        glCompileShader(sh);
        GLint ok = 0;
        glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
        char log[4096] = {0};
        glGetShaderInfoLog(sh, sizeof log, nullptr, log);
        ASSERT_TRUE(ok) << name << ": " << log;
        program_ = glCreateProgram();
        glAttachShader(program_, sh);
        glLinkProgram(program_);
        glGetProgramiv(program_, GL_LINK_STATUS, &ok);
        glGetProgramInfoLog(program_, sizeof log, nullptr, log);
        glDeleteShader(sh);
        ASSERT_TRUE(ok) << name << ": " << log;
        glUseProgram(program_);
    }
    template <class T>
    GLuint buffer(GLuint binding, const std::vector<T>& data, size_t bytes = 0) {
        GLuint b = 0;
        glGenBuffers(1, &b);
        buffers_.push_back(b);
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, b);
        glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(bytes ? bytes : data.size() * sizeof(T)),
                     data.empty() ? nullptr : data.data(), GL_DYNAMIC_COPY);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, b);
        return b;
    }
    void set(const char* name, int v) { glUniform1i(glGetUniformLocation(program_, name), v); }
    void set(const char* name, float v) { glUniform1f(glGetUniformLocation(program_, name), v); }
    std::vector<float> run(GLuint out, size_t invocations, size_t floats) {
        set("count", int(invocations));
        glDispatchCompute(GLuint((invocations + 63) / 64), 1, 1);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        std::vector<float> r(floats);
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, out);
        glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(floats * sizeof(float)), r.data());
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
        return r;
    }

    OSMesaContext ctx_ = nullptr;
    std::vector<unsigned char> pixels_;
    std::vector<GLuint> buffers_;
    GLuint program_ = 0;
};

NVec rand_unit(std::mt19937_64& rng) {
    std::normal_distribution<double> g(0.0, 1.0);
    return glm::normalize(NVec(g(rng), g(rng), g(rng)));
}
NVec rotate_from(std::mt19937_64& rng, const NVec& a, double psi) {
    const NVec p = glm::normalize(glm::cross(a, rand_unit(rng)));
    return glm::normalize(a * std::cos(psi) + p * std::sin(psi));
}
}  // namespace

// Every parallax method at budgets 1, 4, 8, 16 on the four maps at 30 and 15 degrees (8 x 8 fragments and 8
// azimuths per view). Float against double: on at least 99 % of the fragments of every method and budget the
// texture coordinates agree within 0.1 texel and the fetch counts within one. 0.1 texel is a step of the
// iteration's threshold (threshold / Vh along the ray: 0.04 texel at 30 degrees, 0.09 at 15): where float
// meets the threshold one step earlier or later than double. The rest are fragments where rounding sends
// float down the other branch (a sample on the other side of the relief).
TEST_F(Gl, ParallaxAgreesWithTheCppReference) {
    build("parallax");
    ParallaxSetup p;
    p.grid = 8;
    for (const auto& name : heightmap_names()) {
        const HeightMap m = make_heightmap(name, 256);
        buffer(0, m.texel);
        set("size", m.size);
        set("depth", float(p.depth));
        set("threshold", float(p.thr()));
        for (double el : {30.0, 15.0}) {
            const std::vector<Fragment> fr = fragments(m, p, el);
            std::vector<float> in;
            for (const Fragment& f : fr) {
                in.insert(in.end(), {float(f.u0), float(f.v0), 0.f, 0.f, float(f.V.u), float(f.V.v), float(f.V.h), 0.f});
            }
            buffer(1, in);
            const GLuint out = buffer(2, std::vector<float>(), fr.size() * 4 * sizeof(float));
            for (int method = 1; method <= 11; ++method) {
                for (int budget : {1, 4, 8, 16}) {
                    set("method", method);
                    set("budget", budget);
                    const std::vector<float> r = run(out, fr.size(), fr.size() * 4);
                    size_t close = 0, same_fetches = 0;
                    for (size_t k = 0; k < fr.size(); ++k) {
                        const Fragment& f = fr[k];
                        const Hit h = run_method(Pm(method), m, p.depth, f.u0, f.v0, f.V, budget, p.thr());
                        const double d = std::hypot(double(r[4 * k + 1]) - h.u, double(r[4 * k + 2]) - h.v) * m.size;
                        close += d <= 0.1;
                        if (d > 0.1 && getenv("GLSL_DEBUG")) {
                            std::printf("%s el %g m %d b %d k %zu: cpp t %.6f f %d  glsl t %.6f f %d\n", name.c_str(), el,
                                        method, budget, k, h.t, h.fetches, double(r[4 * k]), int(r[4 * k + 3]));
                        }
                        same_fetches += std::abs(int(r[4 * k + 3]) - h.fetches) <= 1;
                    }
                    EXPECT_GE(close, fr.size() * 99 / 100) << name << " " << el << " deg, " << pm_info(Pm(method)).key
                                                          << " at " << budget;
                    EXPECT_GE(same_fetches, fr.size() * 99 / 100) << name << ", " << pm_info(Pm(method)).key;
                }
            }
        }
    }
}

// Every way of making unit vectors, on 300 random spans of 1..64 intervals whose end vectors are up to 120
// degrees apart: every component of every pixel's N and H within 2e-4 of the C++ reference.
TEST_F(Gl, NormalizeAgreesWithTheCppReference) {
    build("normalize");
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    struct Span {
        NVec n1, n2, h1, h2;
        uint32_t l;
    };
    std::vector<Span> spans;
    std::vector<float> sp;
    std::vector<int32_t> pix;
    for (int k = 0; k < 300; ++k) {
        Span s;
        s.n1 = rand_unit(rng);
        s.n2 = rotate_from(rng, s.n1, u01(rng) * 2.1);
        s.h1 = rand_unit(rng);
        s.h2 = rotate_from(rng, s.h1, u01(rng) * 1.0);
        s.l = 1 + uint32_t(rng() % 64);
        spans.push_back(s);
        for (const NVec& v : {s.n1, s.n2, s.h1, s.h2}) sp.insert(sp.end(), {float(v.x), float(v.y), float(v.z), 0.f});
        sp[sp.size() - 16 + 3] = float(s.l);
        for (uint32_t i = 0; i <= s.l; ++i) pix.insert(pix.end(), {k, int32_t(i)});
    }
    buffer(0, sp);
    buffer(1, pix);
    const size_t n = pix.size() / 2;
    const GLuint out = buffer(2, std::vector<float>(), n * 8 * sizeof(float));
    NormBounds b;
    const unsigned exponent = 50;
    set("diffuseLen", float(1 - b.diffuse));
    set("specularLen", float(std::pow(1 - b.specular, 1.0 / exponent)));
    for (NormMode mode : norm_modes()) {
        set("mode", int(mode));
        const std::vector<float> r = run(out, n, n * 8);
        double worst = 0;
        size_t k = 0;
        for (const Span& s : spans) {
            SpanVectors v;
            NormOps ops;
            interpolate_span(s.n1, s.n2, s.h1, s.h2, s.l, mode, b, exponent, &v, &ops);
            for (uint32_t i = 0; i <= s.l; ++i, ++k) {
                for (int c = 0; c < 3; ++c) {
                    worst = std::max(worst, std::fabs(double(r[8 * k + c]) - v.n[i][c]));
                    worst = std::max(worst, std::fabs(double(r[8 * k + 4 + c]) - v.h[i][c]));
                }
            }
        }
        EXPECT_LE(worst, 2e-4) << norm_mode_name(mode);
        std::printf("%-10s largest difference %.2e\n", norm_mode_name(mode), worst);
    }
}

// The paper's test, the exact test and the N.H bound on 20 000 random triangles (normals in caps of 10 and
// 30 degrees): the verdicts agree on at least 99.9 % of them, the bounds within 5e-4 (float's sin r from
// cos r near 1 loses digits): nh_bound.h's margin for float, 1e-3, keeps the float bound conservative.
TEST_F(Gl, HighlightAgreesWithTheCppReference) {
    build("highlight");
    std::mt19937_64 rng(6);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    // per triangle: three normals and H in a cap around c, three halfway vectors in a cap around c2, up to
    // 60 degrees from c (the caps overlap on some, not on others)
    std::vector<std::array<NVec, 7>> tris;
    std::vector<float> in;
    for (int k = 0; k < 20000; ++k) {
        const NVec c = rand_unit(rng), c2 = rotate_from(rng, c, u01(rng) * 1.05);
        const double r = (k % 2 ? 10.0 : 30.0) * 3.14159265358979 / 180;
        std::array<NVec, 7> t;
        for (int i = 0; i < 7; ++i) t[size_t(i)] = rotate_from(rng, i < 4 ? c : c2, u01(rng) * r);
        tris.push_back(t);
        for (const NVec& v : t) in.insert(in.end(), {float(v.x), float(v.y), float(v.z), 0.f});
    }
    buffer(0, in);
    const GLuint out = buffer(1, std::vector<float>(), tris.size() * 8 * sizeof(float));
    const std::vector<float> r = run(out, tris.size(), tris.size() * 8);
    size_t dom = 0, xoy = 0, exact = 0;
    double worst_t = 0, worst_c = 0;
    auto v3 = [](const NVec& v) { return nhb::Vec3<double>{v.x, v.y, v.z}; };
    for (size_t k = 0; k < tris.size(); ++k) {
        const auto& t = tris[k];
        dom += (r[8 * k] > 0.5) == paper_test(t[0], t[1], t[2], t[3], ProjPlane::dominant).inside;
        xoy += (r[8 * k + 1] > 0.5) == paper_test(t[0], t[1], t[2], t[3], ProjPlane::xoy).inside;
        const nhb::Vec3<double> a = v3(t[0]), b = v3(t[1]), c = v3(t[2]), h = v3(t[3]);
        exact += int(std::lround(r[8 * k + 2])) == spherical_sign_t(a, b, c, h);
        const nhb::Vec3<double> vh[3] = {v3(t[4]), v3(t[5]), v3(t[6])}, vn[3] = {a, b, c};
        const double tight = nhb::nh_max(nhb::cone_of_triangle(a, b, c), nhb::cone_of_triangle(vh[0], vh[1], vh[2]), 0.0);
        const double cheap = nhb::nh_max(nhb::cone_of_cluster(vn, 3), nhb::cone_of_cluster(vh, 3), 0.0);
        worst_t = std::max(worst_t, std::fabs(double(r[8 * k + 4]) - tight));
        worst_c = std::max(worst_c, std::fabs(double(r[8 * k + 5]) - cheap));
    }
    EXPECT_GE(dom, tris.size() * 999 / 1000);
    EXPECT_GE(xoy, tris.size() * 999 / 1000);
    EXPECT_GE(exact, tris.size() * 999 / 1000);
    EXPECT_LE(worst_t, 5e-4);
    EXPECT_LE(worst_c, 5e-4);
    std::printf("agreement: paper dominant %zu, XOY %zu, exact %zu of %zu; nh_max within %.1e / %.1e\n", dom, xoy, exact,
                tris.size(), worst_t, worst_c);
}
