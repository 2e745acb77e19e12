#version 330 core
// The parallax library in a fragment shader, as a user would call it (validated by glslangValidator, ctest
// glsl_validate): the height in a texture's red channel, the gradient from a normal map.
uniform sampler2D heightMap;
uniform sampler2D normalMap;
uniform float depth;
in vec2 uv;
in vec3 viewTangent;
out vec4 color;

float pmHeight(vec2 p) { return texture(heightMap, p).r; }
vec2 pmGradient(vec2 p) {
    vec3 n = texture(normalMap, p).xyz * 2.0 - 1.0;
    return -n.xy / (n.z * depth);
}

#pragma methods_library

void main() {
    vec3 V = normalize(viewTangent);
    int fetches;
    float t = pmRun(5, uv, V, depth, 8, depth / 512.0, fetches);
    color = vec4(texture(heightMap, uv + t * V.xy).rrr, 1.0);
}
