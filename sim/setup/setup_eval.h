// setup_eval.h - spec_setup against the host's double-precision setup: per-pixel bounds, test spans.
//
// The reference for a span is the host (sim/host/span_host) fed the same quantized end vectors the setup
// gets, with exact cos^n: host(i) = c_used * max(0, cos(zeta0 + i dzeta))^n. The setup's descriptor goes
// through the core (bit-exact model = RTL), so the bound is the core's plus 0.2 % for the setup
// (issue 13, item 4):
//   inside the epicentre (|zeta0 + i dzeta| <= epicentre_end(n)):  host(i) * (q(n) + 0.004) + 2^-13
//   elsewhere:                                                      C * (a(n) + 0.004) + 2^-12
// Some spans are ill-conditioned: the host's split of N.H = A cos(t gamma - lambda) into C = Is A^n and the
// angles depends on the end vectors' last bits (gamma below the input's resolution, nearly opposite normals,
// H2' nearly opposite H1). For those the bound is widened by what the host itself gives for end vectors moved
// by `eps` (2^-20 rad, a sixty-fourth of the input format's resolution) in random directions, for H1 moved
// by eps toward and away from N1 and across (where H2' is within eps of -H1 every great circle joins them),
// and, where N2 is within 1/64 rad of -N1, for N2 and N1 each tilted by eps in 16 directions (the rotation's
// axis turns by eps / sin(angle to opposite) there, which random tilts cover poorly):
// the setup is then held to "the host's answer for nearly the same span" (backward error eps). Each check
// reports whether the widened bound was needed. Where gamma is within the input's resolution (2^-14) of pi the
// great circle from H1 to H2' ~ -H1 is the input rounding's choice, and where N2 is that close to -N1 the axis
// of the rotation N2 -> N1 is: the bound is widened over all of them (33 circles, 32 axes).
// Under the midpoint rule, where moving N1.H1, N2.H2 and N.H by 2 eps changes the rule's decision (fit or
// fallback, e.g. an amplitude within rounding of 1), the bound is widened over both answers.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "analysis.h"
#include "setup_model.h"
#include "span_host.h"

namespace spec {

// The host's view of a setup input: the components' values as doubles, strength = code / 2^str_frac.
host::SpanEnds host_ends(const SetupFormat& sf, const SetupInput& in);
double host_strength(const SetupFormat& sf, const SetupInput& in);
host::GammaRule host_rule(const SetupInput& in);

struct SpanCheck {
    double ratio = 0;         // worst |out - host| / bound over the span's pixels (<= 1: within the bound)
    double plain_ratio = 0;   // the same with the bound not widened for conditioning
    bool widened = false;     // some pixel needed the widened bound
    uint32_t worst_pixel = 0;
    bool inside = false;      // the worst pixel is inside the epicentre
    bool ambiguous = false;   // the input's rounding chooses the answer (gamma or the angle of N2 to N1 within
                              // pi_gap of pi): widened over the circles from H1 to H2' or the axes N2 -> N1
    double out = 0, ref = 0, bound = 0;
};

struct CheckOptions {
    double eps = 1.0 / (1 << 20);   // backward error allowed for ill-conditioned spans (rad)
    int samples = 16;               // perturbed host evaluations per ill-conditioned span
    double setup_share = 0.002;     // what the setup adds to the core's 0.002 (issue: 0.004 in all)
    double pi_gap = 1.0 / (1 << 14);   // closer to pi than this (the input's resolution): any circle, any axis
};

// Checks the pixels `out` (UQ0.c_w codes, l + 1 of them) of a span set up from `in` against the host.
// The host must accept the input (no zero vector).
SpanCheck check_span(const Model& core, const SetupFormat& sf, const SetupInput& in, const std::vector<uint32_t>& out,
                     std::mt19937_64& rng, const CheckOptions& opt = CheckOptions());

// Test spans: random end vectors of random lengths (0.5 .. 1.9) in classes that exercise each degenerate case.
enum class SpanKind {
    random,          // N and H anywhere, the highlight near the span often
    near_equal,      // N2 within 1e-4 .. 3e-2 rad of N1, H2 of H1 (short spans of a smooth mesh)
    flat_normal,     // N1 = N2 as codes (a plane), H moving
    near_opposite,   // N2 within 1e-4 .. 2e-3 rad of -N1 (1 + N1.N2 around the host's 1e-6), or exactly -N1
    facing_away,     // N.H <= 0 at one or both ends
    gamma_zero,      // H2 = H1 and N2 = N1 up to the last bits (gamma -> 0)
    single_pixel,    // l = 0
    saturating,      // strength up to 2: C = Is A^n >= 1
    count
};
const char* kind_name(SpanKind k);
SetupInput random_case(std::mt19937_64& rng, const SetupFormat& sf, SpanKind kind, unsigned n, uint32_t max_len);

// Any bit pattern: random components (small, extreme and zero ones too), strength, n, l and rule.
SetupInput random_raw(std::mt19937_64& rng, const SetupFormat& sf);

// Double in [-2, 2) -> component code (round to nearest, saturating).
int32_t component_code(const SetupFormat& sf, double v);

}  // namespace spec
