// spec_model.h - bit-exact C++ model of spec_unit's datapath and pixel sequence.
//
// Every step is the integer operation of the RTL block named in the comment; the tables come from the
// same generator functions that write the ROM images (rom/gen/romgen.h).
#pragma once

#include <cstdint>
#include <vector>

#include "pow_table.h"
#include "spec_format.h"

namespace spec {

// Raw register contents, as written through spec_unit's ports.
struct SpanRegs {
    uint32_t c = 0;       // register 1, UQ0.c_w
    int64_t dzeta = 0;    // register 2, signed, ang_frac fraction bits
    int64_t zeta0 = 0;    // register 3, signed, ang_frac fraction bits
    uint32_t n = 0;       // register 4
    uint32_t len = 0;     // counter 5: intervals l
};

// Multiplier 11's registered result: position in ROM 12 and the "past pi/2" flag.
struct TablePos {
    uint32_t index = 0;   // tbl_aw bits: rounded to nearest (interp = false) or truncated (interp = true)
    uint32_t frac = 0;    // interp_frac bits below the position (interp = true; else 0)
    bool zero = false;    // |sqrt(n/k) * angle| >= pi/2 (for interp = false: after rounding to the grid)
};

class Model {
public:
    explicit Model(const Format& f = Format());

    const Format& format() const { return f_; }

    // Adder 6 with register 8: saturating two's complement addition in ang_w bits.
    int64_t accumulate(int64_t angle, int64_t dzeta) const;
    // Multiplier 11 on |angle| and ROM 9's word for n.
    TablePos mul11(int64_t angle, unsigned n) const;
    // Decoder 10: the Fig. 10 gates (patent mode with the patent's tables) or ROM 9's table field.
    int table(unsigned n) const;
    // ROM 12 read, decoder 10 choosing the table (the whole word, with the step field when interp).
    uint64_t rom12(unsigned n, const TablePos& p) const;
    // The interpolator (interp = true): table[i] - round(delta_i * f / 2^interp_frac); else the word itself.
    uint32_t interpolate(uint64_t word, uint32_t frac) const;
    // Multiplier 13: round(C * table / 2^mul13_shift), 0 when the position is past pi/2.
    uint32_t mul13(uint32_t c, uint32_t table, bool zero) const;
    // The whole datapath after register 8 (spec_datapath; in pow mode spec_powpath).
    uint32_t pixel(uint32_t c, int64_t angle, unsigned n) const;

    // Pow mode (docs/pow.md, rtl/spec_powpath.v), stage by stage:
    // ROM 9 at the angle's position, interpolated: the value V (pow_val_w bits) of L = V * 2^-(pow_xb + shift).
    uint32_t pow_log(const PowPos& p, uint32_t* shift) const;
    // Multiplier 11 and the alignment: y = floor(n V 2^(pow_yf - pow_xb - shift)), y with pow_yf fraction bits;
    // *overflow when y >= 2^(pow_yi + pow_yf) (the pixel is then 0).
    uint64_t pow_y(uint32_t v, uint32_t shift, unsigned n, bool* overflow) const;
    // ROM 12 at y's fraction (rounded to the nearest position, or interpolated with interp), shifted right by y's
    // integer part: 2^-y in UQ1.tbl_frac, what multiplier 13 multiplies by C. *zero when the integer part (after
    // the rounding's carry) reaches 2^pow_yi.
    uint32_t pow_exp(uint64_t y, bool* zero) const;
    // The value before multiplier 13 for an angle and n (0 where the pixel is 0), and the pixel.
    uint32_t pow_value(int64_t angle, unsigned n) const;
    uint32_t pow_pixel(uint32_t c, int64_t angle, unsigned n) const;
    // The l + 1 pixels of one span, in order.
    std::vector<uint32_t> span(const SpanRegs& r) const;
    // Register 8's value for pixel i of the span (with saturation).
    std::vector<int64_t> angles(const SpanRegs& r) const;

    uint32_t rom9_word(unsigned n) const { return rom9_.at(n); }   // the whole word (with the table field)
    uint32_t scale_word(unsigned n) const { return rom9_.at(n) & ((uint32_t(1) << f_.scale_w) - 1); }
    const std::vector<uint32_t>& rom9() const { return rom9_; }
    const std::vector<uint64_t>& rom12() const { return rom12_; }
    const std::vector<uint64_t>& pow_log_rom() const { return log_; }   // pow mode's ROM 9

    // Host-side quantization (what specsim does before writing the registers).
    int64_t angle_min() const { return -(int64_t(1) << (f_.ang_w - 1)); }
    int64_t angle_max() const { return (int64_t(1) << (f_.ang_w - 1)) - 1; }
    // Round to nearest; throws std::out_of_range when the value does not fit the format.
    int64_t quantize_angle(double radians) const;
    // Round to nearest UQ0.c_w; throws std::out_of_range outside [0, 1). 1 - 2^-(c_w+1) <= C < 1 gives the
    // largest code (2^c_w - 1).
    uint32_t quantize_c(double c) const;
    double angle_value(int64_t raw) const;
    double out_value(uint32_t raw) const;

private:
    Format f_;
    std::vector<uint32_t> rom9_;   // patent and tuned mode
    std::vector<uint64_t> log_;    // pow mode
    std::vector<uint64_t> rom12_;
};

}  // namespace spec
