#include "romgen.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "fit.h"
#include "pow_table.h"

namespace spec {

namespace {
constexpr double kPi = 3.14159265358979323846;

uint32_t checked_round(double v, int width, const char* what, size_t addr) {
    if (!std::isfinite(v) || v < 0.0) {
        throw std::out_of_range(std::string(what) + ": value at address " + std::to_string(addr) +
                                " is not a finite non-negative number");
    }
    double r = std::nearbyint(v);
    if (r >= std::ldexp(1.0, width)) {
        throw std::out_of_range(std::string(what) + ": value " + std::to_string(r) + " at address " +
                                std::to_string(addr) + " does not fit " + std::to_string(width) + " bits");
    }
    return static_cast<uint32_t>(r);
}
}  // namespace

void Format::validate() const {
    auto need = [](bool ok, const char* msg) {
        if (!ok) throw std::invalid_argument(msg);
    };
    need(c_w >= 2 && c_w <= 24, "c_w must be 2..24");
    need(out_w == c_w, "out_w must equal c_w (n = 0 must give C exactly)");
    need(ang_w >= 8 && ang_w <= 40, "ang_w must be 8..40");
    need(ang_frac >= 4 && ang_frac <= ang_w - 3, "ang_frac must be 4..ang_w-3 (the range must hold pi)");
    need(n_w >= 4 && n_w <= 12, "n_w must be 4..12 (decoder 10's gates need n's bit 3)");
    need(l_w >= 1 && l_w <= 24, "l_w must be 1..24");
    need(tbl_aw >= 4 && tbl_aw <= 16, "tbl_aw must be 4..16");
    need(tbl_frac >= 4 && tbl_frac <= 24, "tbl_frac must be 4..24");
    need(scale_frac >= 4 && scale_w <= 27 && scale_w > scale_frac, "scale_w/scale_frac out of range");
    need(prod_frac() > tbl_aw + 1, "ang_frac + scale_frac must exceed tbl_aw + 1");
    need(ang_w + scale_w <= 64, "ang_w + scale_w must be <= 64");
    need(ang_w % 2 == 0, "ang_w must be even (multiplier 11 splits the angle into two halves)");
    if (interp) {
        need(interp_frac >= 1 && prod_frac() >= tbl_aw + interp_frac, "interp_frac must be 1..prod_frac - tbl_aw");
        need(delta_w >= 1 && delta_w <= 20, "delta_w must be 1..20");
        need(rom12_dw() <= 40, "ROM 12 word wider than 40 bits");
    }
    need(!tables.empty() && tables.size() <= 16, "the table set must hold 1..16 tables");
    for (size_t i = 0; i < tables.size(); ++i) {
        need(tables[i] >= 1 && tables[i] <= 256 && (i == 0 || tables[i] > tables[i - 1]),
             "the table set must be strictly increasing powers k in 1..256");
    }
    if (mode == Mode::pow) {
        // the log table (ROM 9), y = n * L and the exp2 table (ROM 12) of pow mode (docs/pow.md)
        need(pow_seg_w >= 1 && pow_seg_w <= 4, "pow_seg_w must be 1..4");
        need(pow_idx_w >= 2 && pow_idx_w <= 8, "pow_idx_w must be 2..8");
        need(pow_frac >= 1 && pow_frac <= 16, "pow_frac must be 1..16");
        need(pow_val_w >= 8 && pow_val_w <= 18, "pow_val_w must be 8..18");
        need(pow_dlt_w >= 1 && pow_dlt_w <= pow_val_w, "pow_dlt_w must be 1..pow_val_w");
        need(pow_sh_w >= 1 && pow_sh_w <= 6, "pow_sh_w must be 1..6");
        need(pow_yi >= 1 && pow_yi <= 6, "pow_yi must be 1..6");
        need(pow_xb >= 0 && pow_xb <= pow_yf, "pow_xb must be 0..pow_yf");
        need(pow_yf >= tbl_aw + (interp ? interp_frac : 1) && pow_yf <= 24,
             "pow_yf must be tbl_aw + interp_frac (tbl_aw + 1 without interp) .. 24");
        need(n_w + pow_val_w + pow_yf - pow_xb <= 48, "n_w + pow_val_w + pow_yf - pow_xb must be <= 48");
        need(rom9_dw() <= 48, "ROM 9 word (the log table's) wider than 48 bits");
        need(tbl_frac >= 8, "tbl_frac must be >= 8 in pow mode");
        need(ang_frac <= 29, "ang_frac must be <= 29 in pow mode (pi/2 in the angle format below 2^31)");
        need(ang_frac - 1 - pow_idx_w - ((1 << pow_seg_w) - 2) >= 0 && ang_frac - 1 - pow_idx_w - pow_frac >= 0,
             "ang_frac too small for the log table (ang_frac - 1 - pow_idx_w - max(pow_frac, 2^pow_seg_w - 2) < 0)");
        return;
    }
    need(rom9_dw() <= 32, "ROM 9 word (scale and table index) wider than 32 bits");
    // The largest scale must fit: sqrt((2^n_w - 1) / k_max) * 2/pi < 2^(scale_w - scale_frac) (for the
    // patent's tables k_max = 16; a table set that serves large n from a small k can still fail in make_rom9).
    double smax = std::sqrt(((1 << n_w) - 1) / double(tables.back())) * 2.0 / kPi;
    need(smax < std::ldexp(1.0, scale_w - scale_frac), "scale_w - scale_frac too small for the largest n");
}

long long Format::pow_half_pi() const { return std::llround(std::ldexp(kPi / 2.0, ang_frac)); }

double rom9_exact(const Format& f, unsigned n) {
    if (f.pow()) throw std::invalid_argument("rom9_exact: pow mode's ROM 9 holds no scale");
    return table_fits(f).at(n).scale * 2.0 / kPi;
}

std::vector<uint32_t> make_rom9(const Format& f) {
    f.validate();
    if (f.pow()) throw std::invalid_argument("make_rom9: pow mode's ROM 9 is the log table (make_pow_log)");
    const std::vector<TableFit>& fits = table_fits(f);
    std::vector<uint32_t> rom(size_t(1) << f.n_w);
    for (size_t n = 0; n < rom.size(); ++n) {
        rom[n] = checked_round(std::ldexp(fits[n].scale * 2.0 / kPi, f.scale_frac), f.scale_w, "ROM 9", n);
        if (f.decoder_rom()) rom[n] |= uint32_t(fits[n].table) << f.scale_w;   // decoder 10 as a ROM field
    }
    return rom;
}

std::vector<uint64_t> make_rom12(const Format& f) {
    f.validate();
    if (f.pow()) return make_pow_exp(f);
    const size_t per = size_t(1) << f.tbl_aw;
    const int ntab = 1 << f.tsel_w();   // the tables of f.tables, then zero tables (never addressed)
    std::vector<uint64_t> rom(size_t(ntab) * per);
    for (int t = 0; t < ntab; ++t) {
        std::vector<uint32_t> v(per + 1, 0);  // v[per] = cos^k(pi/2) = 0
        for (size_t i = 0; t < int(f.tables.size()) && i < per; ++i) {
            double x = static_cast<double>(i) * (kPi / 2.0) / static_cast<double>(per);
            v[i] = checked_round(std::ldexp(std::pow(std::cos(x), f.tables[t]), f.tbl_frac), f.tbl_dw(), "ROM 12",
                                 t * per + i);
        }
        for (size_t i = 0; i < per; ++i) {
            uint64_t word = v[i];
            if (f.interp) {
                if (v[i + 1] > v[i]) throw std::out_of_range("ROM 12: table " + std::to_string(t) + " rises at " +
                                                             std::to_string(i));
                const uint64_t delta = v[i] - v[i + 1];
                if (delta >= (uint64_t(1) << f.delta_w)) {
                    throw std::out_of_range("ROM 12: delta " + std::to_string(delta) + " at address " +
                                            std::to_string(t * per + i) + " does not fit delta_w = " +
                                            std::to_string(f.delta_w) + " bits");
                }
                word |= delta << f.tbl_dw();
            }
            rom[t * per + i] = word;
        }
    }
    return rom;
}

std::string hex_image(const std::vector<uint64_t>& words, int width, const std::string& what,
                      const std::string& header) {
    const int digits = (width + 3) / 4;
    std::string out;
    out.reserve(header.size() + 1 + words.size() * (digits + 1));
    if (!header.empty()) out += header + "\n";
    char buf[24];
    for (size_t a = 0; a < words.size(); ++a) {
        if (width < 64 && (words[a] >> width) != 0) {
            throw std::out_of_range(what + ": word at address " + std::to_string(a) + " exceeds " +
                                    std::to_string(width) + " bits");
        }
        std::snprintf(buf, sizeof buf, "%0*llx\n", digits, static_cast<unsigned long long>(words[a]));
        out += buf;
    }
    return out;
}

namespace {
std::string tables_text(const Format& f) {
    std::string t;
    for (size_t i = 0; i < f.tables.size(); ++i) t += (i ? "," : "") + std::to_string(f.tables[i]);
    return t;
}
}  // namespace

// The parameters each image depends on, in the order rtl/spec_rom9.v and rtl/spec_rom12.v read them back
// ($sscanf at time 0: a simulation whose parameters differ stops with a message naming the file and the field).
std::string rom9_header(const Format& f) {
    if (f.pow()) {
        return "// specrom ROM 9 pow: ang_frac=" + std::to_string(f.ang_frac) + " half_pi=" +
               std::to_string(f.pow_half_pi()) + " seg_w=" + std::to_string(f.pow_seg_w) + " idx_w=" +
               std::to_string(f.pow_idx_w) + " val_w=" + std::to_string(f.pow_val_w) + " dlt_w=" +
               std::to_string(f.pow_dlt_w) + " sh_w=" + std::to_string(f.pow_sh_w) + " xb=" + std::to_string(f.pow_xb) +
               " words=" + std::to_string(1 << f.rom9_aw()) + " width=" + std::to_string(f.rom9_dw()) +
               " mode=pow log2cos";
    }
    return "// specrom ROM 9: n_w=" + std::to_string(f.n_w) + " scale_w=" + std::to_string(f.scale_w) +
           " scale_frac=" + std::to_string(f.scale_frac) + " decoder_rom=" + std::to_string(f.decoder_rom() ? 1 : 0) +
           " tsel_w=" + std::to_string(f.decoder_rom() ? f.tsel_w() : 2) + " words=" + std::to_string(1 << f.n_w) +
           " width=" + std::to_string(f.rom9_dw()) + " mode=" + mode_name(f.mode) + " tables=" + tables_text(f);
}

std::string rom12_header(const Format& f) {
    if (f.pow()) {
        return "// specrom ROM 12 pow: tbl_aw=" + std::to_string(f.tbl_aw) + " tbl_frac=" + std::to_string(f.tbl_frac) +
               " interp=" + std::to_string(f.interp ? 1 : 0) + " delta_w=" + std::to_string(f.interp ? f.delta_w : 0) +
               " words=" + std::to_string(1 << f.rom12_aw()) + " width=" + std::to_string(f.rom12_dw()) +
               " mode=pow exp2";
    }
    return "// specrom ROM 12: tbl_aw=" + std::to_string(f.tbl_aw) + " tsel_w=" + std::to_string(f.tsel_w()) +
           " tbl_frac=" + std::to_string(f.tbl_frac) + " interp=" + std::to_string(f.interp ? 1 : 0) +
           " delta_w=" + std::to_string(f.interp ? f.delta_w : 0) + " words=" + std::to_string(1 << f.rom12_aw()) +
           " width=" + std::to_string(f.rom12_dw()) + " tables=" + tables_text(f);
}

namespace {
struct Param {
    std::string name;
    long long value;
    std::string doc;
};

// Everything that describes a configuration: the cores' parameters, spec_stream's descriptor layout and the
// latencies. Both headers list the same entries (SPEC_<name> in Verilog, spec_params::<name> in C++).
std::vector<Param> params(const Format& f) {
    const Format::DescLayout d = f.desc();
    return {
        {"C_W", f.c_w, "register 1: C, UQ0.C_W"},
        {"ANG_W", f.ang_w, "registers 2, 3, 8: angle, two's complement radians"},
        {"ANG_FRAC", f.ang_frac, "fraction bits of the angle"},
        {"N_W", f.n_w, "register 4: exponent n"},
        {"L_W", f.l_w, "counter 5: intervals l"},
        {"OUT_W", f.out_w, "output 27: intensity, UQ0.OUT_W"},
        {"SCALE_W", f.scale_w, "ROM 9 word: the scale of multiplier 11 times 2/pi, unsigned"},
        {"SCALE_FRAC", f.scale_frac, "fraction bits of the ROM 9 word"},
        {"TBL_AW", f.tbl_aw, "ROM 12: positions per table = 2^TBL_AW over [0, pi/2)"},
        {"TBL_FRAC", f.tbl_frac, "ROM 12 word: UQ1.TBL_FRAC, TBL_FRAC+1 bits"},
        {"INTERP", f.interp ? 1 : 0, "1: ROM 12 words carry the step to the next position, interpolated"},
        {"INTERP_FRAC", f.interp_frac, "fraction bits of the position used by the interpolation"},
        {"DELTA_W", f.delta_w, "width of the step field (with INTERP = 1)"},
        {"DECODER_ROM", f.decoder_rom() ? 1 : 0,
         f.decoder_rom() ? std::string(mode_name(f.mode)) + " mode / table set " + tables_text(f) +
                               ": ROM 9's top TSEL_W bits are the table (decoder 10 as a ROM)"
                         : "0: decoder 10's gates (Fig. 10) choose the table"},
        {"TSEL_W", f.decoder_rom() ? f.tsel_w() : 2, "ROM 12 table index width"},
        {"POW", f.pow() ? 1 : 0,
         f.pow() ? "pow mode: ROM 9 the log table, multiplier 11 by n, ROM 12 exp2 (docs/pow.md)"
                 : "0: ROM 9 the scale, ROM 12 the cos^k tables (patent and tuned mode)"},
        {"POW_SEG_W", f.pow_seg_w, "pow mode: 2^POW_SEG_W segments of the log table per side"},
        {"POW_IDX_W", f.pow_idx_w, "pow mode: 2^POW_IDX_W entries per segment"},
        {"POW_FRAC", f.pow_frac, "pow mode: fraction bits of the log table's interpolation"},
        {"POW_VAL_W", f.pow_val_w, "pow mode: the log table's value field"},
        {"POW_DLT_W", f.pow_dlt_w, "pow mode: the log table's step field (magnitude; a sign bit above it)"},
        {"POW_SH_W", f.pow_sh_w, "pow mode: the log table's shift field: L = value * 2^-(POW_XB + shift)"},
        {"POW_XB", f.pow_xb, "pow mode: the shift field's base"},
        {"POW_YF", f.pow_yf, "pow mode: fraction bits of y = n * L"},
        {"POW_YI", f.pow_yi, "pow mode: integer bits of y (y >= 2^POW_YI gives 0)"},
        {"POW_K", f.pow_half_pi(), "pow mode: pi/2 in the angle format, round(pi/2 * 2^ANG_FRAC)"},
        {"DESC_W", d.width, "spec_stream: descriptor width (s_axis_tdata)"},
        {"DESC_C_LSB", d.c_lsb, "spec_stream descriptor: C at [DESC_C_LSB +: C_W]"},
        {"DESC_N_LSB", d.n_lsb, "spec_stream descriptor: n at [DESC_N_LSB +: N_W]"},
        {"DESC_L_LSB", d.l_lsb, "spec_stream descriptor: l at [DESC_L_LSB +: L_W]"},
        {"DESC_ZETA0_LSB", d.zeta0_lsb, "spec_stream descriptor: zeta0 at [DESC_ZETA0_LSB +: ANG_W]"},
        {"DESC_DZETA_LSB", d.dzeta_lsb, "spec_stream descriptor: dzeta at [DESC_DZETA_LSB +: ANG_W]"},
        {"DATAPATH_LATENCY", f.datapath_latency(), "spec_datapath: register 8 to output 27, clocks"},
        {"UNIT_FIRST_PIXEL", f.unit_first_pixel(), "spec_unit: pixel i valid in cycle t + this + 2i after Start in t"},
        {"STREAM_LATENCY", f.stream_latency(), "spec_stream: descriptor accepted in a -> first pixel in a + this"},
        {"STREAM_ACC", f.stream_acc(), "spec_stream: stages of the pipelined accumulator (register 8)"},
        {"STREAM_SEQ_LATENCY", f.stream_seq_latency(),
         "spec_stream_seq: descriptor accepted in a -> first pixel in a + this (and the clocks between spans)"},
    };
}

// A name for the configuration that the Verilog header defines as a macro, so that including two headers of
// different configurations in one compilation is an error instead of the first one silently winning.
std::string config_tag(const std::string& body) {
    uint32_t h = 2166136261u;  // FNV-1a of the parameter lines
    for (unsigned char ch : body) h = (h ^ ch) * 16777619u;
    char buf[16];
    std::snprintf(buf, sizeof buf, "%08x", h);
    return buf;
}
}  // namespace

std::string verilog_header(const Format& f, const std::string& rom_dir) {
    std::ostringstream body;
    for (const auto& p : params(f)) {
        body << "`define SPEC_" << p.name << " " << p.value << "  // " << p.doc << "\n";
    }
    const std::string tag = config_tag(body.str());
    std::ostringstream o;
    o << "// spec_params.vh - generated by specrom from rom/gen/spec_format.h; do not edit.\n"
      << "// Default parameters of spec_unit and spec_stream, the descriptor layout and the latencies of this\n"
      << "// configuration; the ROM images beside this file are made for them (the cores check at time 0).\n"
      << "`ifdef SPEC_PARAMS_VH\n"
      << "`ifndef SPEC_PARAMS_" << tag << "\n"
      << "// Two spec_params.vh of different configurations in one compilation: the first one's macros would win\n"
      << "// silently. Put one configuration's directory on the include path; pass other configurations' values\n"
      << "// as parameters of the instances (docs/interface.md, \"Configurations\").\n"
      << "`include \"ERROR_two_spec_params_vh_of_different_configurations_in_one_compilation\"\n"
      << "`endif\n"
      << "`else\n"
      << "`define SPEC_PARAMS_VH\n"
      << "`define SPEC_PARAMS_" << tag << "\n"
      << body.str()
      << "`define SPEC_ROM9_FILE \"" << rom_dir << "rom9_scale.hex\"\n"
      << "`define SPEC_ROM12_FILE \"" << rom_dir << "rom12_cosk.hex\"\n"
      << "`endif\n";
    return o.str();
}

std::string cpp_header(const Format& f) {
    std::ostringstream o;
    o << "// spec_params.h - generated by specrom from rom/gen/spec_format.h; do not edit.\n"
      << "// The widths and scales the ROM images beside this file were made for, the descriptor layout and latencies.\n"
      << "#pragma once\n\nnamespace spec_params {\n";
    for (const auto& p : params(f)) {
        o << "constexpr int " << p.name << " = " << p.value << ";  // " << p.doc << "\n";
    }
    o << "constexpr int TBL_DW = " << f.tbl_dw() << ";\n"
      << "constexpr int ROM9_DEPTH = " << (1 << f.n_w) << ";\n"
      << "constexpr int ROM12_DEPTH = " << (1 << f.rom12_aw()) << ";\n"
      << "constexpr int TABLE_K[" << f.tables.size() << "] = {" << tables_text(f) << "};\n"
      << "}  // namespace spec_params\n";
    return o.str();
}

namespace {
void write_file(const std::string& path, const std::string& text) {
    const std::string tmp = path + ".tmp";
    {
        std::ofstream os(tmp, std::ios::binary | std::ios::trunc);
        if (!os) throw std::runtime_error("cannot write " + tmp);
        os << text;
        os.close();
        if (!os) {
            std::remove(tmp.c_str());
            throw std::runtime_error("cannot write " + tmp);
        }
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        std::remove(tmp.c_str());
        throw std::runtime_error("cannot rename " + tmp + " to " + path);
    }
}
}  // namespace

void write_all(const Format& f, const std::string& dir, const std::string& rom_dir) {
    f.validate();
    // Build everything first: a range error leaves no file written.
    std::vector<uint64_t> r9w;
    if (f.pow()) {
        r9w = make_pow_log(f);
    } else {
        const auto w = make_rom9(f);
        r9w.assign(w.begin(), w.end());
    }
    const std::string r9 = hex_image(r9w, f.rom9_dw(), "ROM 9", rom9_header(f));
    const std::string r12 = hex_image(make_rom12(f), f.rom12_dw(), "ROM 12", rom12_header(f));
    const std::string vh = verilog_header(f, rom_dir);
    const std::string h = cpp_header(f);
    write_file(dir + "/rom9_scale.hex", r9);
    write_file(dir + "/rom12_cosk.hex", r12);
    write_file(dir + "/spec_params.vh", vh);
    write_file(dir + "/spec_params.h", h);
}

}  // namespace spec
