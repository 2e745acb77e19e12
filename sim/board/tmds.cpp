// tmds.cpp - DVI 1.0 TMDS encoder, decoder and character alignment (see tmds.h).
#include "tmds.h"

#include <cstddef>

namespace spec {
namespace board {

namespace {
const uint32_t kControl[4] = {0x354, 0x0ab, 0x154, 0x2ab};  // 1101010100, 0010101011, 0101010100, 1010101011
int ones(uint32_t v) { return __builtin_popcount(v); }
}  // namespace

uint32_t TmdsEncoder::encode(bool de, unsigned c, uint8_t d) {
    if (!de) {
        cnt_ = 0;
        return kControl[c & 3u];
    }
    // stage 1: XOR or XNOR chain, whichever gives fewer transitions
    const int n1 = ones(d);
    const bool xnor = n1 > 4 || (n1 == 4 && !(d & 1u));
    uint32_t qm = d & 1u;
    for (int i = 1; i < 8; ++i) {
        uint32_t b = ((qm >> (i - 1)) ^ (uint32_t(d) >> i)) & 1u;
        if (xnor) b ^= 1u;
        qm |= b << i;
    }
    const uint32_t qm8 = xnor ? 0u : 1u;
    // stage 2: DC balance (the running disparity counts ones minus zeros of the characters sent)
    const int diff = 2 * ones(qm) - 8;
    uint32_t q;
    if (cnt_ == 0 || diff == 0) {
        q = ((qm8 ^ 1u) << 9) | (qm8 << 8) | (qm8 ? qm : (~qm & 0xffu));
        cnt_ += qm8 ? diff : -diff;
    } else if ((cnt_ > 0 && diff > 0) || (cnt_ < 0 && diff < 0)) {
        q = (1u << 9) | (qm8 << 8) | (~qm & 0xffu);
        cnt_ += 2 * int(qm8) - diff;
    } else {
        q = (qm8 << 8) | qm;
        cnt_ += diff - 2 * int(qm8 ^ 1u);
    }
    return q;
}

TmdsChar tmds_decode(uint32_t q) {
    TmdsChar r;
    q &= 0x3ffu;
    for (unsigned c = 0; c < 4; ++c) {
        if (q == kControl[c]) {
            r.is_control = true;
            r.c = c;
            return r;
        }
    }
    const uint32_t v = (q & 0x200u) ? (~q & 0xffu) : (q & 0xffu);
    const bool xor_chain = (q & 0x100u) != 0;
    uint32_t d = v & 1u;
    for (int i = 1; i < 8; ++i) {
        uint32_t b = ((v >> i) ^ (v >> (i - 1))) & 1u;
        if (!xor_chain) b ^= 1u;
        d |= b << i;
    }
    r.d = uint8_t(d);
    // a data character must be what the encoder makes of d at some running disparity
    r.valid = false;
    for (int cnt = -8; cnt <= 8 && !r.valid; cnt += 2) {
        TmdsEncoder e;
        e.set_disparity(cnt);
        r.valid = (e.encode(true, 0, r.d) == q);
    }
    return r;
}

int find_alignment(const std::vector<uint8_t>& bits, int run) {
    for (int off = 0; off < 10; ++off) {
        int streak = 0;
        for (size_t i = size_t(off); i + 10 <= bits.size(); i += 10) {
            uint32_t q = 0;
            for (int b = 0; b < 10; ++b) q |= uint32_t(bits[i + size_t(b)] & 1u) << b;
            streak = tmds_decode(q).is_control ? streak + 1 : 0;
            if (streak >= run) return off;
        }
    }
    return -1;
}

std::vector<uint32_t> to_chars(const std::vector<uint8_t>& bits, int offset) {
    std::vector<uint32_t> out;
    for (size_t i = size_t(offset); i + 10 <= bits.size(); i += 10) {
        uint32_t q = 0;
        for (int b = 0; b < 10; ++b) q |= uint32_t(bits[i + size_t(b)] & 1u) << b;
        out.push_back(q);
    }
    return out;
}

}  // namespace board
}  // namespace spec
