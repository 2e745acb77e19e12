// setup_fp.h - the floating-point arithmetic of spec_setup, bit for bit: the definitions the model
// (sim/setup/setup_model), the schedule checker (rom/gen/setup_sched) and the RTL units (rtl/spec_setup_f*.v)
// implement. docs/setup.md explains the choices.
//
// A value is a sign, an exponent e (fp_e bits, two's complement) and a mantissa m of fp_m bits with its leading
// one explicit: value = (-1)^s * m * 2^(e - (fp_m - 1)), m in [2^(fp_m-1), 2^fp_m); m = 0 is zero (sign and
// exponent then 0). Every operation rounds its exact (or, for the adder, guard-bit) result half up on the
// magnitude; a result below 2^emin flushes to zero, one at or above 2^(emax+1) saturates to the largest value.
#pragma once

#include <cstdint>

namespace spec {

typedef unsigned __int128 setup_u128;

struct FpFmt {
    int m = 22;   // mantissa bits, the leading one included
    int e = 8;    // exponent bits
    int g = 3;    // guard bits of the adder below the larger operand's last bit
    int emin() const { return -(1 << (e - 1)); }
    int emax() const { return (1 << (e - 1)) - 1; }
    int w() const { return 1 + e + m; }   // a word: {sign, exponent, mantissa}
};

struct Fp {
    uint64_t m = 0;
    int32_t e = 0;
    bool s = false;
    bool zero() const { return m == 0; }
    bool operator==(const Fp& o) const { return m == o.m && e == o.e && s == o.s; }
};

inline int setup_msb(setup_u128 x) {
    int p = -1;
    while (x) {
        x >>= 1;
        ++p;
    }
    return p;
}

// (-1)^s * X * 2^k rounded to the format (X exact, any width up to 128 bits).
inline Fp fp_round(const FpFmt& f, bool s, setup_u128 X, int k) {
    Fp r;
    if (X == 0) return r;
    const int lp = setup_msb(X);
    uint64_t m;
    int e;
    if (lp >= f.m - 1) {
        const int sh = lp - (f.m - 1);
        setup_u128 t = sh > 0 ? (X + (setup_u128(1) << (sh - 1))) >> sh : X;
        e = k + lp;
        if (t >> f.m) {   // rounding carried into a new leading one
            t >>= 1;
            ++e;
        }
        m = static_cast<uint64_t>(t);
    } else {
        m = static_cast<uint64_t>(X << (f.m - 1 - lp));
        e = k + lp;
    }
    if (e < f.emin()) return r;
    if (e > f.emax()) {
        r.m = (uint64_t(1) << f.m) - 1;
        r.e = f.emax();
        r.s = s;
        return r;
    }
    r.m = m;
    r.e = e;
    r.s = s;
    return r;
}

inline Fp fp_from_int(const FpFmt& f, int64_t v, int k = 0) {
    return fp_round(f, v < 0, static_cast<setup_u128>(v < 0 ? -v : v), k);
}

// A constant: the double's 53 bits rounded like any result.
Fp fp_from_double(const FpFmt& f, double v);
double fp_value(const FpFmt& f, const Fp& a);

// Operand modifiers: the sign inverted, cleared; the exponent moved by k (0 stays 0, range as fp_round).
inline Fp fp_neg(Fp a) {
    if (!a.zero()) a.s = !a.s;
    return a;
}
inline Fp fp_abs(Fp a) {
    a.s = false;
    return a;
}
inline Fp fp_scale(const FpFmt& f, Fp a, int k) {
    if (a.zero() || k == 0) return a;
    const int e = a.e + k;
    if (e < f.emin()) return Fp();
    if (e > f.emax()) {
        a.m = (uint64_t(1) << f.m) - 1;
        a.e = f.emax();
        return a;
    }
    a.e = e;
    return a;
}

// a * b * 2^k: the exact product rounded once (k: the operation's result scale).
inline Fp fp_mul(const FpFmt& f, const Fp& a, const Fp& b, int k = 0) {
    if (a.zero() || b.zero()) return Fp();
    return fp_round(f, a.s != b.s, static_cast<setup_u128>(a.m) * b.m, a.e + b.e - 2 * (f.m - 1) + k);
}

// |a| < |b|
inline bool fp_mag_less(const Fp& a, const Fp& b) {
    if (b.zero()) return false;
    if (a.zero()) return true;
    return a.e != b.e ? a.e < b.e : a.m < b.m;
}

// (a + b) * 2^k: the larger magnitude x with g guard bits, the smaller one shifted right by the exponent
// difference (bits below the guard bits dropped), added or subtracted, then rounded once. Equal magnitudes of
// opposite signs give zero.
inline Fp fp_add(const FpFmt& f, Fp a, Fp b, int k = 0) {
    if (a.zero()) return fp_scale(f, b, k);
    if (b.zero()) return fp_scale(f, a, k);
    if (fp_mag_less(a, b)) {
        const Fp t = a;
        a = b;
        b = t;
    }
    const int d = a.e - b.e;
    const setup_u128 x = static_cast<setup_u128>(a.m) << f.g;
    const setup_u128 y = d >= f.m + f.g ? 0 : (static_cast<setup_u128>(b.m) << f.g) >> d;
    const setup_u128 X = a.s == b.s ? x + y : x - y;
    return fp_round(f, a.s, X, a.e - (f.m - 1) - f.g + k);
}

// signed a < b (zero has no sign)
inline bool fp_less(const Fp& a, const Fp& b) {
    const bool an = a.s && !a.zero(), bn = b.s && !b.zero();
    if (an != bn) return an;
    return an ? fp_mag_less(b, a) : fp_mag_less(a, b);
}

// {s, e, m} as a word of f.w() bits and back (the banks' and the hex files' layout).
inline uint64_t fp_word(const FpFmt& f, const Fp& a) {
    const uint64_t em = static_cast<uint64_t>(static_cast<uint32_t>(a.e)) & ((uint64_t(1) << f.e) - 1);
    return (uint64_t(a.s) << (f.e + f.m)) | (em << f.m) | a.m;
}
inline Fp fp_unword(const FpFmt& f, uint64_t w) {
    Fp a;
    a.m = w & ((uint64_t(1) << f.m) - 1);
    const int64_t e = static_cast<int64_t>((w >> f.m) & ((uint64_t(1) << f.e) - 1));
    a.e = static_cast<int32_t>(e >= (int64_t(1) << (f.e - 1)) ? e - (int64_t(1) << f.e) : e);
    a.s = ((w >> (f.e + f.m)) & 1) != 0;
    return a;
}

}  // namespace spec
