#version 430 core
// Runs sim/methods/glsl/normalize.glsl over random spans (tests/test_glsl.cpp): one invocation per pixel.
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Spans { vec4 span[]; };   // n1, n2, h1, h2 (xyz); n1.w = l
layout(std430, binding = 1) readonly buffer Pixels { ivec2 pix[]; };  // (span, i)
layout(std430, binding = 2) writeonly buffer Results { vec4 res[]; }; // n, h
uniform int count;
uniform int mode;  // 0 full, 1 rsqrt, 2 newton, 3 recurrence, 4 halving, 5 adaptive
uniform float diffuseLen;
uniform float specularLen;

#pragma methods_library

void main() {
    int id = int(gl_GlobalInvocationID.x);
    if (id >= count) return;
    int s = pix[id].x, i = pix[id].y;
    vec3 n1 = span[4 * s].xyz, n2 = span[4 * s + 1].xyz, h1 = span[4 * s + 2].xyz, h2 = span[4 * s + 3].xyz;
    int l = int(span[4 * s].w);
    vec3 n, h;
    if (mode == 0) { n = nzFull(n1, n2, i, l); h = nzFull(h1, h2, i, l); }
    else if (mode == 1) { n = nzRsqrt(n1, n2, i, l); h = nzRsqrt(h1, h2, i, l); }
    else if (mode == 2) { n = nzNewton(n1, n2, i, l); h = nzNewton(h1, h2, i, l); }
    else if (mode == 3) { n = nzRecurrence(n1, n2, i, l); h = nzRecurrence(h1, h2, i, l); }
    else if (mode == 4) nzHalving(n1, n2, h1, h2, i, l, 2.0, 2.0, n, h);
    else nzHalving(n1, n2, h1, h2, i, l, diffuseLen, specularLen, n, h);
    res[2 * id] = vec4(n, 0.0);
    res[2 * id + 1] = vec4(h, 0.0);
}
