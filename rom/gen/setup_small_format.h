// setup_small_format.h - the arithmetic of spec_setup_small, the CORDIC setup of the up5k configuration (one
// span at a time; kept where the multiplier setup does not fit: docs/setup.md, "The small CORDIC setup"):
// widths, iteration counts and table sizes. One set of definitions for the generator (setuprom --config up5k:
// the tables and setup_small_params.{vh,h}), the bit-exact model (sim/setup/setup_small_model) and, through the
// generated header, the RTL (rtl/spec_setup_small.v, spec_setup_engine.v, spec_setup_backend.v).
//
// The setup never normalizes a vector: every quantity it needs is an angle (atan2 is scale-invariant) or a
// magnitude of a vector it builds itself with a known length. Each input vector is pre-scaled by a power of
// two (exact), then CORDIC passes rotate the frame: a pass vectors one 2-D pair of a "driving" vector to its
// positive first axis and rotates the same pair of the "follower" vectors by the same micro-rotations.
#pragma once

#include <stdexcept>
#include <string>

namespace spec {

// The defaults are the up5k configuration's format: coordinates four bits wider than the 16-bit span ends and as
// many micro-rotations (f = iters = 20). With f = iters = 16 (the iCEBreaker's narrow format before issue 28) the
// default scene through the up5k shader was 11 levels of 255 from the double-precision reference and nearly
// opposite normals 15 times the bound below; with 20 every kind of span is within the core's bound plus 2 % of C
// (backward error 2^-13 rad, two codes of the input: setup_config_check, docs/setup.md), and the tables are cut to match.
struct SmallSetupFormat {
    // ---- interface ----
    int vec_w = 16;      // end vectors N1, N2, H1, H2: three two's complement components each
    int vec_frac = 14;   //   value = code / 2^vec_frac: Q1.14, [-2, 2); any length, not zero
    int str_w = 16;      // strength Is*ks: unsigned, value = code / 2^str_frac
    int str_frac = 15;   //   UQ1.15, [0, 2)

    // ---- CORDIC ----
    int f = 20;          // fraction bits of the coordinates: a vector's largest component is pre-scaled into
                         // [2^(f-1), 2^f); coordinates are f + 3 bits wide (w())
    int iters = 20;      // micro-rotations per pass (residual angle <= atan(2^-(iters-1)))
    int zf = 29;         // fraction bits of the angle lanes (radians); zw() bits wide; the least the model
                         // accepts: the core's ang_frac + 1 (dzeta = gamma / l)
    int gain_frac = 20;  // the CORDIC gain is applied to a vector's third coordinate as shift-and-add terms
                         // (canonical signed digits) accurate to 2^-gain_frac

    // ---- log2 / exp2 ----
    int lf = 18;         // fraction bits of log2 values
    int ef = 18;         // exp2 table: 2^-x in (0.5, 1] with ef fraction bits (above the C code's 16 bits:
                         // the back end's rounding shift of C is at least 1)
    int tb = 8;          // both tables have 2^tb intervals on [0, 1) (2^tb + 1 words); tb + rb <= f: the
                         // back end's log2 normalizer takes them from f + 1 bits
    int rb = 9;          // interpolation: rb fraction bits of the position between two words

    // ---- degenerate spans ----
    int flat_log2 = -20; // gamma < 2^flat_log2 rad: the span is flat (lambda = 0, dzeta = 0, A = cos theta1)
    int opp_tau_log2 = -14;  // N2's projection after P2 below 2^(f + opp_tau_log2): exactly opposite normals
    int opp_k = 707;     // normals are "opposite" when N2's tilt off -N1 has tangent < 1/opp_k
                         // (1/707 rad = 1.414e-3: the host's 1 + N1.N2 < 1e-6)

    int w() const { return f + 3; }     // coordinate width: magnitudes stay below 4 * 2^f (docs/setup.md)
    int zw() const { return zf + 4; }   // angle lane width: |angle| < 8 rad

    // Throws std::invalid_argument with a one-line reason when the combination is not supported.
    void validate() const {
        auto need = [](bool ok, const char* what) {
            if (!ok) throw std::invalid_argument(std::string("small setup format: ") + what);
        };
        need(vec_w >= 8 && vec_w <= 16, "vec_w must be 8..16 (a 16-bit slot of the span-ends beat each)");
        need(vec_frac >= 1 && vec_frac <= vec_w - 1, "vec_frac must be 1..vec_w-1");
        need(str_w >= 4 && str_w <= 16 && str_frac >= 0 && str_frac <= str_w, "bad strength format (at most 16 bits)");
        need(f >= vec_w && f <= 40, "f must be vec_w..40");
        need(iters >= 8 && iters <= f + 2, "iters must be 8..f+2");
        need(zf >= 20 && zf <= 40, "zf must be 20..40");
        need(gain_frac >= 8 && gain_frac <= 40, "gain_frac must be 8..40");
        need(lf >= 12 && lf <= 28 && ef >= 12 && ef <= 28, "lf and ef must be 12..28");
        need(tb >= 4 && tb <= 12 && rb >= 4 && rb <= 16, "tb must be 4..12, rb 4..16");
        need(lf >= tb + rb && ef >= tb + rb, "lf and ef must be >= tb + rb");
        need(flat_log2 <= -4 && flat_log2 >= -zf + 2, "flat_log2 must be -zf+2..-4");
        need(opp_tau_log2 <= -8 && opp_tau_log2 >= -f + 4, "opp_tau_log2 must be -f+4..-8");
        need(opp_k >= 1 && opp_k < (1 << 16), "opp_k must be 1..65535");
    }
};

}  // namespace spec
