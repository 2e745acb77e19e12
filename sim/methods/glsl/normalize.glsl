// normalize.glsl - companion paper B's ways of making unit vectors along a span, in GLSL (GLSL 3.30 and
// later; C++ reference: sim/methods/normalize.h, normalize.cpp). A span runs from pixel 0 to pixel l; a and b
// are its end vectors (unit where the function says so), i the pixel (0..l). Per pixel and without state,
// so a fragment shader can call them; the recurrence and the halving walk from the span's start to pixel i
// (a compute shader that owns a span would run them once for every pixel).

// Classic Phong: normalize(lerp).
vec3 nzFull(vec3 a, vec3 b, int i, int l) {
    if (i == 0) return a;
    if (i == l) return b;
    return normalize(a + (b - a) * (float(i) / float(l)));
}

// The GPU's inversesqrt.
vec3 nzRsqrt(vec3 a, vec3 b, int i, int l) {
    if (i == 0) return a;
    if (i == l) return b;
    vec3 c = a + (b - a) * (float(i) / float(l));
    return c * inversesqrt(dot(c, c));
}

// Unit ends, the lerp corrected by one Newton step for 1 / |N|: N (1.5 - 0.5 N.N).
vec3 nzNewton(vec3 a, vec3 b, int i, int l) {
    if (i == 0) return a;
    if (i == l) return b;
    vec3 c = a + (b - a) * (float(i) / float(l));
    return c * (1.5 - 0.5 * dot(c, c));
}

// Unit ends, slerp by the recurrence N(i+1) = 2 cos(phi) N(i) - N(i-1), phi = psi / l.
vec3 nzRecurrence(vec3 a, vec3 b, int i, int l) {
    if (i == 0) return a;
    if (i == l) return b;
    float c = clamp(dot(a, b), -1.0, 1.0);
    vec3 w = b - a * c;
    float wl = length(w);
    if (wl < 1e-6 || c < -0.999) return normalize(a + (b - a) * (float(i) / float(l)));
    float phi = acos(c) / float(l);
    float k = 2.0 * cos(phi);
    vec3 prev = a, cur = a * cos(phi) + (w / wl) * sin(phi);
    for (int j = 1; j < i; ++j) {
        vec3 next = cur * k - prev;
        prev = cur;
        cur = next;
    }
    return cur;
}

// The paper's halving (diffuseLen = specularLen = 2: never stop early) and adaptive method (stop at the first
// level where zN / 2 >= diffuseLen and zN zH / 4 >= specularLen, then lerp inside the segment), for N and H
// together: the span extended to 2^k intervals by the paper's normalize(a + (b - a) 2^k / l), and the
// midpoint of unit Na, Nb being (Na + Nb) / z with z = sqrt(2 + z) from one level to the next.
void nzHalving(vec3 n1, vec3 n2, vec3 h1, vec3 h2, int i, int l, float diffuseLen, float specularLen,
               out vec3 n, out vec3 h) {
    if (i == 0 || l <= 1 || i == l) {
        n = i == 0 ? n1 : n2;
        h = i == 0 ? h1 : h2;
        return;
    }
    int L2 = 1;
    while (L2 < l) L2 *= 2;
    vec3 ne = n2, he = h2;
    if (L2 != l) {
        float s = float(L2) / float(l);
        ne = normalize(n1 + (n2 - n1) * s);
        he = normalize(h1 + (h2 - h1) * s);
    }
    float zn = sqrt(2.0 + 2.0 * dot(n1, ne)), zh = sqrt(2.0 + 2.0 * dot(h1, he));
    if (zn < 1e-6 || zh < 1e-6) {
        n = nzFull(n1, n2, i, l);
        h = nzFull(h1, h2, i, l);
        return;
    }
    // the segment [lo, lo + seg] holding pixel i, its end vectors
    int lo = 0, seg = L2;
    vec3 na = n1, nb = ne, ha = h1, hb = he;
    while (seg > 1) {
        if (0.5 * zn >= diffuseLen && 0.25 * zn * zh >= specularLen) break;
        int mid = seg / 2;
        vec3 nm = (na + nb) / zn, hm = (ha + hb) / zh;
        if (i == lo + mid) {
            n = nm;
            h = hm;
            return;
        }
        if (i < lo + mid) {
            nb = nm;
            hb = hm;
        } else {
            lo += mid;
            na = nm;
            ha = hm;
        }
        zn = sqrt(2.0 + zn);
        zh = sqrt(2.0 + zh);
        seg = mid;
    }
    float f = float(i - lo) / float(seg);  // a shift in fixed point
    n = na + (nb - na) * f;
    h = ha + (hb - ha) * f;
}
