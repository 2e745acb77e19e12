#version 430 core
// Runs sim/methods/glsl/parallax.glsl over a grid of fragments (tests/test_glsl.cpp): one invocation per
// fragment, the height map in a buffer, bilinear between texel centres and repeating as the C++ reference's
// HeightMap::at.
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Heights { float texel[]; };
layout(std430, binding = 1) readonly buffer Fragments { vec4 frag[]; };  // (u0, v0, 0, 0), (Vx, Vy, Vz, 0)
layout(std430, binding = 2) writeonly buffer Results { vec4 res[]; };    // (t, u, v, fetches)
uniform int size;
uniform int count;
uniform int method;
uniform int budget;
uniform float depth;
uniform float threshold;

float tex(int i, int j) { return texel[((j % size + size) % size) * size + ((i % size + size) % size)]; }

float pmHeight(vec2 uv) {
    vec2 x = uv * float(size) - 0.5;
    vec2 f0 = floor(x);
    ivec2 ij = ivec2(f0);
    vec2 f = x - f0;
    float a = tex(ij.x, ij.y) + f.x * (tex(ij.x + 1, ij.y) - tex(ij.x, ij.y));
    float b = tex(ij.x, ij.y + 1) + f.x * (tex(ij.x + 1, ij.y + 1) - tex(ij.x, ij.y + 1));
    return a + f.y * (b - a);
}

vec2 pmGradient(vec2 uv) {
    vec2 x = uv * float(size) - 0.5;
    vec2 f0 = floor(x);
    ivec2 ij = ivec2(f0);
    vec2 f = x - f0;
    int i = ij.x, j = ij.y;
    return float(size) * vec2((1.0 - f.y) * (tex(i + 1, j) - tex(i, j)) + f.y * (tex(i + 1, j + 1) - tex(i, j + 1)),
                              (1.0 - f.x) * (tex(i, j + 1) - tex(i, j)) + f.x * (tex(i + 1, j + 1) - tex(i + 1, j)));
}

#pragma methods_library

void main() {
    int id = int(gl_GlobalInvocationID.x);
    if (id >= count) return;
    vec2 p0 = frag[2 * id].xy;
    vec3 V = frag[2 * id + 1].xyz;
    int fetches;
    float t = pmRun(method, p0, V, depth, budget, threshold, fetches);
    res[id] = vec4(t, p0 + t * V.xy, float(fetches));
}
