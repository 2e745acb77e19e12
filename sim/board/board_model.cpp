// board_model.cpp - the bit-exact model of boards/common/ (see board_model.h).
#include "board_model.h"

#include <cstdlib>
#include <stdexcept>

namespace spec {
namespace board {

uint64_t isqrt(uint64_t x) {
    uint64_t r = 0, rem = 0;
    for (int i = 62; i >= 0; i -= 2) {   // the digit-by-digit method, as isqrt.v
        rem = (rem << 2) | ((x >> i) & 3u);
        const uint64_t trial = (r << 2) | 1u;
        r <<= 1;
        if (rem >= trial) {
            rem -= trial;
            r |= 1u;
        }
    }
    return r;
}

std::vector<SubSpan> line_spans(const BoardScene& s, int y) {
    std::vector<SubSpan> out;
    const int zf = s.zf;
    for (size_t o = 0; o < s.spheres.size(); ++o) {
        const Sphere& sp = s.spheres[o];
        const int64_t r2 = 2 * sp.r;
        const int64_t dy = 2 * int64_t(y) + 1 - 2 * int64_t(sp.cy);
        if (std::llabs(dy) >= r2) continue;
        const uint64_t w2 = uint64_t(r2 * r2 - dy * dy);
        const uint64_t sroot = isqrt(w2 << (2 * zf)) >> zf;   // floor(sqrt(w2)), through the Z-width root
        if (sroot == 0) continue;
        const int64_t m = (sroot & 1u) ? int64_t(sroot) : int64_t(sroot) - 1;
        const int64_t x0 = sp.cx - (m + 1) / 2;
        bool have_prev = false;
        int64_t p_prev = 0;
        std::array<int32_t, 3> n_prev{};
        for (int j = 0; j <= s.split_k; ++j) {
            const int64_t p = (m * int64_t(s.split[size_t(j)]) + 128) >> 8;
            if (have_prev && p == p_prev) continue;
            const int64_t dx = 2 * p - m;
            const uint64_t z = isqrt((w2 - uint64_t(dx * dx)) << (2 * zf));
            const std::array<int32_t, 3> n{int32_t(dx * (1 << zf)), int32_t(dy * (1 << zf)), int32_t(z)};
            if (have_prev) {
                SubSpan ss;
                ss.obj = unsigned(o);
                ss.x0 = int(x0 + p_prev);
                ss.l = unsigned(p - p_prev);
                ss.n1 = n_prev;
                ss.n2 = n;
                out.push_back(ss);
            }
            have_prev = true;
            p_prev = p;
            n_prev = n;
        }
    }
    return out;
}

namespace {
// round(mag k / 2^14), half up (mag, k >= 0)
uint32_t light_product(uint32_t mag, int32_t k) {
    const uint64_t p = uint64_t(mag) * uint64_t(k);
    return uint32_t((p >> 14) + ((p >> 13) & 1u));
}
}  // namespace

std::vector<uint32_t> light_table(const Quant& q) {
    if (q.quarter_sin.size() != 65) throw std::logic_error("light_table: the quarter wave must have 65 words");
    std::vector<uint32_t> t(256, 0u);
    for (size_t i = 0; i < q.quarter_sin.size(); ++i) {
        t[i] = light_product(q.quarter_sin[i], q.sin_e);
        t[128 + i] = light_product(q.quarter_sin[i], q.sin_half_e);
    }
    return t;
}

LightQ light_q(const Quant& q, unsigned frame) {
    const unsigned t = frame & 255u;
    auto wave = [&](unsigned a, bool* neg) {   // |sin(2 pi a / 256)| from the quarter wave, and its sign
        a &= 255u;
        const unsigned i = a & 63u;
        *neg = (a & 128u) != 0;
        return q.quarter_sin[(a & 64u) ? 64 - i : i];
    };
    auto mul = [](uint32_t mag, int32_t k, bool neg) {   // round(mag k / 2^14) with the sign
        const int32_t r = int32_t(light_product(mag, k));
        return neg ? -r : r;
    };
    bool ns = false, nc = false;
    const uint32_t ms = wave(t, &ns), mc = wave(t + 64, &nc);
    LightQ L;
    L.l = {mul(mc, q.sin_e, nc), mul(ms, q.sin_e, ns), q.cos_e};
    L.h = {mul(mc, q.sin_half_e, nc), mul(ms, q.sin_half_e, ns), q.cos_half_e};
    return L;
}

std::array<uint32_t, 3> compose(const ObjQuant& o, uint32_t dif, uint32_t spc, int out_bits) {
    const uint32_t e = std::min<uint32_t>(65535u, o.ka + dif);
    std::array<uint32_t, 3> rgb{};
    const uint32_t scale = (1u << out_bits) - 1u;
    for (int c = 0; c < 3; ++c) {
        const uint32_t p = (e * o.cd[c]) >> 8;
        const uint32_t s = std::min<uint32_t>(65535u, p + spc);
        rgb[size_t(c)] = (s * scale + 32768u) >> 16;
    }
    return rgb;
}

std::array<uint32_t, 3> background(const Quant& q, int out_bits) {
    std::array<uint32_t, 3> rgb{};
    for (int c = 0; c < 3; ++c) {
        // the 8-bit colour reduced as compose.v reduces a 16-bit one: v * 257 is v as UQ0.16
        const uint32_t s = q.bg8[c] * 257u;
        rgb[size_t(c)] = (s * ((1u << out_bits) - 1u) + 32768u) >> 16;
    }
    return rgb;
}

Frame model_frame(const BoardScene& s, const Shader& shader, unsigned f, int out_bits, int y0, int y1) {
    const Quant q = quantize(s);
    const LightQ light = light_q(q, f);
    Frame fr;
    fr.w = s.mode.h_active;
    fr.h = s.mode.v_active;
    fr.out_bits = out_bits;
    fr.px.assign(size_t(fr.w) * size_t(fr.h), background(q, out_bits));
    for (int y = y0; y < y1; ++y) {
        for (const SubSpan& ss : line_spans(s, y)) {
            const ObjQuant& o = q.obj[ss.obj];
            ShadeIn in;
            in.n1 = ss.n1;
            in.n2 = ss.n2;
            in.l = ss.l;
            in.zf = s.zf;
            in.light = light.l;
            in.n = 1;
            in.strength = o.kd;
            const std::vector<uint32_t> dif = shader(in);
            in.light = light.h;
            in.n = o.n;
            in.strength = o.ks;
            const std::vector<uint32_t> spc = shader(in);
            if (dif.size() != ss.l + 1 || spc.size() != ss.l + 1) throw std::logic_error("shader: wrong pixel count");
            for (unsigned i = 0; i <= ss.l; ++i) {
                fr.px[size_t(y) * size_t(fr.w) + size_t(ss.x0) + i] = compose(o, dif[i], spc[i], out_bits);
            }
        }
    }
    return fr;
}

}  // namespace board
}  // namespace spec
