#version 430 core
// Runs sim/methods/glsl/highlight.glsl over random triangles (tests/test_glsl.cpp): one invocation each.
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Tris { vec4 tri[]; };   // na, nb, nc, h, ha, hb, hc (xyz)
layout(std430, binding = 1) writeonly buffer Results { vec4 res[]; };
uniform int count;

#pragma methods_library

void main() {
    int id = int(gl_GlobalInvocationID.x);
    if (id >= count) return;
    vec3 a = tri[7 * id].xyz, b = tri[7 * id + 1].xyz, c = tri[7 * id + 2].xyz, h = tri[7 * id + 3].xyz;
    vec3 ha = tri[7 * id + 4].xyz, hb = tri[7 * id + 5].xyz, hc = tri[7 * id + 6].xyz;
    // the paper's test (dominant, XOY), the exact test, and nh_max with the tight and the centroid cones
    res[2 * id] = vec4(hlPaperTest(a, b, c, h, true) ? 1.0 : 0.0, hlPaperTest(a, b, c, h, false) ? 1.0 : 0.0,
                       float(hlSphericalSign(a, b, c, h)), 0.0);
    res[2 * id + 1] = vec4(hlNhMax(hlConeTriangle(a, b, c), hlConeTriangle(ha, hb, hc), 0.0),
                           hlNhMax(hlConeCentroid(a, b, c), hlConeCentroid(ha, hb, hc), 0.0), 0.0, 0.0);
}
