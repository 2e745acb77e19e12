// parallax.glsl - companion paper C's parallax methods in GLSL (GLSL 3.30 and later; C++ reference:
// sim/methods/parallax.h, parallax.cpp). Tangent space, texture units: the polygon is z = 0, the relief
// z = s h(u, v) with h in [0, 1]; V is the unit vector toward the viewer (V.z > 0). Each function returns t,
// the distance along V: the texture coordinates to shade with are p0 + t * V.xy.
//
// The caller provides
//     float pmHeight(vec2 uv);    // h at uv, in [0, 1] (e.g. texture(heightMap, uv).r)
//     vec2 pmGradient(vec2 uv);   // grad h at uv, texture units (pmPremecz only; e.g. from a normal map)
// Budgets count height fetches; the iterations stop early at |d| <= threshold.

float pmF(vec2 p0, vec3 V, float s, float t) { return t * V.z - s * pmHeight(p0 + t * V.xy); }

// Kaneko (2001): t = s h(P0) / Vz.
float pmKaneko(vec2 p0, vec3 V, float s) { return s * pmHeight(p0) / V.z; }

// Welsh (2004), offset limiting: t = s h(P0).
float pmWelsh(vec2 p0, vec3 V, float s) { return s * pmHeight(p0); }

// Welsh with scale and bias -s/2 (the polygon taken as the relief's mean level): from the slab's mid-plane.
float pmWelshBias(vec2 p0, vec3 V, float s) {
    float tm = 0.5 * s / V.z;
    return tm + s * (pmHeight(p0 + tm * V.xy) - 0.5);
}

// The paper's iteration (4)-(5): t <- t + d, d = s h(P(t)) - t Vz, from t0 (0: the paper; s / Vz: the
// slab's top). fetches: how many it spent.
float pmIterate(vec2 p0, vec3 V, float s, float threshold, int budget, float t0, out int fetches) {
    float t = t0;
    fetches = 0;
    for (int i = 0; i < budget; ++i) {
        float d = s * pmHeight(p0 + t * V.xy) - t * V.z;
        ++fetches;
        if (abs(d) <= threshold) break;
        t += d;
    }
    return t;
}

// Premecz (2006), the iteration with slope information: t <- t + d N_z from the slab's top.
float pmPremecz(vec2 p0, vec3 V, float s, float threshold, int budget, out int fetches) {
    float t = s / V.z;
    fetches = 0;
    for (int i = 0; i < budget; ++i) {
        vec2 p = p0 + t * V.xy;
        float d = s * pmHeight(p) - t * V.z;
        ++fetches;
        if (abs(d) <= threshold) break;
        vec2 g = s * pmGradient(p);
        t += d / sqrt(1.0 + dot(g, g));
    }
    return t;
}

// A linear search of up to `steps` samples t_k = T (1 - k / (steps + 1)) for the first below the relief,
// then `refine` steps inside the bracket: bisections (secantRefine false) or regula falsi, at least the
// samples the search left when spendAll. end: 0 the first sample below (steep parallax), 1 the bracket's
// midpoint (relief mapping), 2 the secant through it (POM, interval mapping).
float pmSearch(vec2 p0, vec3 V, float s, int steps, int refine, bool secantRefine, int end, bool spendAll,
               out int fetches) {
    float T = s / V.z;
    float lo = 0.0, hi = T, flo = 0.0, fhi = 0.0;
    bool loKnown = false, hiKnown = false;
    fetches = 0;
    for (int k = 1; k <= steps; ++k) {
        float t = T * (1.0 - float(k) / float(steps + 1));
        float f = pmF(p0, V, s, t);
        ++fetches;
        if (f <= 0.0) {
            lo = t;
            flo = f;
            loKnown = true;
            break;
        }
        hi = t;
        fhi = f;
        hiKnown = true;
    }
    if (spendAll) refine = max(refine, steps + refine - fetches);
    for (int r = 0; r < refine; ++r) {
        float t = (secantRefine && loKnown && hiKnown) ? hi - fhi * (hi - lo) / (fhi - flo) : 0.5 * (lo + hi);
        float f = pmF(p0, V, s, t);
        ++fetches;
        if (f <= 0.0) {
            lo = t;
            flo = f;
            loKnown = true;
        } else {
            hi = t;
            fhi = f;
            hiKnown = true;
        }
    }
    if (end == 0) return lo;
    if (end == 2 && loKnown && hiKnown) return hi - fhi * (hi - lo) / (fhi - flo);
    return 0.5 * (lo + hi);
}

// A linear search of max(1, budget / 4) samples brackets the first hit, then the paper's iteration from the
// bracket's upper end, kept inside the bracket.
float pmHybrid(vec2 p0, vec3 V, float s, float threshold, int budget, out int fetches) {
    float T = s / V.z;
    int L = max(1, budget / 4);
    float lo = 0.0, hi = T, fhi = 0.0;
    bool hiKnown = false;
    fetches = 0;
    for (int k = 1; k <= L; ++k) {
        float t = T * (1.0 - float(k) / float(L + 1));
        float f = pmF(p0, V, s, t);
        ++fetches;
        if (f <= 0.0) {
            lo = t;
            break;
        }
        hi = t;
        fhi = f;
        hiKnown = true;
    }
    float t = hi, f = fhi;
    bool have = hiKnown, stepped = false, converged = false;
    for (int guard = 0; guard <= budget; ++guard) {
        if (!have) {
            if (fetches >= budget) break;
            f = pmF(p0, V, s, t);
            ++fetches;
        }
        if (abs(f) <= threshold) {
            converged = true;
            break;
        }
        t = clamp(t - f, lo, hi);
        have = false;
        stepped = true;
    }
    if (!stepped && !converged) t = 0.5 * (lo + hi);
    return t;
}

// The budgeted methods by the C++ reference's numbering (parallax.h, Pm): 1 kaneko, 2 welsh, 3 welsh-bias,
// 4 paper, 5 paper-top, 6 premecz, 7 hybrid, 8 steep, 9 pom, 10 relief, 11 interval.
float pmRun(int method, vec2 p0, vec3 V, float s, int budget, float threshold, out int fetches) {
    budget = max(1, budget);
    int B = min(6, budget / 3);
    fetches = 1;
    if (method == 1) return pmKaneko(p0, V, s);
    if (method == 2) return pmWelsh(p0, V, s);
    if (method == 3) return pmWelshBias(p0, V, s);
    if (method == 4) return pmIterate(p0, V, s, threshold, budget, 0.0, fetches);
    if (method == 5) return pmIterate(p0, V, s, threshold, budget, s / V.z, fetches);
    if (method == 6) return pmPremecz(p0, V, s, threshold, budget, fetches);
    if (method == 7) return pmHybrid(p0, V, s, threshold, budget, fetches);
    if (method == 8) return pmSearch(p0, V, s, budget, 0, false, 0, false, fetches);
    if (method == 9) return pmSearch(p0, V, s, budget, 0, false, 2, false, fetches);
    if (method == 10) return pmSearch(p0, V, s, budget - B, B, false, 1, true, fetches);
    if (method == 11) return pmSearch(p0, V, s, budget - B, B, true, 2, true, fetches);
    fetches = 0;
    return 0.0;
}
