#include "setup_rom.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace spec {

std::vector<GainTerm> csd_terms(double x, int frac) {
    // non-adjacent form of the integer round(x * 2^frac): digits in {-1, 0, +1}, no two neighbours non-zero
    int64_t v = std::llround(std::ldexp(x, frac));
    std::vector<GainTerm> t;
    int pos = 0;
    while (v != 0) {
        if (v & 1) {
            const int d = 2 - static_cast<int>(v & 3);   // +1 if v = 1 mod 4, -1 if v = 3 mod 4
            t.push_back({d, frac - pos});
            v -= d;
        }
        v >>= 1;
        ++pos;
    }
    return {t.rbegin(), t.rend()};   // largest term first
}

double terms_value(const std::vector<GainTerm>& terms) {
    double s = 0;
    for (const GainTerm& g : terms) s += g.sign * std::ldexp(1.0, -g.shift);
    return s;
}

SetupConsts setup_consts(const SetupFormat& sf) {
    sf.validate();
    SetupConsts c;
    c.gain = 1.0;
    for (int i = 0; i < sf.iters; ++i) c.gain *= std::sqrt(1.0 + std::ldexp(1.0, -2 * i));
    c.gain_terms = csd_terms(c.gain, sf.gain_frac);
    c.half_terms = csd_terms(c.gain / 2.0, sf.gain_frac);
    for (int i = 0; i < sf.iters; ++i) c.atan.push_back(std::llround(std::ldexp(std::atan(std::ldexp(1.0, -i)), sf.zf)));
    const double pi = 3.14159265358979323846;
    c.half_pi = std::llround(std::ldexp(pi / 2, sf.zf));
    c.pi = std::llround(std::ldexp(pi, sf.zf));
    c.two_pi = std::llround(std::ldexp(2 * pi, sf.zf));
    // The N1 lane goes through G2 and Gamma1 as a follower of halving passes (gain G/2 each) and through the
    // Lambda vectoring (gain G): it starts at 2^f * 4 / G^3 so that its final magnitude is A * 2^f.
    c.n1_start = std::llround(std::ldexp(4.0 / (c.gain * c.gain * c.gain), sf.f));
    c.log2_gain = std::llround(std::ldexp(std::log2(c.gain), sf.lf));
    c.flat_z = int64_t(1) << (sf.zf + sf.flat_log2);
    return c;
}

std::vector<uint64_t> make_setup_log2(const SetupFormat& sf) {
    sf.validate();
    std::vector<uint64_t> t;
    const int n = 1 << sf.tb;
    for (int j = 0; j <= n; ++j) t.push_back(static_cast<uint64_t>(std::llround(std::ldexp(std::log2(1.0 + double(j) / n), sf.lf))));
    return t;
}

std::vector<uint64_t> make_setup_exp2(const SetupFormat& sf) {
    sf.validate();
    std::vector<uint64_t> t;
    const int n = 1 << sf.tb;
    for (int j = 0; j <= n; ++j) t.push_back(static_cast<uint64_t>(std::llround(std::ldexp(std::exp2(-double(j) / n), sf.ef))));
    return t;
}

namespace {

struct Param {
    std::string name;
    long long value;
    std::string doc;
};

std::vector<Param> params(const SetupFormat& sf, const SetupConsts& c) {
    return {
        {"VEC_W", sf.vec_w, "end vector components, two's complement"},
        {"VEC_FRAC", sf.vec_frac, "fraction bits of a component"},
        {"STR_W", sf.str_w, "strength Is*ks, unsigned"},
        {"STR_FRAC", sf.str_frac, "fraction bits of the strength"},
        {"F", sf.f, "fraction bits of the CORDIC coordinates"},
        {"W", sf.w(), "coordinate width"},
        {"ITERS", sf.iters, "CORDIC micro-rotations per pass"},
        {"ZF", sf.zf, "fraction bits of the angle lanes"},
        {"ZW", sf.zw(), "angle lane width"},
        {"LF", sf.lf, "fraction bits of log2 values"},
        {"EF", sf.ef, "fraction bits of the exp2 table"},
        {"TB", sf.tb, "log2 and exp2 tables: 2^TB intervals"},
        {"RB", sf.rb, "interpolation fraction bits"},
        {"OPP_K", sf.opp_k, "opposite normals: tilt tangent below 1/OPP_K"},
        {"OPP_TAU", (long long)1 << (sf.f + sf.opp_tau_log2), "N2's projection below it after P2: exactly opposite normals"},
        {"N1_START", c.n1_start, "start length of the N1 lane, round(2^F * 4 / G^3)"},
        {"LOG2_GAIN", c.log2_gain, "round(log2(G) * 2^LF)"},
        {"HALF_PI", c.half_pi, "round(pi/2 * 2^ZF)"},
        {"PI", c.pi, "round(pi * 2^ZF)"},
        {"TWO_PI", c.two_pi, "round(2 pi * 2^ZF)"},
        {"FLAT_Z", c.flat_z, "gamma below 2^FLAT_LOG2 rad, in angle-lane units: the span is flat"},
        {"BEAT_W", 256, "spec_setup / spec_shader: span-ends beat width (s_axis_tdata)"},
        {"BEAT_VEC_LSB", 0, "span ends: N1, N2, H1, H2 (x, y, z each) at [BEAT_VEC_LSB + 16 * k +: VEC_W]"},
        {"BEAT_STR_LSB", 192, "span ends: Is*ks at [BEAT_STR_LSB +: STR_W]"},
        {"BEAT_N_LSB", 208, "span ends: n at [BEAT_N_LSB +: N_W]"},
        {"BEAT_L_LSB", 224, "span ends: l at [BEAT_L_LSB +: L_W]"},
        {"BEAT_RULE_BIT", 240, "span ends: gamma rule (1: midpoint)"},
        {"FLAGS_W", 7, "spec_setup / spec_shader: flags on tuser"},
        {"GAIN_N", static_cast<long long>(c.gain_terms.size()), "terms of the multiplication by G"},
        {"HALF_N", static_cast<long long>(c.half_terms.size()), "terms of the multiplication by G/2"},
    };
}

// A packed constant: field i (width bits each) in bits [i*width +: width].
std::string packed(const std::vector<int64_t>& v, int width) {
    const int bits = static_cast<int>(v.size()) * width;
    std::vector<int> b(bits, 0);
    for (size_t i = 0; i < v.size(); ++i) {
        for (int k = 0; k < width; ++k) b[i * width + k] = static_cast<int>((static_cast<uint64_t>(v[i]) >> k) & 1);
    }
    std::string hex;
    for (int d = (bits + 3) / 4 - 1; d >= 0; --d) {
        int x = 0;
        for (int k = 3; k >= 0; --k) x = 2 * x + (4 * d + k < bits ? b[4 * d + k] : 0);
        hex += "0123456789abcdef"[x];
    }
    return std::to_string(bits) + "'h" + hex;
}

std::string terms_fields(const std::vector<GainTerm>& t, bool signs) {
    std::vector<int64_t> v;
    for (const GainTerm& g : t) v.push_back(signs ? (g.sign < 0 ? 1 : 0) : g.shift);
    return packed(v, signs ? 1 : 8);
}

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

std::string table_image(const std::vector<uint64_t>& words, int width, const std::string& what,
                        const std::string& header) {
    const int digits = (width + 3) / 4;
    std::string out = header;
    char buf[24];
    for (size_t a = 0; a < words.size(); ++a) {
        if ((words[a] >> width) != 0) {
            throw std::out_of_range(what + ": word at address " + std::to_string(a) + " exceeds " + std::to_string(width) +
                                    " bits");
        }
        std::snprintf(buf, sizeof buf, "%0*llx\n", digits, static_cast<unsigned long long>(words[a]));
        out += buf;
    }
    return out;
}

}  // namespace

std::string setup_verilog_header(const SetupFormat& sf) {
    const SetupConsts c = setup_consts(sf);
    std::ostringstream o;
    o << "// setup_params.vh - generated by setuprom from rom/gen/setup_format.h; do not edit.\n"
      << "// Parameters of spec_setup's arithmetic; setup_log2.hex and setup_exp2.hex beside this file are made for them.\n"
      << "`ifndef SETUP_PARAMS_VH\n`define SETUP_PARAMS_VH\n";
    for (const Param& p : params(sf, c)) {
        // values past 31 bits as sized literals (a plain Verilog number is 32-bit signed)
        std::string v = std::to_string(p.value);
        if (p.value >= (1LL << 31)) v = std::to_string(sf.zw()) + "'d" + v;
        o << "`define SETUP_" << p.name << " " << v << "  // " << p.doc << "\n";
    }
    o << "// atan(2^-i) * 2^ZF for i = 0 .. ITERS-1, ZW bits each, i = 0 in the lowest bits\n"
      << "`define SETUP_ATAN " << packed(c.atan, sf.zw()) << "\n"
      << "// t * G and t * G/2 as sums of sign * floor(t / 2^shift): shifts (8-bit two's complement) and signs (1 = minus)\n"
      << "`define SETUP_GAIN_SHIFT " << terms_fields(c.gain_terms, false) << "\n"
      << "`define SETUP_GAIN_NEG " << terms_fields(c.gain_terms, true) << "\n"
      << "`define SETUP_HALF_SHIFT " << terms_fields(c.half_terms, false) << "\n"
      << "`define SETUP_HALF_NEG " << terms_fields(c.half_terms, true) << "\n"
      << "`define SETUP_LOG2_FILE \"rom/setup_log2.hex\"\n"
      << "`define SETUP_EXP2_FILE \"rom/setup_exp2.hex\"\n"
      << "`endif\n";
    return o.str();
}

std::string setup_cpp_header(const SetupFormat& sf) {
    const SetupConsts c = setup_consts(sf);
    std::ostringstream o;
    o << "// setup_params.h - generated by setuprom from rom/gen/setup_format.h; do not edit.\n"
      << "// The parameters the committed setup tables in rom/ were made for.\n"
      << "#pragma once\n\nnamespace setup_params {\n";
    for (const Param& p : params(sf, c)) {
        o << "constexpr long long " << p.name << " = " << p.value << ";  // " << p.doc << "\n";
    }
    o << "}  // namespace setup_params\n";
    return o.str();
}

void write_setup_all(const SetupFormat& sf, const std::string& dir) {
    sf.validate();
    // The images hold words 0 .. 2^tb - 1; the RTL has the last word (2^lf, 2^(ef-1)) as a constant.
    const std::string hdr = "// generated by setuprom: tb=" + std::to_string(sf.tb) + " lf=" + std::to_string(sf.lf) +
                            " ef=" + std::to_string(sf.ef) + " words=" + std::to_string(1 << sf.tb) + "\n";
    std::vector<uint64_t> lw = make_setup_log2(sf), ew = make_setup_exp2(sf);
    lw.pop_back();
    ew.pop_back();
    const std::string lg = table_image(lw, sf.lf, "setup log2 table", hdr);
    const std::string ex = table_image(ew, sf.ef + 1, "setup exp2 table", hdr);
    const std::string vh = setup_verilog_header(sf);
    const std::string h = setup_cpp_header(sf);
    write_file(dir + "/setup_log2.hex", lg);
    write_file(dir + "/setup_exp2.hex", ex);
    write_file(dir + "/setup_params.vh", vh);
    write_file(dir + "/setup_params.h", h);
}

}  // namespace spec
