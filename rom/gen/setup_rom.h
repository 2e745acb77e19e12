// setup_rom.h - constants and tables of spec_setup, computed from SetupFormat; the files setuprom writes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "setup_format.h"

namespace spec {

// One term of a constant multiplication by shift and add: sign * floor(t / 2^shift) (shift >= 0) or
// sign * t * 2^-shift (shift < 0). The product is the sum of the terms, each floored on its own.
struct GainTerm {
    int sign;   // +1 or -1
    int shift;
};

struct SetupConsts {
    double gain = 0;                    // G = prod_{i < iters} sqrt(1 + 4^-i), the CORDIC gain of one pass
    std::vector<GainTerm> gain_terms;   // t * G
    std::vector<GainTerm> half_terms;   // t * G / 2 (a pass that also halves its pair)
    std::vector<int64_t> atan;          // round(atan(2^-i) * 2^zf), i = 0 .. iters - 1
    int64_t half_pi = 0, pi = 0, two_pi = 0;   // round(x * 2^zf)
    int64_t n1_start = 0;               // the N1 lane's start length U = round(2^f * 4 / G^3)
    int64_t log2_gain = 0;              // round(log2(G) * 2^lf)
    int64_t flat_z = 0;                 // 2^(zf + flat_log2): gamma below it is flat
};

// Throws std::invalid_argument for an unsupported format.
SetupConsts setup_consts(const SetupFormat& sf);

// Canonical signed digits of round(x * 2^frac), as terms of x * t (shift = frac - digit position).
std::vector<GainTerm> csd_terms(double x, int frac);
// The value the terms stand for (sum of sign * 2^-shift).
double terms_value(const std::vector<GainTerm>& terms);

// log2 table: 2^tb + 1 words, word j = round(log2(1 + j / 2^tb) * 2^lf) (the last is 2^lf).
std::vector<uint64_t> make_setup_log2(const SetupFormat& sf);
// exp2 table: 2^tb + 1 words, word j = round(2^(-j / 2^tb) * 2^ef) (the first 2^ef, the last 2^(ef-1)).
std::vector<uint64_t> make_setup_exp2(const SetupFormat& sf);

std::string setup_verilog_header(const SetupFormat& sf);
std::string setup_cpp_header(const SetupFormat& sf);

// Writes setup_log2.hex, setup_exp2.hex (words 0 .. 2^tb - 1; the RTL has the last word as a constant),
// setup_params.vh and setup_params.h into dir (each through a temporary file and a rename; nothing is
// written when a table does not fit its width).
void write_setup_all(const SetupFormat& sf, const std::string& dir);

}  // namespace spec
