// fuzz_input.h - reads typed values from a fuzzer's byte string (a small FuzzedDataProvider that also
// builds with g++ for the regression replays). Past the end every read returns 0 / empty.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace fuzz {

class Input {
public:
    Input(const uint8_t* data, size_t size) : p_(data), n_(size) {}
    bool empty() const { return i_ >= n_; }
    uint8_t byte() { return i_ < n_ ? p_[i_++] : 0; }
    uint64_t u64() {
        uint64_t v = 0;
        for (int k = 0; k < 8; ++k) v = v << 8 | byte();
        return v;
    }
    // an integer in [lo, hi]
    int64_t range(int64_t lo, int64_t hi) {
        const uint64_t span = static_cast<uint64_t>(hi - lo) + 1;
        const uint64_t v = span <= 256 ? byte() : span <= 65536 ? (uint64_t(byte()) << 8 | byte()) : u64();
        return lo + static_cast<int64_t>(span == 0 ? v : v % span);
    }
    // a double: usually a modest value, sometimes raw bits (NaN, infinities, huge, tiny, -0)
    double real(double scale = 4.0) {
        const uint8_t kind = byte();
        if (kind < 32) {
            uint64_t bits = u64();
            double d;
            std::memcpy(&d, &bits, sizeof d);
            return d;
        }
        if (kind < 48) {
            static const double special[] = {0.0, -0.0, 1.0, -1.0, 0.5, 1e-300, -1e-300, 1e300, 3.141592653589793,
                                             1.5707963267948966, 8.0, -8.0, 7.999999996274710, 0.99999, 1e-9, 65535.5};
            return special[kind - 32];
        }
        const int64_t m = static_cast<int64_t>(u64() >> 11);  // 53 bits
        return scale * (static_cast<double>(m) / 4503599627370496.0 - 1.0);
    }
    // the rest split at NUL bytes (at most max_tokens)
    std::vector<std::string> tokens(size_t max_tokens = 32) {
        std::vector<std::string> t;
        std::string cur;
        while (!empty() && t.size() < max_tokens) {
            const char c = static_cast<char>(byte());
            if (c == '\0') {
                t.push_back(cur);
                cur.clear();
            } else {
                cur += c;
            }
        }
        if (!cur.empty() && t.size() < max_tokens) t.push_back(cur);
        return t;
    }

private:
    const uint8_t* p_;
    size_t n_;
    size_t i_ = 0;
};

// A broken promise: print it and abort, so that libFuzzer (or the replay) reports the input.
[[noreturn]] inline void fail(const std::string& what) {
    std::fprintf(stderr, "fuzz: %s\n", what.c_str());
    std::abort();
}
inline void check(bool ok, const std::string& what) {
    if (!ok) fail(what);
}
// Messages the programs print are one printable line: not empty, no newline, carriage return or other
// control character (input echoed in a message is escaped, spec::printable).
inline void one_line(const char* msg) {
    bool ok = *msg != '\0';
    for (const char* c = msg; *c; ++c) ok = ok && static_cast<unsigned char>(*c) >= 0x20 && *c != 0x7f;
    check(ok, std::string("message not one printable line: '") + msg + "'");
}

}  // namespace fuzz
