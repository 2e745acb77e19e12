#include "pow_table.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace spec {

namespace {
uint64_t mask(int w) { return w >= 64 ? ~uint64_t(0) : (uint64_t(1) << w) - 1; }
}  // namespace

PowPos pow_position(const Format& f, int64_t angle) {
    const int af = f.ang_frac;
    const int ns = 1 << f.pow_seg_w;
    const uint64_t mag = angle < 0 ? uint64_t(-angle) : uint64_t(angle);   // |register 8| (2^(ang_w-1) fits)
    const int64_t k = f.pow_half_pi();
    PowPos p;
    p.past = int64_t(mag) > k;
    p.side = mag >= (uint64_t(1) << af) ? 1 : 0;
    // side 1: K - a in ang_frac bits (two's complement, as the RTL's difference; a past K gives a position the
    // output never depends on: it is 0, or C for n = 0)
    const uint64_t t = (p.side ? uint64_t(k) - mag : mag) & mask(af);
    int bl = 0;
    while (bl < 64 && (t >> bl) != 0) ++bl;
    const int lz = af - bl;
    const int sh = std::min(lz, ns - 2);
    p.seg = std::min(lz, ns - 1);
    const uint64_t u = t << sh;   // the leading one (if any) at bit af - 1
    p.idx = static_cast<uint32_t>((u >> (af - 1 - f.pow_idx_w)) & mask(f.pow_idx_w));
    const int low = af - 1 - f.pow_idx_w - f.pow_frac;   // the fraction's LSB in u
    p.frac = static_cast<uint32_t>((low >= 0 ? u >> low : u << -low) & mask(f.pow_frac));
    return p;
}

double pow_grid_t(const Format& f, int seg, double idx) {
    const int ns = 1 << f.pow_seg_w;
    const int m = 1 << f.pow_idx_w;
    if (seg < ns - 1) return std::ldexp(m + idx, f.ang_frac - 1 - f.pow_idx_w - seg);
    return std::ldexp(idx, f.ang_frac - 1 - f.pow_idx_w - (ns - 2));
}

double pow_angle(const Format& f, int side, double t) {
    return std::ldexp(side == 0 ? t : double(f.pow_half_pi()) - t, -f.ang_frac);
}

double pow_log_exact(const Format& f, int side, double t) { return -std::log2(std::cos(pow_angle(f, side, t))); }

double pow_log_entry(const Format& f, int side, int seg, double idx) {
    const int ns = 1 << f.pow_seg_w;
    if (side == 1 && seg == ns - 1 && idx == 0) return pow_log_exact(f, 1, pow_grid_t(f, seg, 1)) + kPowEdgeStep;
    return pow_log_exact(f, side, pow_grid_t(f, seg, idx));
}

uint64_t PowWord::pack(const Format& f) const {
    return (uint64_t(shift) << (f.pow_val_w + f.pow_dlt_w + 1)) | (uint64_t(neg ? 1 : 0) << (f.pow_val_w + f.pow_dlt_w)) |
           (uint64_t(dlt) << f.pow_val_w) | val;
}

PowWord PowWord::unpack(const Format& f, uint64_t w) {
    PowWord p;
    p.val = static_cast<uint32_t>(w & mask(f.pow_val_w));
    p.dlt = static_cast<uint32_t>((w >> f.pow_val_w) & mask(f.pow_dlt_w));
    p.neg = ((w >> (f.pow_val_w + f.pow_dlt_w)) & 1) != 0;
    p.shift = static_cast<uint32_t>((w >> (f.pow_val_w + f.pow_dlt_w + 1)) & mask(f.pow_sh_w));
    return p;
}

std::vector<uint64_t> make_pow_log(const Format& f) {
    f.validate();
    if (!f.pow()) throw std::invalid_argument("make_pow_log: the format is not in pow mode");
    const int ns = 1 << f.pow_seg_w;
    const int m = 1 << f.pow_idx_w;
    const double vmax = std::ldexp(1.0, f.pow_val_w) - 1.0;
    std::vector<uint64_t> rom(size_t(1) << f.rom9_aw());
    for (int side = 0; side < 2; ++side) {
        for (int seg = 0; seg < ns; ++seg) {
            std::vector<double> l(m + 1);
            double lmax = 0;
            for (int i = 0; i <= m; ++i) {
                l[i] = pow_log_entry(f, side, seg, i);
                if (!std::isfinite(l[i]) || l[i] < 0) {
                    throw std::out_of_range("ROM 9 (pow): -log2 cos is not finite at side " + std::to_string(side) +
                                            ", segment " + std::to_string(seg) + ", entry " + std::to_string(i));
                }
                lmax = std::max(lmax, l[i]);
            }
            // the segment's scale: the finest whose values (and the point after the last) fit pow_val_w bits
            int x = f.pow_xb + (1 << f.pow_sh_w) - 1;
            while (x >= f.pow_xb && std::nearbyint(std::ldexp(lmax, x)) > vmax) --x;
            if (x < f.pow_xb) {
                throw std::out_of_range("ROM 9 (pow): side " + std::to_string(side) + ", segment " + std::to_string(seg) +
                                        " needs a scale below 2^-pow_xb (values up to " + std::to_string(lmax) + ")");
            }
            for (int i = 0; i < m; ++i) {
                const double v = std::nearbyint(std::ldexp(l[i], x));
                const double next = std::nearbyint(std::ldexp(l[i + 1], x));
                const double d = next - v;
                PowWord w;
                w.val = static_cast<uint32_t>(v);
                w.neg = d < 0;
                w.shift = static_cast<uint32_t>(x - f.pow_xb);
                if (std::fabs(d) > std::ldexp(1.0, f.pow_dlt_w) - 1) {
                    throw std::out_of_range("ROM 9 (pow): step " + std::to_string((long long)d) + " at side " + std::to_string(side) +
                                            ", segment " + std::to_string(seg) + ", entry " + std::to_string(i) +
                                            " does not fit pow_dlt_w = " + std::to_string(f.pow_dlt_w) + " bits");
                }
                w.dlt = static_cast<uint32_t>(std::fabs(d));
                PowPos p;
                p.side = side;
                p.seg = seg;
                p.idx = static_cast<uint32_t>(i);
                rom[p.address(f)] = w.pack(f);
            }
        }
    }
    return rom;
}

std::vector<uint64_t> make_pow_exp(const Format& f) {
    f.validate();
    if (!f.pow()) throw std::invalid_argument("make_pow_exp: the format is not in pow mode");
    const size_t per = size_t(1) << f.tbl_aw;
    std::vector<uint64_t> v(per + 1);
    for (size_t p = 0; p <= per; ++p) {
        v[p] = static_cast<uint64_t>(std::nearbyint(std::ldexp(std::exp2(-double(p) / double(per)), f.tbl_frac)));
    }
    std::vector<uint64_t> rom(per);
    for (size_t p = 0; p < per; ++p) {
        uint64_t word = v[p];
        if (f.interp) {
            const uint64_t delta = v[p] - v[p + 1];
            if (delta >= (uint64_t(1) << f.delta_w)) {
                throw std::out_of_range("ROM 12 (pow): delta " + std::to_string(delta) + " at address " +
                                        std::to_string(p) + " does not fit delta_w = " + std::to_string(f.delta_w) +
                                        " bits");
            }
            word |= delta << f.tbl_dw();
        }
        rom[p] = word;
    }
    return rom;
}

}  // namespace spec
