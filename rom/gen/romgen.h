// romgen.h - contents of ROM 9 and ROM 12 and the files the generator writes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "spec_format.h"

namespace spec {

// ROM 9: 2^n_w words, word n = round(s(n) * 2/pi * 2^scale_frac) with s(n) the scale of fit.h (patent mode:
// sqrt(n / k(n))); word 0 = 0 (n = 0: cos^0 = 1). With f.decoder_rom() (tuned mode or another table set) the
// table index of n sits above the scale: word = table << scale_w | scale (rom9_dw() bits).
std::vector<uint32_t> make_rom9(const Format& f);

// ROM 12: 2^tsel_w * 2^tbl_aw words (4 tables for the patent's set), word (t << tbl_aw) | i =
// round(cos^k_t(i * pi/2 / 2^tbl_aw) * 2^tbl_frac) with k_t = f.tables[t] (0 for the padding tables),
// with interp: | (word_i - word_(i+1)) << tbl_dw (the next position of the last word is cos^k(pi/2) = 0).
std::vector<uint64_t> make_rom12(const Format& f);

// Exact real value ROM 9's scale stands for (s(n) * 2/pi, before rounding), for the analysis.
double rom9_exact(const Format& f, unsigned n);

// $readmemh text: the header line (a `//` comment, omitted when empty), then one word per line, fixed width hex
// digits. Every value is range-checked against `width` bits (std::out_of_range names the ROM and the address).
std::string hex_image(const std::vector<uint64_t>& words, int width, const std::string& what,
                      const std::string& header = "");

// The first line of each image: the parameters it was made for, which the RTL reads back at time 0
// (rtl/spec_rom9.v, rtl/spec_rom12.v) and syn/rom_check.py checks before synthesis.
std::string rom9_header(const Format& f);
std::string rom12_header(const Format& f);

// The Verilog header: every parameter, the descriptor layout and the latencies as SPEC_* macros, and the ROM
// images' paths as SPEC_ROM9_FILE / SPEC_ROM12_FILE = rom_dir + file name (rom_dir ends in '/', or is empty).
std::string verilog_header(const Format& f, const std::string& rom_dir = "rom/");
std::string cpp_header(const Format& f);

// Writes rom9_scale.hex, rom12_cosk.hex, spec_params.vh and spec_params.h into dir; the Verilog header names
// the images as rom_dir + file name. Each file is written to a temporary name and renamed, so no half-written
// file is left behind.
void write_all(const Format& f, const std::string& dir, const std::string& rom_dir);

}  // namespace spec
