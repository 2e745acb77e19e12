// span_host.h - the patent's "external device": per-span register contents from the span's end vectors.
//
// A span (one run of pixels on a scanline) has unit normals N1, N2 and unit halfway vectors H1, H2 at its
// first and last pixel, l intervals (l + 1 pixels), exponent n and specular strength Is*ks. The host
// computes, by the digest's equations (2)-(5) and (12)-(16):
//
//   H2' = H2 - v x H2 + v x (v x H2) / (1 + c),   v = N1 x N2, c = N1 . N2   (Rodrigues: N2 onto N1)
//   cos(theta1) = N1 . H1,  cos(theta2) = N1 . H2',  gamma = angle(H1, H2')
//   A cos(lambda) = cos(theta1),  A sin(lambda) = (cos(theta2) - cos(theta1) cos(gamma)) / sin(gamma)
//   C = Is * ks * A^n,  register 3 = zeta0 = -lambda,  register 2 = dzeta = gamma / l
//
// so that pixel i sees N.H = A cos(zeta0 + i * dzeta) and the core outputs C cos^n(zeta0 + i * dzeta)
// (approximated by cos^k(sqrt(n/k) * angle); the core applies sqrt(n/k) itself: docs/decisions.md #1).
// Degenerate spans (gamma -> 0, cos(theta1) <= 0, nearly opposite normals, l = 0, C >= 1) are handled
// without NaN and counted; see docs/host.md.
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

#include "spec_model.h"

namespace spec {
namespace host {

using Vec = glm::dvec3;

// The span's end vectors (unit length; the host normalizes them and rejects zero or non-finite ones).
struct SpanEnds {
    Vec n1, n2;  // normals at the first and the last pixel
    Vec h1, h2;  // halfway vectors at the first and the last pixel
};

// Degenerate cases met while setting up a span (bits of SpanSetup::flags).
enum SpanFlag : unsigned {
    kFlat = 1u << 0,           // gamma below kFlatGamma (N1 = N2 and H1 = H2, or l = 0): lambda = 0, dzeta = 0
    kOpposite = 1u << 1,       // 1 + N1.N2 below kOppositeEps: the rotation axis is taken from the slerp plane
    kCSaturated = 1u << 2,     // Is*ks*A^n does not fit UQ0.16: register 1 holds its largest code
    kSinglePixel = 1u << 3,    // l = 0
    kNoHighlight = 1u << 4,    // N.H <= 0 over the whole span: C = 0 (n >= 1)
    kGammaFallback = 1u << 5,  // GammaRule::midpoint could not fit the span: the patent's gamma was used
};

// How gamma (the span's angle range) is chosen. Both give a sinusoid a cos(t*gamma - lambda) through the
// span's end values N1.H1 and N2.H2 (eq. 3 holds for any gamma); they differ inside the span.
enum class GammaRule {
    patent,    // eq. (4): gamma = angle(H1, H2'). Exact when H moves on a great circle in the normal's frame
               // (e.g. N1 = N2); for a constant H and a turning normal the exact value is angle(N1, N2).
    midpoint,  // gamma such that the sinusoid also passes through N.H at the span's middle
               // (N, H = normalized N1 + N2, H1 + H2): cos(gamma/2) = (N1.H1 + N2.H2) / (2 N.H).
               // Exact whenever N.H is a sinusoid along the span (H constant, N constant, or both rigid);
               // falls back to the patent's gamma when the fit is not a sinusoid of amplitude <= 1.
};

constexpr double kFlatGamma = 1e-9;    // rad
constexpr double kOppositeEps = 1e-6;  // 1 + cos(psi)

struct SpanSetup {
    double cos_t1 = 0, cos_t2 = 0;  // N1.H1, N1.H2'
    double gamma = 0;               // angle(H1, H2'), [0, pi]
    double a = 0;                   // amplitude: N.H(t) = a cos(t*gamma - lambda), [0, 1]
    double lambda = 0;              // (-pi, pi]
    double c = 0;                   // Is*ks*a^n, before quantization (can exceed 1)
    double c_used = 0;              // c saturated to register 1's largest value (1 - 2^-16)
    double zeta0 = 0, dzeta = 0;    // radians, unscaled: -lambda and gamma / l
    unsigned n = 0;
    uint32_t l = 0;
    SpanRegs regs;                  // what is written into registers 1-4 and counter 5
    unsigned flags = 0;             // SpanFlag bits

    // The intensity the host asks for at pixel i in double precision: c_used * max(0, cos(zeta_i))^n
    // with zeta_i = zeta0 + i*dzeta (exact cos^n, no table approximation, unquantized registers).
    double value(uint32_t i) const;
    // The same with register 1's quantized C and the quantized angles (what the core's input means).
    double value_quantized(const Model& m, uint32_t i) const;
};

// How often each degenerate case occurred.
struct Counters {
    uint64_t spans = 0, flat = 0, opposite = 0, c_saturated = 0, single_pixel = 0, no_highlight = 0;
    uint64_t gamma_fallback = 0;
    void add(unsigned flags);
    Counters& operator+=(const Counters& o);
};

// The register contents for one span. strength = Is*ks (>= 0). n: 0..2^n_w-1, l: 0..2^l_w-1.
// Throws std::invalid_argument (one-line message) on a non-finite or zero-length vector, a negative or
// non-finite strength, or n / l outside the core's formats.
// midpoint_checked = false (for the accuracy checks' knife edges only): GammaRule::midpoint keeps its fit
// wherever it can be computed, amplitude above 1 and the thresholds of midpoint_fit() included.
SpanSetup setup_span(const Model& m, const SpanEnds& e, double strength, unsigned n, uint32_t l,
                     GammaRule rule = GammaRule::patent, bool midpoint_checked = true);

// GammaRule::midpoint's fit of A cos(t gamma - lambda) through c1 = N1.H1 (t = 0), f1 = N2.H2 (t = 1) and
// fm = N.H at the span's middle (t = 1/2): gamma and A sin(lambda). False where the fit is not a sinusoid of
// amplitude <= 1 (fm <= 1e-3, (c1 + f1) / (2 fm) outside [0, 1], gamma < 1e-6 or A > 1): the rule then falls
// back to the patent's gamma. checked = false accepts every fit it can compute (fm > 0, 0 < gamma <= pi).
bool midpoint_fit(double c1, double f1, double fm, double* gamma, double* a_sin, bool checked = true);

// Spherical interpolation of unit vectors: a at t = 0, b at t = 1, along the shorter great circle;
// for b = -a along the great circle through perpendicular(a).
Vec slerp(const Vec& a, const Vec& b, double t);
// A fixed unit vector perpendicular to the unit vector a.
Vec perpendicular(const Vec& a);
// H2 carried by the rotation that takes N2 onto N1 (the digest's Rodrigues formula; for nearly opposite
// normals the axis-angle form about the slerp plane's normal). *opposite tells which was used.
Vec carry_to_n1(const Vec& n1, const Vec& n2, const Vec& h2, bool* opposite = nullptr);
// Unit vector, or std::invalid_argument naming `what` when v is zero-length or not finite.
Vec unit(const Vec& v, const char* what);

// Brute force in double precision, what the host's formulas stand for: pixel i of l + 1,
// t = i / l, N = slerp(N1, N2, t), H = slerp(H1, H2, t), strength * max(0, N.H)^n.
double brute_force(const SpanEnds& e, double strength, unsigned n, uint32_t l, uint32_t i);

}  // namespace host
}  // namespace spec
