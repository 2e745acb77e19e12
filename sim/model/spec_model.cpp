#include "spec_model.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "romgen.h"

namespace spec {

Model::Model(const Format& f) : f_(f), rom9_(make_rom9(f)), rom12_(make_rom12(f)) {}

int64_t Model::accumulate(int64_t angle, int64_t dzeta) const {
    int64_t s = angle + dzeta;  // ang_w <= 40, no host overflow
    if (s > angle_max()) return angle_max();
    if (s < angle_min()) return angle_min();
    return s;
}

TablePos Model::mul11(int64_t angle, unsigned n) const {
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

uint32_t Model::pixel(uint32_t c, int64_t angle, unsigned n) const {
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
