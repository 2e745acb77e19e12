// setup_small_model.h - bit-exact C++ model of spec_setup_small, the small CORDIC setup of the up5k configuration
// (one span at a time; kept where the multiplier setup, spec_setup, does not fit: docs/setup.md): the span's end
// vectors in, spec_stream's descriptor out. The gamma rule is always the patent's (eq. 4): a span that asks for
// the midpoint rule gets kSetupGammaFallback.
//
// It computes what the host (sim/host/span_host, double precision) computes - C = Is*ks*A^n, zeta0 = -lambda,
// dzeta = gamma / l and the degenerate-case flags - with the integer operations of the RTL, in the RTL's order:
//
//   pre-scale each vector by a power of two (exact; a zero vector is invalid)
//   P1  (x,y) driven by N1, followers N2, H1, H2, P   \  the frame where N1 = z (P = perpendicular(N1) of
//   P2  (z,x) driven by N1, followers N2, H1, H2, P   /  the host, N1 x e_k, exact from N1's components)
//   P3  (x,y) driven by N2, followers H1, H2            N2 into the (z,x) plane: the rotation axis is y
//                                                       (N2 exactly opposite N1: P's projection instead)
//   P4  (z,x) driven by N2, follower H2                 H2 carried by the rotation N2 -> N1 (= z): H2'
//   G1  (x,y) driven by H1, follower H2'             \  the frame where H1 = z, with N1 as a follower lane
//   G2  (z,x) driven by H1, followers H2', N1        /  that starts as (0, 0, U)
//   Q1  (x,y) driven by H2', follower N1                H2' into the (z,x) plane: the tangent T is x
//   gamma  = angle of H2' from z (vectoring with an angle lane)
//   lambda = atan2(N1.x, N1.z) and A * 2^f = |(N1.z, N1.x)| (vectoring with an angle lane)
//   C = 2^-(n * -log2 A - log2 Is) by log2 / exp2 tables, dzeta = gamma / l by division, zeta0 = -lambda
//
// A pass vectors one coordinate pair of its driving vector onto the pair's positive first axis with
// `iters` CORDIC micro-rotations and applies the same micro-rotations to the followers; the followers' and
// the driver's third coordinate is multiplied by the CORDIC gain (shift-and-add terms), so that all three
// coordinates of a vector keep one common scale. docs/setup.md has the derivation, the widths and the
// measured accuracy.
#pragma once

#include <cstdint>
#include <vector>

#include "setup_model.h"
#include "setup_rom.h"
#include "setup_small_format.h"
#include "spec_format.h"
#include "spec_model.h"

namespace spec {

// Intermediate values, for the tests.
struct SmallSetupTrace {
    int64_t gamma_z = 0;    // gamma, zf fraction bits
    int64_t lambda_z = 0;   // lambda, zf fraction bits
    int64_t mag = 0;        // A * 2^f
    int64_t c1 = 0;         // N1.z after Q1: cos(theta1) * 2^f / G
    int64_t rho2 = 0, z2 = 0;   // N2 after P3: (rho2, 0, z2)
    int64_t proj2 = 0;           // max(|N2.x|, |N2.y|) after P2
    bool exact_opposite = false;  // N2's projection after P2 within rounding of zero, N2.z < 0
    int64_t log2_a = 0;     // -log2 A * 2^lf (after clamping to >= 0)
    int64_t p = 0;          // -log2 C * 2^lf
    bool flat = false;
};

class SmallSetupModel {
public:
    explicit SmallSetupModel(const SmallSetupFormat& sf = SmallSetupFormat(), const Format& core = Format());

    const SmallSetupFormat& format() const { return sf_; }
    const Format& core_format() const { return cf_; }
    const SmallSetupConsts& consts() const { return k_; }

    // trace: the intermediate values, when not null
    SetupResult run(const SetupInput& in, SmallSetupTrace* trace = nullptr) const;

    // The pieces, public for the unit tests.
    struct Vec {
        int64_t c[3];
    };
    // A vector's components shifted left so that the largest magnitude is in [2^(f-1), 2^f); false if zero.
    bool prescale(const int32_t q[3], Vec* v) const;
    // One pass: lanes[0] drives (its pair (pa, pb) goes to (+r, ~0)); every lane gets the same rotation,
    // its third coordinate multiplied by G (halve: the pair first rounded to half, the third times G/2).
    void pass(std::vector<Vec*> lanes, int pa, int pb, bool halve) const;
    // Vectoring with an angle lane: *angle = atan2(b, a) in (-pi, pi] (zf fraction bits), *mag = G * |(a, b)|.
    void vector_angle(int64_t a, int64_t b, int64_t* angle, int64_t* mag) const;
    // sum of sign * floor(t / 2^shift)
    int64_t gain_mul(int64_t t, bool halve) const;
    // log2(x) * 2^lf for x > 0 (x < 2^48): leading one, table, linear interpolation.
    int64_t log2_fixed(uint64_t x) const;
    // 2^(-p / 2^lf) * 2^ef for 0 <= p < 2^lf (table and linear interpolation), in (2^(ef-1), 2^ef].
    int64_t exp2_frac(int64_t p) const;
    // round(2^(c_w - p / 2^lf)) for p > 0, 0 when it is below 1/2 LSB's worth; at most 2^c_w - 1.
    uint32_t c_code(int64_t p) const;
    // round(gamma_z / (l * 2^(zf - ang_frac))), gamma_z >= 0, l >= 1.
    int64_t divide(int64_t gamma_z, uint32_t l) const;

private:
    void check(int64_t v, int bits, const char* what) const;   // internal error when v leaves its width

    SmallSetupFormat sf_;
    Format cf_;
    SmallSetupConsts k_;
    std::vector<uint64_t> log2_, exp2_;
};

}  // namespace spec
