#include "setup_small_model.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace spec {

namespace {
constexpr int X = 0, Y = 1, Z = 2;
}

SmallSetupModel::SmallSetupModel(const SmallSetupFormat& sf, const Format& core)
    : sf_(sf), cf_(core), k_(small_setup_consts(sf)), log2_(make_small_log2(sf)), exp2_(make_small_exp2(sf)) {
    core.validate();
    if (sf.zf < core.ang_frac + 1) throw std::invalid_argument("setup format: zf must exceed the core's ang_frac");
    // the RTL's (spec_setup_backend) needs, which the model's arithmetic alone would not
    if (sf.ef <= core.c_w) throw std::invalid_argument("setup format: ef must exceed the core's C width");
    if (sf.tb + sf.rb > sf.f) throw std::invalid_argument("setup format: tb + rb must be at most f");
}

void SmallSetupModel::check(int64_t v, int bits, const char* what) const {
    const int64_t lim = int64_t(1) << (bits - 1);
    if (v < -lim || v >= lim) throw std::logic_error(std::string("setup model: ") + what + " leaves its " +
                                                     std::to_string(bits) + "-bit width");
}

bool SmallSetupModel::prescale(const int32_t q[3], Vec* v) const {
    int32_t m = 0;
    for (int k = 0; k < 3; ++k) m = std::max(m, q[k] < 0 ? -q[k] : q[k]);
    if (m == 0) return false;
    int e = 0;
    while ((int64_t(2) << e) <= m) ++e;   // 2^e <= m < 2^(e+1)
    const int s = sf_.f - 1 - e;           // >= f - vec_w >= 0
    for (int k = 0; k < 3; ++k) v->c[k] = int64_t(q[k]) * (int64_t(1) << s);
    return true;
}

int64_t SmallSetupModel::gain_mul(int64_t t, bool halve) const {
    int64_t s = 0;
    for (const GainTerm& g : halve ? k_.half_terms : k_.gain_terms) {
        const int64_t term = g.shift >= 0 ? (t >> g.shift) : t * (int64_t(1) << -g.shift);
        s += g.sign * term;
    }
    return s;
}

void SmallSetupModel::pass(std::vector<Vec*> lanes, int pa, int pb, bool halve) const {
    const int pt = 3 - pa - pb;
    const int w = sf_.w();
    Vec* d = lanes[0];
    if (halve) {   // the pair to half its length first (the third coordinate is multiplied by G/2 below)
        for (Vec* v : lanes) {
            v->c[pa] = (v->c[pa] + 1) >> 1;
            v->c[pb] = (v->c[pb] + 1) >> 1;
        }
    }
    if (d->c[pa] < 0) {   // a rotation by pi first: the driver's pair into the half-plane a >= 0
        for (Vec* v : lanes) {
            v->c[pa] = -v->c[pa];
            v->c[pb] = -v->c[pb];
        }
    }
    for (int i = 0; i < sf_.iters; ++i) {
        const bool pos = d->c[pb] >= 0;   // rotate by -atan(2^-i) when b >= 0, else by +atan(2^-i)
        for (Vec* v : lanes) {
            const int64_t a = v->c[pa], b = v->c[pb];
            v->c[pa] = pos ? a + (b >> i) : a - (b >> i);
            v->c[pb] = pos ? b - (a >> i) : b + (a >> i);
            check(v->c[pa], w, "a coordinate");
            check(v->c[pb], w, "a coordinate");
        }
    }
    for (Vec* v : lanes) {
        v->c[pt] = gain_mul(v->c[pt], halve);
        check(v->c[pt], w, "a third coordinate");
    }
}

void SmallSetupModel::vector_angle(int64_t a, int64_t b, int64_t* angle, int64_t* mag) const {
    int64_t z = 0;
    if (a < 0) {   // a quarter turn first: the pair into the half-plane a >= 0
        if (b >= 0) {
            const int64_t t = a;
            a = b;
            b = -t;
            z = k_.half_pi;
        } else {
            const int64_t t = a;
            a = -b;
            b = t;
            z = -k_.half_pi;
        }
    }
    for (int i = 0; i < sf_.iters; ++i) {
        const int64_t na = b >= 0 ? a + (b >> i) : a - (b >> i);
        const int64_t nb = b >= 0 ? b - (a >> i) : b + (a >> i);
        z += b >= 0 ? k_.atan[i] : -k_.atan[i];
        a = na;
        b = nb;
        check(a, sf_.w(), "a vectoring coordinate");
        check(b, sf_.w(), "a vectoring coordinate");
    }
    check(z, sf_.zw(), "an angle");
    *angle = z;
    *mag = a;
}

int64_t SmallSetupModel::log2_fixed(uint64_t x) const {
    if (x == 0 || (x >> 48) != 0) throw std::logic_error("setup model: log2 of an out-of-range value");
    int e = 63;
    while (!((x >> e) & 1)) --e;
    const int fb = sf_.tb + sf_.rb;
    const uint64_t mask = (uint64_t(1) << fb) - 1;
    const uint64_t frac = (e >= fb ? (x >> (e - fb)) : (x << (fb - e))) & mask;   // bits below the leading one
    const uint64_t j = frac >> sf_.rb, r = frac & ((uint64_t(1) << sf_.rb) - 1);
    const int64_t t0 = static_cast<int64_t>(log2_[j]), t1 = static_cast<int64_t>(log2_[j + 1]);
    const int64_t interp = ((t1 - t0) * static_cast<int64_t>(r) + (int64_t(1) << (sf_.rb - 1))) >> sf_.rb;
    return (int64_t(e) << sf_.lf) + t0 + interp;
}

int64_t SmallSetupModel::exp2_frac(int64_t p) const {
    const int64_t j = p >> (sf_.lf - sf_.tb);
    const int64_t r = (p >> (sf_.lf - sf_.tb - sf_.rb)) & ((int64_t(1) << sf_.rb) - 1);
    const int64_t e0 = static_cast<int64_t>(exp2_[j]), e1 = static_cast<int64_t>(exp2_[j + 1]);
    return e0 - (((e0 - e1) * r + (int64_t(1) << (sf_.rb - 1))) >> sf_.rb);
}

uint32_t SmallSetupModel::c_code(int64_t p) const {
    const int64_t pi = p >> sf_.lf;
    const int shift = sf_.ef - cf_.c_w + static_cast<int>(pi);   // >= ef - c_w
    if (pi > cf_.c_w + 1) return 0;
    const int64_t e = exp2_frac(p & ((int64_t(1) << sf_.lf) - 1));
    const int64_t code = shift > 0 ? (e + (int64_t(1) << (shift - 1))) >> shift : e << -shift;
    const int64_t top = (int64_t(1) << cf_.c_w) - 1;
    return static_cast<uint32_t>(std::min(code, top));
}

int64_t SmallSetupModel::divide(int64_t gamma_z, uint32_t l) const {
    const int s = sf_.zf - cf_.ang_frac;
    const int64_t d = int64_t(l) << s;
    return (gamma_z + (d >> 1)) / d;
}

SetupResult SmallSetupModel::run(const SetupInput& in, SmallSetupTrace* trace) const {
    SetupResult res;
    SmallSetupTrace local;
    SmallSetupTrace& t = trace ? *trace : local;
    t = SmallSetupTrace();
    const uint32_t n = in.n & ((1u << cf_.n_w) - 1);
    const uint32_t l = in.l & ((1u << cf_.l_w) - 1);
    const uint32_t s = in.strength & ((1u << sf_.str_w) - 1);
    res.regs.n = n;
    res.regs.len = l;
    unsigned& flags = res.flags;
    if (l == 0) flags |= kSetupSinglePixel;

    Vec n1, n2, h1, h2;
    int32_t q[4][3];
    const int32_t* src[4] = {in.n1, in.n2, in.h1, in.h2};
    for (int v = 0; v < 4; ++v) {
        for (int k = 0; k < 3; ++k) {   // the component's vec_w bits, sign-extended
            const int32_t m = int32_t((uint32_t(src[v][k]) << (32 - sf_.vec_w)));
            q[v][k] = m >> (32 - sf_.vec_w);
        }
    }
    if (!prescale(q[0], &n1) || !prescale(q[1], &n2) || !prescale(q[2], &h1) || !prescale(q[3], &h2)) {
        flags |= kSetupInvalid;
        return res;   // C = 0, zeta0 = dzeta = 0
    }

    // perpendicular(N1) of the host: N1 x e_k, e_k the axis of N1's smallest component (first of x, y, z)
    Vec pp;
    {
        const int64_t ax = std::abs(n1.c[X]), ay = std::abs(n1.c[Y]), az = std::abs(n1.c[Z]);
        if (ax <= ay && ax <= az) pp = Vec{{0, n1.c[Z], -n1.c[Y]}};
        else if (ay <= az) pp = Vec{{-n1.c[Z], 0, n1.c[X]}};
        else pp = Vec{{n1.c[Y], -n1.c[X], 0}};
    }
    // The frame where N1 = z; then H2 carried by the rotation that takes N2 onto N1.
    pass({&n1, &n2, &h1, &h2, &pp}, X, Y, false);
    pass({&n1, &n2, &h1, &h2, &pp}, Z, X, true);
    // Exactly opposite normals (N2's projection on the plane z = 0 within rounding of zero): the rotation
    // axis is the host's, N1 x perpendicular(N1): P3 vectors perpendicular(N1) instead of N2's projection.
    const int64_t tau = int64_t(1) << (sf_.f + sf_.opp_tau_log2);
    t.proj2 = std::max(std::abs(n2.c[X]), std::abs(n2.c[Y]));
    t.exact_opposite = n2.c[Z] < 0 && std::abs(n2.c[X]) < tau && std::abs(n2.c[Y]) < tau;
    if (t.exact_opposite) {
        n2.c[X] = pp.c[X];
        n2.c[Y] = pp.c[Y];
    }
    pass({&n2, &h1, &h2}, X, Y, true);
    t.rho2 = n2.c[X];
    t.z2 = n2.c[Z];
    if (t.exact_opposite) n2.c[X] = 0;
    if (t.exact_opposite || (t.z2 < 0 && t.rho2 * sf_.opp_k < -t.z2)) flags |= kSetupOpposite;
    pass({&n2, &h2}, Z, X, false);
    // The frame where H1 = z: N1 (the old z axis) becomes a lane of its own, of start length U.
    Vec m1{{0, 0, k_.n1_start}};
    pass({&h1, &h2}, X, Y, true);
    pass({&h1, &h2, &m1}, Z, X, true);
    pass({&h2, &m1}, X, Y, true);
    t.c1 = m1.c[Z];
    int64_t mag_h2;
    vector_angle(h2.c[Z], h2.c[X], &t.gamma_z, &mag_h2);
    vector_angle(m1.c[Z], m1.c[X], &t.lambda_z, &t.mag);
    if (in.midpoint) flags |= kSetupGammaFallback;   // the midpoint rule: not in this model yet

    // Degenerate spans, angles.
    t.flat = l == 0 || t.gamma_z < k_.flat_z;
    bool nohl = false;
    int64_t x;   // A * 2^f (or, flat, cos(theta1) * 2^f / G)
    int64_t off = int64_t(sf_.f) << sf_.lf;
    const int sh = sf_.zf - cf_.ang_frac;
    if (t.flat) {
        flags |= kSetupFlat;
        x = t.c1;
        off -= k_.log2_gain;
        if (n > 0 && t.c1 <= 0) nohl = true;
    } else {
        int64_t z0 = -t.lambda_z;
        const int64_t mid = z0 + (t.gamma_z >> 1);
        if (mid > k_.pi) z0 -= k_.two_pi;
        else if (mid < -k_.pi) z0 += k_.two_pi;
        if (n > 0 && (z0 + t.gamma_z <= -k_.half_pi || z0 >= k_.half_pi)) nohl = true;
        res.regs.zeta0 = (z0 + (int64_t(1) << (sh - 1))) >> sh;
        res.regs.dzeta = divide(t.gamma_z, l);
        x = t.mag;
    }
    check(res.regs.zeta0, cf_.ang_w, "zeta0");
    check(res.regs.dzeta, cf_.ang_w, "dzeta");

    // C = Is * A^n = 2^-p, p = n * (-log2 A) - log2 Is.
    if (nohl) {
        flags |= kSetupNoHighlight;
        return res;
    }
    if (s == 0 || (n > 0 && x <= 0)) return res;   // C = 0
    const int64_t la_max = int64_t(31) << sf_.lf;
    if (x > 0) t.log2_a = std::min(la_max, std::max<int64_t>(0, off - log2_fixed(static_cast<uint64_t>(x))));
    const int64_t log2_is = log2_fixed(s) - (int64_t(sf_.str_frac) << sf_.lf);
    t.p = int64_t(n) * t.log2_a - log2_is;
    if (t.p <= 0) {
        flags |= kSetupCSaturated;
        res.regs.c = (1u << cf_.c_w) - 1;
    } else {
        res.regs.c = c_code(t.p);
    }
    return res;
}

}  // namespace spec
