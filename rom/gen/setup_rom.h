// setup_rom.h - the files setuprom writes for a setup configuration (rom/gen/setup_format.h): the EFU's and the
// finish stage's tables, the machine's microcode, and the parameter headers that carry the schedule's shape to the
// RTL (setup_params.vh) and to C++ (setup_params.h). docs/setup.md describes each.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "setup_format.h"
#include "setup_small_format.h"
#include "setup_program.h"
#include "setup_sched.h"

namespace spec {

// Everything a configuration generates, computed once.
struct SetupBuild {
    SetupFormat sf;
    SetupProgram prog;
    SetupTables tab;
    SetupSchedule sched;
    SetupUcodeLayout lay;
    std::vector<std::vector<uint64_t>> ucode;
    explicit SetupBuild(const SetupFormat& f);
};

std::string setup_verilog_header(const SetupBuild& b, const std::string& rom_dir);
std::string setup_cpp_header(const SetupBuild& b);
std::string setup_efu_image(const SetupBuild& b);     // the EFU's table ROM
std::string setup_exp2_image(const SetupBuild& b);    // the finish stage's exp2 table
std::string setup_ucode_image(const SetupBuild& b);   // II microcode words

// Writes setup_efu.hex, setup_exp2.hex, setup_ucode.hex, setup_params.vh and setup_params.h into dir (each through
// a temporary file and a rename). rom_dir: the directory name the header's default file parameters use.
// Before writing, the schedule runs spans through the cycle-level machine (SetupMachineSim) against the program;
// a difference is an internal error and nothing is written.
void write_setup_all(const SetupFormat& sf, const std::string& dir, const std::string& rom_dir);

// ---- the up5k configuration's small CORDIC setup (spec_setup_small; rom/gen/setup_small_format.h) ------------

// One term of a constant multiplication by shift and add: sign * floor(t / 2^shift) (shift >= 0) or
// sign * t * 2^-shift (shift < 0). The product is the sum of the terms, each floored on its own.
struct GainTerm {
    int sign;   // +1 or -1
    int shift;
};

struct SmallSetupConsts {
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
SmallSetupConsts small_setup_consts(const SmallSetupFormat& sf);

// Canonical signed digits of round(x * 2^frac), as terms of x * t (shift = frac - digit position).
std::vector<GainTerm> csd_terms(double x, int frac);
// The value the terms stand for (sum of sign * 2^-shift).
double terms_value(const std::vector<GainTerm>& terms);

// log2 table: 2^tb + 1 words, word j = round(log2(1 + j / 2^tb) * 2^lf) (the last is 2^lf).
std::vector<uint64_t> make_small_log2(const SmallSetupFormat& sf);
// exp2 table: 2^tb + 1 words, word j = round(2^(-j / 2^tb) * 2^ef) (the first 2^ef, the last 2^(ef-1)).
std::vector<uint64_t> make_small_exp2(const SmallSetupFormat& sf);

std::string small_verilog_header(const SmallSetupFormat& sf, const std::string& rom_dir);
std::string small_cpp_header(const SmallSetupFormat& sf);

// Writes setup_small_log2.hex, setup_small_exp2.hex (words 0 .. 2^tb - 1; the RTL has the last word as a
// constant), setup_small_params.vh and setup_small_params.h into dir (each through a temporary file and a
// rename; nothing is written when a table does not fit its width).
void write_small_all(const SmallSetupFormat& sf, const std::string& dir, const std::string& rom_dir);

}  // namespace spec
