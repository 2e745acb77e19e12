// highlight.glsl - companion paper A's per-triangle tests and the N.H cone bound in GLSL (GLSL 3.30 and
// later; C++ reference: sim/methods/highlight_tests.h and the standalone header sim/methods/nh_bound.h).
// All vectors unit.

vec2 hlProj(vec3 v, int drop) { return drop == 0 ? v.yz : (drop == 1 ? v.zx : v.xy); }

// The paper's projected test: true when H' is inside the triangle of the lines through the projected arc
// midpoints parallel to the projected chords. dominant: drop the coordinate in which |h| is largest (else the
// paper's XOY). A vertex on its own line (no area) counts as inside.
bool hlPaperTest(vec3 na, vec3 nb, vec3 nc, vec3 h, bool dominant) {
    int drop = 2;
    if (dominant) {
        vec3 ah = abs(h);
        drop = (ah.x >= ah.y && ah.x >= ah.z) ? 0 : (ah.y >= ah.z ? 1 : 2);
    }
    vec3 n[3] = vec3[3](na, nb, nc);
    vec2 hp = hlProj(h, drop);
    bool inside = true;
    for (int k = 0; k < 3; ++k) {
        vec3 b = n[(k + 1) % 3], c = n[(k + 2) % 3];
        vec2 pb = hlProj(b, drop), pc = hlProj(c, drop), pk = hlProj(n[k], drop);
        vec2 dir = pc - pb;
        vec3 sum = b + c;
        float len2 = dot(sum, sum);
        vec2 m = len2 > 0.0 ? hlProj(sum, drop) * inversesqrt(len2) : pb;
        float sv = dir.x * (pk.y - m.y) - dir.y * (pk.x - m.x);
        float sh = dir.x * (hp.y - m.y) - dir.y * (hp.x - m.x);
        if (abs(sv) < 1e-15 || dot(dir, dir) < 1e-30) continue;
        if ((sv > 0.0 && sh < 0.0) || (sv < 0.0 && sh > 0.0)) inside = false;
    }
    return inside;
}

// The exact test where it is fast: 1 inside (or on the boundary), 0 outside, -1 undecided (the normals not
// in an open hemisphere around their sum, or nearly on one great circle).
int hlSphericalSign(vec3 na, vec3 nb, vec3 nc, vec3 h) {
    vec3 g = na + nb + nc;
    float s0 = dot(na, cross(nb, nc));
    if (!(dot(g, na) > 0.0 && dot(g, nb) > 0.0 && dot(g, nc) > 0.0) || abs(s0) < 1e-14) return -1;
    if (dot(h, g) <= 0.0) return 0;
    float d1 = dot(na, cross(nb, h)), d2 = dot(nb, cross(nc, h)), d3 = dot(nc, cross(na, h));
    if (s0 > 0.0) return (d1 >= 0.0 && d2 >= 0.0 && d3 >= 0.0) ? 1 : 0;
    return (d1 <= 0.0 && d2 <= 0.0 && d3 <= 0.0) ? 1 : 0;
}

// A cone (cap) holding unit vectors: xyz the axis, w = cos r; invalid (r >= 90 degrees) when w <= 0.
vec4 hlCapAround(vec3 dir, vec3 a, vec3 b, vec3 c) {
    float len2 = dot(dir, dir);
    if (!(len2 > 0.0)) return vec4(0.0, 0.0, 1.0, -2.0);
    vec3 axis = dir * inversesqrt(len2);
    return vec4(axis, min(dot(axis, a), min(dot(axis, b), dot(axis, c))));
}

// Per triangle, cheap: the cap around the normalized sum (nh_bound.h's cone_of_cluster with k = 3).
vec4 hlConeCentroid(vec3 a, vec3 b, vec3 c) { return hlCapAround(a + b + c, a, b, c); }

// Per triangle, tight: the best of five caps (nh_bound.h's cone_of_triangle).
vec4 hlConeTriangle(vec3 a, vec3 b, vec3 c) {
    vec3 sum = a + b + c;
    vec3 circ = cross(b - a, c - a);
    if (dot(circ, sum) < 0.0) circ = -circ;
    vec4 best = hlCapAround(a + b, a, b, c);
    vec4 k = hlCapAround(b + c, a, b, c);
    if (k.w > best.w) best = k;
    k = hlCapAround(c + a, a, b, c);
    if (k.w > best.w) best = k;
    k = hlCapAround(circ, a, b, c);
    if (k.w > best.w) best = k;
    k = hlCapAround(sum, a, b, c);
    if (k.w > best.w) best = k;
    return best;
}

// >= N.H for every N in cone cn and H in cone ch (1 when a cone is invalid or they overlap).
float hlNhMax(vec4 cn, vec4 ch, float margin) {
    if (cn.w <= 0.0 || ch.w <= 0.0) return 1.0;
    float sn = sqrt(1.0 - cn.w * cn.w), sh = sqrt(1.0 - ch.w * ch.w);
    float cth = dot(cn.xyz, ch.xyz);
    float sth = length(cross(cn.xyz, ch.xyz));
    float cal = cn.w * ch.w - sn * sh, sal = sn * ch.w + cn.w * sh;
    if (cth >= cal) return 1.0;
    return min(1.0, cth * cal + sth * sal + margin);
}
