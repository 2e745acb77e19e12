// spec_format.h - the one set of definitions behind every width, scale and table of the core.
//
// The ROM generator (specrom) emits the $readmemh images of ROM 9 and ROM 12 and the headers
// rom/spec_params.vh (Verilog) and rom/spec_params.h (C++) from this struct; the bit-exact model
// computes its tables with the same functions (romgen.h). A ctest fails when a committed file in rom/
// differs from what the generator makes now, so RTL, model and generator cannot drift.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace spec {

// How ROM 9 (and the table choice) are filled (docs/tuned.md, docs/pow.md).
//   patent: ROM 9 holds sqrt(n/k) (the patent's Taylor match), decoder 10 picks k by the Fig. 10 gates.
//   tuned:  ROM 9 holds, per n, the scale that minimises the worst relative error over the epicentre
//           (minimax) and, in two extra bits above it, the table that does best: the decoder becomes a ROM
//           (the patent allows it: "decoder 10 may also be a ROM"). Same datapath, same ROM 12.
//   pow:    cos^n = exp2(n log2 cos): ROM 9 holds -log2 cos of the angle (read every pixel at register 8's angle,
//           a floating format, interpolated), multiplier 11 multiplies it by n, ROM 12 holds exp2 of minus the
//           fraction, shifted by the integer part, and multiplier 13 multiplies by C. Every n is computed, no
//           cos^k approximation (docs/pow.md). The RTL's parameter POW = 1.
enum class Mode { patent, tuned, pow };
inline const char* mode_name(Mode m) { return m == Mode::tuned ? "tuned" : m == Mode::pow ? "pow" : "patent"; }
// Throws std::invalid_argument for anything but "patent", "tuned" or "pow".
inline Mode parse_mode(const std::string& s) {
    if (s == "patent") return Mode::patent;
    if (s == "tuned") return Mode::tuned;
    if (s == "pow") return Mode::pow;
    throw std::invalid_argument("unknown mode '" + s + "' (patent, tuned, pow)");
}

// The patent's four tables of ROM 12 (Fig. 10, Fig. 15).
constexpr int kTables[4] = {1, 2, 4, 16};
inline std::vector<int> patent_tables() { return {1, 2, 4, 16}; }

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

    // ROM 9's contents and the table set (docs/tuned.md). The default is the patent: Taylor scale sqrt(n/k),
    // tables k = 1, 2, 4, 16, chosen by decoder 10's gates. Any other table set, and tuned mode, put the table
    // index into ROM 9's word above the scale (decoder_rom()); ROM 12 holds the tables in the order given,
    // padded with zero tables up to 2^tsel_w().
    Mode mode = Mode::patent;
    std::vector<int> tables = patent_tables();   // k of each ROM 12 table, strictly increasing, 1..256

    // Pow mode (mode == Mode::pow, docs/pow.md). ROM 9 is the log table L(t) = -log2 cos: the angle's magnitude a
    // below 1 rad is t = a itself (side 0), from 1 rad to pi/2 it is t = K - a, K = pi/2 in the angle format
    // (side 1, where L = -log2 sin t); t < 1 rad either way. Each side has 2^pow_seg_w segments: the octaves
    // [2^-(j+1), 2^-j) rad, j = 0 .. 2^pow_seg_w - 2, and the interval below the last octave; each segment has
    // 2^pow_idx_w equidistant entries, interpolated linearly with pow_frac fraction bits of the position. A word
    // holds {shift s (pow_sh_w bits), sign of the step, |step| (pow_dlt_w bits), value V (pow_val_w bits)} with
    // L = V * 2^-(pow_xb + s); the step is the next entry's value minus this one's, in this entry's scale.
    // y = n * L is formed with pow_yf fraction bits; y >= 2^pow_yi gives 0. ROM 12 holds 2^-f, f = y's fraction,
    // over 2^tbl_aw positions (UQ1.tbl_frac; with interp its step to the next position, as in patent mode).
    int pow_seg_w = 3;
    int pow_idx_w = 6;
    int pow_frac = 10;
    int pow_val_w = 16;
    int pow_dlt_w = 14;
    int pow_sh_w = 5;
    int pow_xb = 12;
    int pow_yf = 18;
    int pow_yi = 5;

    bool pow() const { return mode == Mode::pow; }
    bool decoder_rom() const { return mode == Mode::tuned || (mode == Mode::patent && tables != patent_tables()); }
    int tsel_w() const {                                  // width of the table index (>= 1)
        int w = 1;
        while ((size_t(1) << w) < tables.size()) ++w;
        return w;
    }
    // ROM 9: {table index, scale}; pow mode: the log table's word, addressed by {side, segment, entry}
    int rom9_dw() const { return pow() ? pow_sh_w + 1 + pow_dlt_w + pow_val_w : scale_w + (decoder_rom() ? tsel_w() : 0); }
    int rom9_aw() const { return pow() ? 1 + pow_seg_w + pow_idx_w : n_w; }
    int tbl_dw() const { return tbl_frac + 1; }
    int rom12_dw() const { return tbl_dw() + (interp ? delta_w : 0); }
    // {table index, position (tbl_aw bits)}; pow mode: one table (exp2), the position alone
    int rom12_aw() const { return tbl_aw + (pow() ? 0 : tsel_w()); }
    // pow mode: pi/2 in the angle format (round(pi/2 * 2^ang_frac)), the constant K of the log table's side 1
    long long pow_half_pi() const;
    int prod_frac() const { return ang_frac + scale_frac; }  // fraction bits of multiplier 11's product
    int mul13_shift() const { return c_w + tbl_frac - out_w; }

    // spec_stream's span descriptor (rtl/spec_stream.v): C, n and l each start at the next multiple of 16 bits,
    // the two angles at the next multiple of 32, and the descriptor is a whole number of 32-bit words. For the
    // default widths: C [15:0], n [25:16], l [47:32], zeta0 [95:64], dzeta [127:96], 128 bits.
    struct DescLayout {
        int c_lsb, n_lsb, l_lsb, zeta0_lsb, dzeta_lsb, width;
    };
    DescLayout desc() const {
        auto up = [](int v, int m) { return (v + m - 1) / m * m; };
        DescLayout d;
        d.c_lsb = 0;
        d.n_lsb = up(d.c_lsb + c_w, 16);
        d.l_lsb = up(d.n_lsb + n_w, 16);
        d.zeta0_lsb = up(d.l_lsb + l_w, 32);
        d.dzeta_lsb = up(d.zeta0_lsb + ang_w, 32);
        d.width = up(d.dzeta_lsb + ang_w, 32);
        return d;
    }

    // Latencies in clock cycles, as the RTL's pipeline has them (a ctest measures them on the Verilated cores):
    //   datapath_latency: spec_datapath, register 8 to output 27 (multiplier 11: 7 stages, ROM 12 and the register
    //                     after it: 2, the interpolator: 2 when interp, multiplier 13: 3);
    //   unit_first_pixel: spec_unit, Start in cycle t -> pixel i's valid_o in cycle t + unit_first_pixel + 2i;
    //   stream_datapath_latency: spec_datapath with PIPE = 1 (spec_stream): a register after each DSP block,
    //                     2 more (4 with interp: also a second register on ROM 12's word, so that the block
    //                     RAM's output register and the interpolator's DSP input register have one each);
    //   stream_acc:       spec_stream's pipelined accumulator (spec_saccum): an input stage, one stage per 12-bit
    //                     segment of ang_w + l_w bits, the last sum segment, two clamp stages;
    //   stream_latency:   spec_stream, descriptor accepted in cycle a (core idle) -> first beat in a + this
    //                     (descriptor buffer and span generator 3, accumulator, datapath, output register);
    //   stream_seq_latency: spec_stream_seq, descriptor accepted in cycle a -> first pixel in a + this (span
    //                     registers and ROM 9 1, spec_datapath with PIPE = 0, output register 1);
    //   stream_seq_gap:   spec_stream_seq, clocks without a pixel between two spans when the next descriptor
    //                     waits and the sink is ready (the last pixel leaves the datapath, then s_axis_tready).
    //   pow mode: spec_powpath's stages instead of spec_datapath's (pow_latency; docs/pow.md).
    int datapath_latency() const { return pow() ? pow_latency(false) : 7 + 2 + (interp ? 2 : 0) + 3; }
    int unit_first_pixel() const { return datapath_latency() + 3; }
    int stream_datapath_latency() const {
        return pow() ? pow_latency(true) : datapath_latency() + 2 + (interp ? 2 : 0);
    }
    // spec_powpath's latency (rtl/spec_powpath.v), pipe: PIPE = 1 (spec_stream: a register after each DSP block,
    // a second one on each interpolated table's word). Front end 3 (|angle| and K - |angle|, side), normalization
    // pow_seg_w, ROM 9 with its register(s), interpolation 2, multiplier by n 2 (input and product registers), the
    // alignment shift (two levels of pow_sh_w a stage), ROM 12's position (plain: rounding 1), ROM 12 with its
    // register(s), [interpolation 2], the shift by y's integer part (two levels a stage, the last in front of
    // multiplier 13) pow_yi / 2, multiplier 13 3.
    int pow_latency(bool pipe) const {
        const int p = pipe ? 1 : 0;
        return 3 + pow_seg_w + (1 + 1 + p) + (2 + p) + (2 + p) + (pow_sh_w + 1) / 2 + (interp ? 0 : 1) +
               (1 + 1 + (interp ? p : 0)) + (interp ? 2 + p : 0) + pow_yi / 2 + (3 + p);
    }
    int stream_acc() const { return (ang_w + l_w + 11) / 12 + 4; }
    int stream_latency() const { return 4 + stream_acc() + stream_datapath_latency(); }
    int stream_seq_latency() const { return datapath_latency() + 2; }
    int stream_seq_gap() const { return datapath_latency() + 2; }

    // Throws std::invalid_argument with a one-line reason when the combination is not supported.
    void validate() const;
};

// Named configurations. "default" is the patent's plain lookup (the committed ROM images in rom/);
// "up5k" fits the iCE40 UP5K's block RAM (ROM 12 of 4 x 256 words with interpolation, a 16-bit ROM 9)
// and keeps the same accuracy bound (docs/decisions.md, docs/stream.md). Either configuration in pow mode
// (mode = Mode::pow): ROM 9 is the log table (2 x 8 x 64 entries; up5k 2 x 8 x 32), ROM 12 the exp2 table of
// the configuration's size (docs/pow.md).
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
        f.pow_idx_w = 5;   // pow mode: ROM 9 of 2 x 8 x 32 words (five SB_RAM40_4K with ROM 12's two, docs/pow.md)
        return f;
    }
    throw std::invalid_argument("unknown configuration '" + name + "' (default, up5k)");
}

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
