#include "setup_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace spec {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

SetupModel::SetupModel(const SetupFormat& sf, const Format& core)
    : sf_(sf), cf_(core), prog_(build_setup_program(sf)), tab_(make_setup_tables(sf)) {
    core.validate();
    sf.validate();
    if (sf.zf < core.ang_frac + 1) throw std::invalid_argument("setup format: zf must exceed the core's ang_frac");
    if (sf.exp_f <= core.c_w) throw std::invalid_argument("setup format: exp_f must exceed the core's C width");
}

bool SetupModel::beat(const SetupInput& in, SetupBeat* b) const {
    const int32_t* src[4] = {in.n1, in.n2, in.h1, in.h2};
    bool valid = true;
    for (int v = 0; v < 4; ++v) {
        bool z = true;
        for (int k = 0; k < 3; ++k) {   // the component's vec_w bits, sign-extended
            const int32_t c = static_cast<int32_t>(static_cast<uint32_t>(src[v][k]) << (32 - sf_.vec_w)) >> (32 - sf_.vec_w);
            b->v[v][k] = c;
            z &= c == 0;
        }
        valid &= !z;
    }
    // PN = N1 x e_k, e_k the axis of N1's smallest |component| (the first of x, y, z): the host's perpendicular
    const int32_t* n1 = b->v[BV_N1];
    const int32_t ax = std::abs(n1[0]), ay = std::abs(n1[1]), az = std::abs(n1[2]);
    int32_t* pn = b->v[BV_PN];
    if (ax <= ay && ax <= az) {
        pn[0] = 0, pn[1] = n1[2], pn[2] = -n1[1];
    } else if (ay <= az) {
        pn[0] = -n1[2], pn[1] = 0, pn[2] = n1[0];
    } else {
        pn[0] = n1[1], pn[1] = -n1[0], pn[2] = 0;
    }
    b->s[BS_RULE] = in.midpoint ? 1 : 0;
    b->s[BS_STRENGTH] = static_cast<int32_t>(in.strength & ((1u << sf_.str_w) - 1));
    b->s[BS_N] = static_cast<int32_t>(in.n & ((1u << cf_.n_w) - 1));
    b->s[BS_L] = static_cast<int32_t>(in.l & ((1u << cf_.l_w) - 1));
    return valid;
}

int64_t SetupModel::fix(const Fp& x, int frac, int sat) const {
    if (x.zero()) return 0;
    const int64_t top = (int64_t(1) << (sat + frac)) - 1;
    const int sh = x.e - (sf_.fp.m - 1) + frac;   // left shift of the mantissa
    int64_t mag;
    if (x.e >= sat) mag = top;
    else if (sh >= 0) mag = static_cast<int64_t>(x.m) << sh;
    else if (-sh > 62) mag = 0;
    else mag = static_cast<int64_t>((x.m + (uint64_t(1) << (-sh - 1))) >> -sh);
    mag = std::min(mag, top);
    return x.s ? -mag : mag;
}

uint32_t SetupModel::c_code(const Fp& p) const {
    if (p.e >= 6) return 0;   // p >= 64: C < 2^-64
    const int64_t q = fix(p, sf_.lf, 6);
    const int64_t pi = q >> sf_.lf;
    if (pi > cf_.c_w + 1) return 0;
    const int64_t fr = q & ((int64_t(1) << sf_.lf) - 1);
    const int64_t e = tab_.exp2.at(static_cast<uint64_t>(fr >> (sf_.lf - sf_.exp_t - sf_.exp_r)));   // 2^-f
    const int shift = sf_.exp_f - cf_.c_w + static_cast<int>(pi);   // >= 1
    const int64_t code = (e + (int64_t(1) << (shift - 1))) >> shift;
    return static_cast<uint32_t>(std::min<int64_t>(code, (int64_t(1) << cf_.c_w) - 1));
}

SetupResult SetupModel::finish(const SetupInput& in, bool valid, const std::array<Fp, SO_COUNT>& o) const {
    SetupResult res;
    const FpFmt& f = sf_.fp;
    const uint32_t n = in.n & ((1u << cf_.n_w) - 1), l = in.l & ((1u << cf_.l_w) - 1);
    res.regs.n = n;
    res.regs.len = l;
    for (int k = 0; k < SO_COUNT; ++k) res.trace.out[k] = fp_value(f, o[k]);
    if (l == 0) res.flags |= kSetupSinglePixel;
    if (!valid) {
        res.flags |= kSetupInvalid;
        return res;   // C = 0, zeta0 = dzeta = 0
    }
    const bool flat = l == 0 || fp_less(o[SO_GAMMA_P], fp_from_double(f, std::ldexp(1.0, sf_.flat_log2)));
    res.trace.flat = flat;
    if (fp_less(o[SO_OPC], fp_from_double(f, sf_.opp_eps))) res.flags |= kSetupOpposite;
    bool nohl;
    Fp p;
    if (flat) {
        res.flags |= kSetupFlat;
        nohl = n > 0 && (o[SO_C1].zero() || o[SO_C1].s);
        p = o[SO_P_F];
    } else {
        if (in.midpoint && o[SO_OK].zero()) res.flags |= kSetupGammaFallback;
        const int zf = sf_.zf;
        const int64_t pi = std::llround(std::ldexp(kPi, zf)), two_pi = std::llround(std::ldexp(2 * kPi, zf));
        const int64_t hp = std::llround(std::ldexp(kPi / 2, zf));
        const int64_t g = fix(o[SO_GAMMA], zf, 2);
        int64_t z0 = -fix(o[SO_LAMBDA], zf, 2);
        const int64_t mid = z0 + (g >> 1);   // the middle of [zeta0, zeta0 + gamma] into [-pi, pi]
        if (mid > pi) z0 -= two_pi;
        else if (mid < -pi) z0 += two_pi;
        nohl = n > 0 && (z0 + g <= -hp || z0 >= hp);
        const int sh = zf - cf_.ang_frac;
        res.regs.zeta0 = (z0 + (int64_t(1) << (sh - 1))) >> sh;
        res.regs.dzeta = fix(o[SO_DZETA], cf_.ang_frac, 2);
        p = o[SO_P_NF];
    }
    if (nohl) {
        res.flags |= kSetupNoHighlight;
        return res;
    }
    if (p.zero() || p.s) {   // C = Is A^n >= 1
        res.flags |= kSetupCSaturated;
        res.regs.c = (1u << cf_.c_w) - 1;
    } else {
        res.regs.c = c_code(p);
    }
    return res;
}

SetupResult SetupModel::run(const SetupInput& in) const {
    SetupBeat b;
    const bool valid = beat(in, &b);
    std::array<Fp, SO_COUNT> o{};
    if (valid) {
        const std::vector<Fp> v = setup_eval(sf_, tab_, prog_, b);
        for (int k = 0; k < SO_COUNT; ++k) o[k] = v[static_cast<size_t>(prog_.out[k])];
    }
    return finish(in, valid, o);
}

}  // namespace spec
