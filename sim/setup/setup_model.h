// setup_model.h - bit-exact C++ model of spec_setup: the span's end vectors in, spec_stream's descriptor out.
//
// It computes what the host (sim/host/span_host, double precision) computes - C = Is*ks*A^n, zeta0 = -lambda,
// dzeta = gamma / l and the degenerate-case flags - with the RTL's operations in three parts:
//
//   pre-stage   the beat's fields; PN = N1 x e_k (e_k the axis of N1's smallest component: the host's
//               perpendicular(N1)); a zero vector makes the span invalid
//   program     the dataflow program of rom/gen/setup_program.h: exact integer products of the 16-bit span ends,
//               then floating-point operations (docs/setup.md derives them), whatever machine runs it
//   finish      fixed point: the flat and opposite tests, the angles rounded and put where the core looks for
//               them, C = 2^-p from an exp2 table, the flags
#pragma once

#include <array>
#include <cstdint>

#include "setup_format.h"
#include "setup_program.h"
#include "spec_format.h"
#include "spec_model.h"

namespace spec {

// The span's end vectors and parameters, as the AXI4-Stream beat of spec_setup carries them.
struct SetupInput {
    int32_t n1[3] = {0, 0, 0}, n2[3] = {0, 0, 0};   // normals at the first and last pixel (vec_w-bit codes)
    int32_t h1[3] = {0, 0, 0}, h2[3] = {0, 0, 0};   // halfway vectors
    uint32_t strength = 0;                          // Is*ks, str_w-bit code
    uint32_t n = 0;                                 // exponent, n_w bits
    uint32_t l = 0;                                 // intervals, l_w bits
    bool midpoint = false;                          // gamma rule requested (docs/setup.md)
};

// Flags on tuser; bits 0..5 are the host's SpanFlag bits (span_host.h).
enum SetupFlag : unsigned {
    kSetupFlat = 1u << 0,           // gamma below 2^flat_log2 (or l = 0): lambda = 0, dzeta = 0
    kSetupOpposite = 1u << 1,       // 1 + N1.N2 below opp_eps (the host's 1e-6)
    kSetupCSaturated = 1u << 2,     // Is*ks*A^n >= 1: C = its largest code
    kSetupSinglePixel = 1u << 3,    // l = 0
    kSetupNoHighlight = 1u << 4,    // N.H <= 0 over the whole span: C = 0 (n >= 1)
    kSetupGammaFallback = 1u << 5,  // the midpoint rule was asked for and not used (patent gamma)
    kSetupInvalid = 1u << 6,        // an end vector is zero: C = 0, zeta0 = dzeta = 0
};
constexpr int kSetupFlagBits = 7;

// The program's results, for tests and `specsim setup --trace`.
struct SetupTrace {
    std::array<double, SO_COUNT> out{};   // SetupOut order
    bool flat = false;
};

struct SetupResult {
    SpanRegs regs;     // spec_stream's descriptor fields (c, n, len, zeta0, dzeta)
    unsigned flags = 0;
    SetupTrace trace;
};

class SetupModel {
public:
    explicit SetupModel(const SetupFormat& sf = SetupFormat(), const Format& core = Format());

    const SetupFormat& format() const { return sf_; }
    const Format& core_format() const { return cf_; }
    const SetupProgram& program() const { return prog_; }
    const SetupTables& tables() const { return tab_; }

    SetupResult run(const SetupInput& in) const;

    // The pieces, public for the tests and the machine checker.
    // The pre-stage: the beat's fields as the IDOT unit reads them; false when an end vector is zero.
    bool beat(const SetupInput& in, SetupBeat* b) const;
    // The finish stage on the program's results.
    SetupResult finish(const SetupInput& in, bool valid, const std::array<Fp, SO_COUNT>& o) const;
    // round(x * 2^frac), half away from zero, saturated to |x| < 2^sat (frac, sat: the finish's widths)
    int64_t fix(const Fp& x, int frac, int sat) const;
    // C's code for p = -log2 C > 0: round(2^(c_w - p)), 0 when p >= 64, at most 2^c_w - 1
    uint32_t c_code(const Fp& p) const;

private:
    SetupFormat sf_;
    Format cf_;
    SetupProgram prog_;
    SetupTables tab_;
};

}  // namespace spec
