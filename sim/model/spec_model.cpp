#include "spec_model.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "romgen.h"

namespace spec {

Model::Model(const Format& f)
    : f_(f), rom9_(f.pow() ? std::vector<uint32_t>() : make_rom9(f)), log_(f.pow() ? make_pow_log(f) : std::vector<uint64_t>()),
      rom12_(make_rom12(f)) {}

int64_t Model::accumulate(int64_t angle, int64_t dzeta) const {
    int64_t s = angle + dzeta;  // ang_w <= 40, no host overflow
    if (s > angle_max()) return angle_max();
    if (s < angle_min()) return angle_min();
    return s;
}

TablePos Model::mul11(int64_t angle, unsigned n) const {
    if (f_.pow()) throw std::logic_error("Model::mul11: pow mode's multiplier 11 multiplies by n (pow_y)");
    const uint64_t mag = static_cast<uint64_t>(angle < 0 ? -angle : angle);   // |register 8|, cos is even
    const unsigned __int128 prod = static_cast<unsigned __int128>(mag) * scale_word(n);
    const int pf = f_.prod_frac();
    const int drop = pf - f_.tbl_aw;
    const unsigned __int128 frac = prod & ((static_cast<unsigned __int128>(1) << pf) - 1);
    TablePos p;
    if (f_.interp) {
        p.zero = (prod >> pf) != 0;
        p.index = static_cast<uint32_t>(frac >> drop);
        p.frac = static_cast<uint32_t>((frac >> (drop - f_.interp_frac)) & ((uint64_t(1) << f_.interp_frac) - 1));
        return p;
    }
    const uint64_t idx_r = static_cast<uint64_t>((frac + (static_cast<unsigned __int128>(1) << (drop - 1))) >> drop);
    p.zero = (prod >> pf) != 0 || idx_r == (uint64_t(1) << f_.tbl_aw);
    p.index = static_cast<uint32_t>(idx_r & ((uint64_t(1) << f_.tbl_aw) - 1));
    return p;
}

int Model::table(unsigned n) const {
    if (f_.pow()) throw std::logic_error("Model::table: pow mode has no cos^k tables");
    return f_.decoder_rom() ? static_cast<int>(rom9_.at(n) >> f_.scale_w) : table_of_n(n);
}

uint64_t Model::rom12(unsigned n, const TablePos& p) const {
    return rom12_.at((static_cast<size_t>(table(n)) << f_.tbl_aw) | p.index);
}

uint32_t Model::interpolate(uint64_t word, uint32_t frac) const {
    const uint32_t value = static_cast<uint32_t>(word & ((uint64_t(1) << f_.tbl_dw()) - 1));
    if (!f_.interp) return value;
    const uint64_t delta = word >> f_.tbl_dw();
    const uint64_t step = (delta * frac + (uint64_t(1) << (f_.interp_frac - 1))) >> f_.interp_frac;
    return static_cast<uint32_t>(value - step);
}

uint32_t Model::mul13(uint32_t c, uint32_t table, bool zero) const {
    const uint64_t t = zero ? 0 : table;
    const int sh = f_.mul13_shift();
    const uint64_t prod = static_cast<uint64_t>(c) * t;
    return static_cast<uint32_t>(sh == 0 ? prod : (prod + (uint64_t(1) << (sh - 1))) >> sh);
}

uint32_t Model::pow_log(const PowPos& p, uint32_t* shift) const {
    const PowWord w = PowWord::unpack(f_, log_.at(p.address(f_)));
    const uint64_t prod = uint64_t(w.dlt) * p.frac;
    const uint32_t r = static_cast<uint32_t>((prod + (uint64_t(1) << (f_.pow_frac - 1))) >> f_.pow_frac);
    *shift = w.shift;
    // the step is at most |step| and lies between this entry's value and the next's: no wrap
    return w.neg ? w.val - r : w.val + r;
}

uint64_t Model::pow_y(uint32_t v, uint32_t shift, unsigned n, bool* overflow) const {
    const uint64_t p = (uint64_t(n) * v) << (f_.pow_yf - f_.pow_xb);
    const uint64_t y = p >> shift;
    *overflow = (y >> (f_.pow_yi + f_.pow_yf)) != 0;
    return y & ((uint64_t(1) << (f_.pow_yi + f_.pow_yf)) - 1);
}

uint32_t Model::pow_exp(uint64_t y, bool* zero) const {
    const int yf = f_.pow_yf, aw = f_.tbl_aw;
    uint64_t whole = y >> yf;
    const uint64_t frac = y & ((uint64_t(1) << yf) - 1);
    uint32_t b;
    if (f_.interp) {
        const uint64_t pos = frac >> (yf - aw);
        const uint32_t fr = static_cast<uint32_t>((frac >> (yf - aw - f_.interp_frac)) & ((uint64_t(1) << f_.interp_frac) - 1));
        b = interpolate(rom12_.at(pos), fr);
    } else {
        // the nearest position: ((frac >> (yf - aw - 1)) + 1) >> 1; 2^aw is position 0 of the next integer
        uint64_t pos = (frac >> (yf - aw)) + ((frac >> (yf - aw - 1)) & 1);
        whole += pos >> aw;
        pos &= (uint64_t(1) << aw) - 1;
        b = static_cast<uint32_t>(rom12_.at(pos) & ((uint64_t(1) << f_.tbl_dw()) - 1));
    }
    *zero = (whole >> f_.pow_yi) != 0;
    return *zero ? 0 : static_cast<uint32_t>(uint64_t(b) >> whole);   // whole < 2^pow_yi <= 64
}

uint32_t Model::pow_value(int64_t angle, unsigned n) const {
    const PowPos p = pow_position(f_, angle);
    uint32_t shift;
    const uint32_t v = pow_log(p, &shift);
    bool ovf, big;
    const uint32_t b = pow_exp(pow_y(v, shift, n, &ovf), &big);
    return (p.past && n != 0) || ovf || big ? 0 : b;
}

uint32_t Model::pow_pixel(uint32_t c, int64_t angle, unsigned n) const {
    return mul13(c, pow_value(angle, n), false);
}

uint32_t Model::pixel(uint32_t c, int64_t angle, unsigned n) const {
    if (f_.pow()) return pow_pixel(c, angle, n);
    const TablePos p = mul11(angle, n);
    return mul13(c, interpolate(rom12(n, p), p.frac), p.zero);
}

std::vector<int64_t> Model::angles(const SpanRegs& r) const {
    std::vector<int64_t> a;
    a.reserve(size_t(r.len) + 1);
    int64_t reg8 = r.zeta0;  // first strobe on 37 with select 36 = 0: register 3 through mux 7
    for (uint64_t i = 0; i <= r.len; ++i) {
        if (i > 0) reg8 = accumulate(reg8, r.dzeta);  // select 36 = 1: adder 6
        a.push_back(reg8);
    }
    return a;
}

std::vector<uint32_t> Model::span(const SpanRegs& r) const {
    std::vector<uint32_t> out;
    out.reserve(size_t(r.len) + 1);
    for (int64_t a : angles(r)) out.push_back(pixel(r.c, a, r.n));
    return out;
}

int64_t Model::quantize_angle(double radians) const {
    if (!std::isfinite(radians)) throw std::out_of_range("angle is not finite");
    const double q = std::nearbyint(std::ldexp(radians, f_.ang_frac));
    if (q < static_cast<double>(angle_min()) || q > static_cast<double>(angle_max())) {
        throw std::out_of_range("angle " + std::to_string(radians) + " rad is outside the format's range [" +
                                std::to_string(angle_value(angle_min())) + ", " +
                                std::to_string(angle_value(angle_max())) + "]");
    }
    return static_cast<int64_t>(q);
}

uint32_t Model::quantize_c(double c) const {
    if (!std::isfinite(c) || c < 0.0 || c >= 1.0) throw std::out_of_range("C must be in [0, 1)");
    const double q = std::nearbyint(std::ldexp(c, f_.c_w));
    const double top = std::ldexp(1.0, f_.c_w) - 1.0;
    return static_cast<uint32_t>(q > top ? top : q);
}

double Model::angle_value(int64_t raw) const { return std::ldexp(static_cast<double>(raw), -f_.ang_frac); }
double Model::out_value(uint32_t raw) const { return std::ldexp(static_cast<double>(raw), -f_.out_w); }

}  // namespace spec
