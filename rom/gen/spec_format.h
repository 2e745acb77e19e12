// spec_format.h - the one set of definitions behind every width, scale and table of the core.
//
// The ROM generator (specrom) emits the $readmemh images of ROM 9 and ROM 12 and the headers
// rom/spec_params.vh (Verilog) and rom/spec_params.h (C++) from this struct; the bit-exact model
// computes its tables with the same functions (romgen.h). A ctest fails when a committed file in rom/
// differs from what the generator makes now, so RTL, model and generator cannot drift.
#pragma once

#include <stdexcept>
#include <string>

namespace spec {

struct Format {
    // Interface widths (ports of spec_unit).
    int c_w = 16;        // register 1: C, unsigned fraction UQ0.c_w
    int ang_w = 32;      // registers 2, 3, 8: angles, two's complement, ang_frac fraction bits (radians)
    int ang_frac = 28;   //   -> range [-2^(ang_w-ang_frac-1), 2^(ang_w-ang_frac-1)) = [-8, 8) rad
    int n_w = 10;        // register 4: exponent n, 0 .. 2^n_w - 1
    int l_w = 16;        // counter 5: intervals l, 0 .. 2^l_w - 1 (l + 1 pixels)
    int out_w = 16;      // output 27: intensity, UQ0.out_w (must equal c_w so that n = 0 gives C exactly)

    // ROM 9: per n, s(n) = sqrt(n/k(n)) * 2/pi, unsigned UQ(scale_w-scale_frac).scale_frac.
    // The 2/pi folds ROM 12's angle unit (quarter turns) into the scale, so multiplier 11's product
    // is the table position directly and |sqrt(n/k) * angle| >= pi/2 is "integer part non-zero".
    int scale_w = 18;
    int scale_frac = 15;

    // ROM 12: four tables cos^k(x), k = 1, 2, 4, 16, x = i * (pi/2) / 2^tbl_aw, i = 0 .. 2^tbl_aw - 1.
    // Values are UQ1.tbl_frac in tbl_frac + 1 bits, so 1.0 (x = 0) is exact.
    int tbl_aw = 12;
    int tbl_frac = 16;

    // Interpolation (a departure from the patent, off by default): each ROM 12 word also holds
    // delta_i = table[i] - table[i+1] (>= 0, the tables fall monotonically; table[2^tbl_aw] = cos^k(pi/2) = 0),
    // multiplier 11 truncates to position i and keeps interp_frac fraction bits f, and the interpolator
    // gives table[i] - round(delta_i * f / 2^interp_frac). Small tables then keep the accuracy of large ones.
    bool interp = false;
    int interp_frac = 10;
    int delta_w = 10;

    int tbl_dw() const { return tbl_frac + 1; }
    int rom12_dw() const { return tbl_dw() + (interp ? delta_w : 0); }
    int rom12_aw() const { return tbl_aw + 2; }          // {table index (2 bits), position (tbl_aw bits)}
    int prod_frac() const { return ang_frac + scale_frac; }  // fraction bits of multiplier 11's product
    int mul13_shift() const { return c_w + tbl_frac - out_w; }

    // Throws std::invalid_argument with a one-line reason when the combination is not supported.
    void validate() const;
};

// Named configurations. "default" is the patent's plain lookup (the committed ROM images in rom/);
// "up5k" fits the iCE40 UP5K's block RAM (ROM 12 of 4 x 256 words with interpolation, a 16-bit ROM 9)
// and keeps the same accuracy bound (docs/decisions.md, docs/stream.md).
inline Format config_format(const std::string& name) {
    Format f;
    if (name == "default") return f;
    if (name == "up5k") {
        f.tbl_aw = 8;
        f.interp = true;
        f.interp_frac = 10;
        f.delta_w = 10;
        f.scale_w = 16;
        f.scale_frac = 13;
        return f;
    }
    throw std::invalid_argument("unknown configuration '" + name + "' (default, up5k)");
}

// The four tables of ROM 12 and the Fig. 10 rule.
constexpr int kTables[4] = {1, 2, 4, 16};

// Fig. 10 (decoder 10): n = 1 -> table 0 (k = 1); n = 2 -> table 1 (k = 2); n = 3..6 -> table 2 (k = 4);
// every other n (0, 7..1000 and 1001..1023) -> table 3 (k = 16).
inline int table_of_n(unsigned n) {
    if (n == 1) return 0;
    if (n == 2) return 1;
    if (n >= 3 && n <= 6) return 2;
    return 3;
}
inline int k_of_n(unsigned n) { return kTables[table_of_n(n)]; }

}  // namespace spec
