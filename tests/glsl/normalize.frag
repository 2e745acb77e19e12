#version 330 core
// The normalization library in a fragment shader (validated by glslangValidator, ctest glsl_validate): the
// span's end vectors and its length as flat inputs, the pixel's index along it.
flat in vec3 n1;
flat in vec3 n2;
flat in int spanLength;
in float along;  // 0 at the span's first pixel, spanLength at its last
uniform vec3 lightDir;
out vec4 color;

#pragma methods_library

void main() {
    int i = int(along + 0.5);
    vec3 a = nzFull(n1, n2, i, spanLength) + nzRsqrt(n1, n2, i, spanLength) + nzNewton(n1, n2, i, spanLength) +
             nzRecurrence(n1, n2, i, spanLength);
    vec3 n, h;
    nzHalving(n1, n2, n1, n2, i, spanLength, 0.99, 0.99, n, h);
    color = vec4(vec3(max(0.0, dot(normalize(a + n), lightDir))), 1.0);
}
