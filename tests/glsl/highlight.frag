#version 330 core
// The highlight library in a fragment shader (validated by glslangValidator, ctest glsl_validate): a triangle's
// vertex normals and halfway vectors as flat inputs; the bound decides whether to evaluate the specular term.
flat in vec3 na;
flat in vec3 nb;
flat in vec3 nc;
flat in vec3 ha;
flat in vec3 hb;
flat in vec3 hc;
in vec3 normal;
in vec3 halfway;
uniform float cullBelow;
uniform float shininess;
out vec4 color;

#pragma methods_library

void main() {
    float bound = hlNhMax(hlConeTriangle(na, nb, nc), hlConeCentroid(ha, hb, hc), 1e-3);
    bool centre = hlPaperTest(na, nb, nc, normalize(ha + hb + hc), true) || hlSphericalSign(na, nb, nc, ha) == 1;
    float s = bound < cullBelow ? 0.0 : pow(max(0.0, dot(normalize(normal), normalize(halfway))), shininess);
    color = vec4(vec3(s), centre ? 1.0 : 0.5);
}
