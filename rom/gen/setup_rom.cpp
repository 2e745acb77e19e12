#include "setup_rom.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>

namespace spec {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

SetupBuild::SetupBuild(const SetupFormat& f)
    : sf(f), prog(build_setup_program(f)), tab(make_setup_tables(f)), sched(setup_schedule(f, prog)),
      lay(setup_ucode_layout(f, sched)), ucode(setup_ucode(f, prog, sched, lay)) {}

namespace {

// A packed constant: field i (width bits each) in bits [i*width +: width], as a sized Verilog literal.
std::string packed(const std::vector<uint64_t>& v, int width) {
    const int bits = std::max(1, static_cast<int>(v.size()) * width);
    std::vector<int> b(static_cast<size_t>(bits), 0);
    for (size_t i = 0; i < v.size(); ++i)
        for (int k = 0; k < width; ++k) b[i * width + k] = static_cast<int>((v[i] >> k) & 1);
    std::string hex;
    for (int d = (bits + 3) / 4 - 1; d >= 0; --d) {
        int x = 0;
        for (int k = 3; k >= 0; --k) x = 2 * x + (4 * d + k < bits ? b[static_cast<size_t>(4 * d + k)] : 0);
        hex += "0123456789abcdef"[x];
    }
    return std::to_string(bits) + "'h" + hex;
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

std::string words_image(const std::vector<uint64_t>& words, int width, const std::string& header) {
    const int digits = (width + 3) / 4;
    std::string out = header;
    char buf[24];
    for (size_t a = 0; a < words.size(); ++a) {
        if (width < 64 && (words[a] >> width) != 0) throw std::logic_error("setuprom: a table word exceeds its width");
        std::snprintf(buf, sizeof buf, "%0*llx\n", digits, static_cast<unsigned long long>(words[a]));
        out += buf;
    }
    return out;
}

struct Def {
    std::string name, value, doc;
};
// values past 31 bits as sized literals (a plain Verilog number is 32-bit signed)
Def def(const std::string& n, long long v, const std::string& doc, int width = 40) {
    return {n, (v >= (1LL << 31) ? std::to_string(width) + "'d" : "") + std::to_string(v), doc};
}

std::vector<Def> defs(const SetupBuild& b, const std::string& rom_dir) {
    const SetupFormat& sf = b.sf;
    const SetupSchedule& s = b.sched;
    const SetupUcodeLayout& l = b.lay;
    const SetupLatency L = setup_latency(sf);
    const FpFmt& f = sf.fp;
    std::vector<Def> d = {
        {"CONFIG", "\"" + sf.name + "\"", "the configuration these files were made for (setuprom --config)"},
        def("VEC_W", sf.vec_w, "end vector components, two's complement"),
        def("VEC_FRAC", sf.vec_frac, "fraction bits of a component"),
        def("STR_W", sf.str_w, "strength Is*ks, unsigned"),
        def("STR_FRAC", sf.str_frac, "fraction bits of the strength"),
        def("BEAT_W", 256, "spec_setup / spec_shader: span-ends beat width (s_axis_tdata)"),
        def("BEAT_VEC_LSB", 0, "span ends: N1, N2, H1, H2 (x, y, z each) at [BEAT_VEC_LSB + 16 * k +: VEC_W]"),
        def("BEAT_STR_LSB", 192, "span ends: Is*ks at [BEAT_STR_LSB +: STR_W]"),
        def("BEAT_N_LSB", 208, "span ends: n at [BEAT_N_LSB +: N_W]"),
        def("BEAT_L_LSB", 224, "span ends: l at [BEAT_L_LSB +: L_W]"),
        def("BEAT_RULE_BIT", 240, "span ends: gamma rule (1: midpoint)"),
        def("FLAGS_W", 7, "spec_setup / spec_shader: flags on tuser"),
        def("FM", f.m, "floating point: mantissa bits, the leading one included"),
        def("FE", f.e, "floating point: exponent bits"),
        def("FG", f.g, "floating point: the adder's guard bits"),
        def("W", f.w(), "a word: {sign, exponent, mantissa}"),
        def("TAB_T", sf.tab_t, "EFU tables: 2^TAB_T intervals"),
        def("TAB_R", sf.tab_r, "EFU tables: interpolation fraction bits"),
        def("TAB_F", sf.tab_f, "EFU tables: fraction bits of a word"),
        def("ZF", sf.zf, "finish: fraction bits of the angles before rounding"),
        def("LF", sf.lf, "finish: fraction bits of p = -log2 C"),
        def("EXP_T", sf.exp_t, "finish: exp2 table, 2^EXP_T intervals"),
        def("EXP_R", sf.exp_r, "finish: exp2 interpolation fraction bits"),
        def("EXP_F", sf.exp_f, "finish: fraction bits of an exp2 word"),
        {"FLAT_WORD", std::to_string(f.w()) + "'h" + [&] {
             char buf[24];
             std::snprintf(buf, sizeof buf, "%llx", static_cast<unsigned long long>(fp_word(f, fp_from_double(f, std::ldexp(1.0, sf.flat_log2)))));
             return std::string(buf);
         }(), "finish: 2^FLAT_LOG2, the patent's gamma below it is flat"},
        {"OPP_WORD", std::to_string(f.w()) + "'h" + [&] {
             char buf[24];
             std::snprintf(buf, sizeof buf, "%llx", static_cast<unsigned long long>(fp_word(f, fp_from_double(f, sf.opp_eps))));
             return std::string(buf);
         }(), "finish: 1 + N1.N2 below it: opposite normals"},
        def("PI_Z", std::llround(std::ldexp(kPi, sf.zf)), "finish: round(pi * 2^ZF)"),
        def("TWO_PI_Z", std::llround(std::ldexp(2 * kPi, sf.zf)), "finish: round(2 pi * 2^ZF)"),
        def("HALF_PI_Z", std::llround(std::ldexp(kPi / 2, sf.zf)), "finish: round(pi/2 * 2^ZF)"),
        def("LAT_IDOT", L.lat[static_cast<int>(SetupUnit::IDOT)], "clocks from issue to result: IDOT"),
        def("LAT_MUL", L.lat[static_cast<int>(SetupUnit::MUL)], "clocks from issue to result: MUL"),
        def("LAT_ADD", L.lat[static_cast<int>(SetupUnit::ADD)], "clocks from issue to result: ADD"),
        def("LAT_EFU", L.lat[static_cast<int>(SetupUnit::EFU)], "clocks from issue to result: EFU"),
        def("LAT_MISC", L.lat[static_cast<int>(SetupUnit::MISC)], "clocks from issue to result: MISC"),
        def("II", s.ii, "clocks a span: a new span every II clocks"),
        def("LMAX_LOG2", s.lmax_log2, "a bank address is {slot, (S - stage) mod 2^LMAX_LOG2}"),
        def("LIN", kSetupLin, "beats in the IDOT unit's buffer"),
        def("LATENCY", s.latency, "clocks from a span's start to its descriptor"),
        def("NU", s.units, "units (the OUT pseudo-unit, the finish's reads, is unit NU)"),
        def("N_BANK", static_cast<long long>(s.banks.size()), "banks (one per unit input port; the last: OUT)"),
        def("UC_W", l.w, "microcode word width"),
        def("OP_W", l.op_w, "microcode: op field"),
        def("SCALE_W", l.scale_w, "microcode: result scale (two's complement)"),
        def("ADDR_W", l.addr_w, "microcode: a bank slot"),
        def("STAGE_W", l.stage_w, "microcode: a stage; the span counter's width"),
        def("CSEL_W", l.csel_w, "microcode: 0 = the bank, k = the port's constant k - 1"),
        def("WSRC_W", l.wsrc_w, "microcode: a bank's write source (index into its source list)"),
    };
    // packed tables
    const int U = s.units + 1;
    std::vector<uint64_t> ty(static_cast<size_t>(U)), pb(static_cast<size_t>(U) * 3), uop(static_cast<size_t>(U)),
        usc(static_cast<size_t>(U)), ust(static_cast<size_t>(U)), ugo(static_cast<size_t>(U));
    std::vector<uint64_t> pad(static_cast<size_t>(U) * 3), pst(pad), pcs(pad), png(pad), pab(pad);
    for (int u = 0; u < U; ++u) {
        ty[u] = u < s.units ? static_cast<uint64_t>(s.unit[static_cast<size_t>(u)].type) : 5;
        ugo[u] = static_cast<uint64_t>(l.go[u]);
        uop[u] = static_cast<uint64_t>(l.op[u]);
        usc[u] = static_cast<uint64_t>(l.scale[u]);
        ust[u] = static_cast<uint64_t>(l.stage[u][0]);
        for (int j = 0; j < 3; ++j) {
            const int bk = s.bank_of[static_cast<size_t>(u) * 3 + j];
            const size_t k = static_cast<size_t>(u) * 3 + j;
            pb[k] = bk < 0 ? 255 : static_cast<uint64_t>(bk);
            pad[k] = static_cast<uint64_t>(l.addr[u][j]);
            pst[k] = static_cast<uint64_t>(l.stage[u][j]);
            pcs[k] = static_cast<uint64_t>(l.csel[u][j]);
            png[k] = static_cast<uint64_t>(l.neg[u][j]);
            pab[k] = static_cast<uint64_t>(l.absb[u][j]);
        }
    }
    size_t maxsrc = 1, maxc = 1;
    for (const SetupBank& bk : s.banks) {
        maxsrc = std::max(maxsrc, bk.sources.size());
        maxc = std::max(maxc, bk.consts.size());
    }
    const size_t B = s.banks.size();
    std::vector<uint64_t> bu(B), bp(B), baw(B), bns(B), bsrc(B * maxsrc, 0), bnc(B), bcon(B * maxc, 0), bpred(B);
    std::vector<uint64_t> we(B), ws(B), wa(B), wst(B);
    for (size_t k = 0; k < B; ++k) {
        const SetupBank& bk = s.banks[k];
        bu[k] = static_cast<uint64_t>(bk.unit);
        bp[k] = static_cast<uint64_t>(bk.port);
        int sb = 0;
        while ((1 << sb) < bk.slots) ++sb;
        baw[k] = static_cast<uint64_t>(sb + s.lmax_log2);
        bns[k] = bk.sources.size();
        for (size_t i = 0; i < bk.sources.size(); ++i) bsrc[k * maxsrc + i] = static_cast<uint64_t>(bk.sources[i]);
        bnc[k] = bk.consts.size();
        for (size_t i = 0; i < bk.consts.size(); ++i) bcon[k * maxc + i] = fp_word(f, bk.consts[i]);
        bpred[k] = bk.port == 2 && bk.unit != s.out_unit;
        we[k] = static_cast<uint64_t>(l.we[k]);
        ws[k] = static_cast<uint64_t>(l.wsrc[k]);
        wa[k] = static_cast<uint64_t>(l.waddr[k]);
        wst[k] = static_cast<uint64_t>(l.wstage[k]);
    }
    std::vector<uint64_t> ends = {static_cast<uint64_t>(b.tab.rsqrt_lo.w[size_t(1) << sf.tab_t]),
                                  static_cast<uint64_t>(b.tab.rsqrt_hi.w[size_t(1) << sf.tab_t]),
                                  static_cast<uint64_t>(b.tab.rcp.w[size_t(1) << sf.tab_t]),
                                  static_cast<uint64_t>(b.tab.atang.w[size_t(1) << sf.tab_t]),
                                  static_cast<uint64_t>(b.tab.log2.w[size_t(1) << sf.tab_t])};
    auto add = [&](const std::string& n, const std::vector<uint64_t>& v, int w, const std::string& doc) {
        d.push_back({n, packed(v, w), doc});
    };
    d.push_back(def("MAXSRC", static_cast<long long>(maxsrc), "the most write sources a bank has"));
    d.push_back(def("MAXC", static_cast<long long>(maxc), "the most constants a port has"));
    add("UNIT_TYPE", ty, 3, "per unit (3 bits): 0 IDOT, 1 MUL, 2 ADD, 3 EFU, 4 MISC, 5 OUT");
    add("PORT_BANK", pb, 8, "per unit port (unit * 3 + port, 8 bits): its bank, 255 none");
    add("BANK_UNIT", bu, 8, "per bank (8 bits): the unit it feeds");
    add("BANK_PORT", bp, 2, "per bank (2 bits): the port it feeds");
    add("BANK_AW", baw, 8, "per bank (8 bits): RAM address width");
    add("BANK_PRED", bpred, 1, "per bank: 1 = a condition bank (one bit: the value is not zero)");
    add("BANK_NSRC", bns, 8, "per bank (8 bits): number of write sources");
    add("BANK_SRC", bsrc, 8, "per bank, MAXSRC entries (8 bits): the write sources' unit indices");
    add("BANK_NCONST", bnc, 8, "per bank (8 bits): number of constants of its port");
    add("BANK_CONST", bcon, f.w(), "per bank, MAXC words: the port's constants");
    add("UC_GO", ugo, 16, "per unit (16 bits): microcode offset of the issue bit");
    add("UC_OP", uop, 16, "per unit: offset of the op field");
    add("UC_SCALE", usc, 16, "per unit: offset of the result scale");
    add("UC_ISTAGE", ust, 16, "per unit: offset of the stage of the beat an IDOT operation reads");
    add("UC_ADDR", pad, 16, "per unit port: offset of the read slot");
    add("UC_STAGE", pst, 16, "per unit port: offset of the read stage");
    add("UC_CSEL", pcs, 16, "per unit port: offset of the constant select");
    add("UC_NEG", png, 16, "per unit port: offset of the negate bit");
    add("UC_ABS", pab, 16, "per unit port: offset of the magnitude bit");
    add("UC_WE", we, 16, "per bank: offset of the write enable");
    add("UC_WSRC", ws, 16, "per bank: offset of the write source");
    add("UC_WADDR", wa, 16, "per bank: offset of the write slot");
    add("UC_WSTAGE", wst, 16, "per bank: offset of the write stage");
    add("EFU_END", ends, sf.tab_f + 1, "the EFU tables' words at the end of the interval (index 2^TAB_T)");
    d.push_back(def("EXP2_END", static_cast<long long>(b.tab.exp2.w[size_t(1) << sf.exp_t]), "exp2 table: the word at 1"));
    d.push_back({"EFU_FILE", "\"" + rom_dir + "/setup_efu.hex\"", "the EFU tables"});
    d.push_back({"EXP2_FILE", "\"" + rom_dir + "/setup_exp2.hex\"", "the finish's exp2 table"});
    d.push_back({"UC_FILE", "\"" + rom_dir + "/setup_ucode.hex\"", "the microcode"});
    return d;
}

}  // namespace

std::string setup_verilog_header(const SetupBuild& b, const std::string& rom_dir) {
    std::ostringstream o;
    o << "// setup_params.vh - generated by setuprom from rom/gen/setup_format.h (configuration " << b.sf.name
      << "); do not edit.\n"
      << "// spec_setup's number format, tables and schedule; setup_efu.hex, setup_exp2.hex and setup_ucode.hex beside\n"
      << "// this file are made for them.\n"
      << "`ifndef SETUP_PARAMS_VH\n`define SETUP_PARAMS_VH\n";
    for (const Def& d : defs(b, rom_dir)) o << "`define SETUP_" << d.name << " " << d.value << "  // " << d.doc << "\n";
    o << "`endif\n";
    return o.str();
}

std::string setup_cpp_header(const SetupBuild& b) {
    const SetupFormat& sf = b.sf;
    std::ostringstream o;
    o << "// setup_params.h - generated by setuprom from rom/gen/setup_format.h (configuration " << sf.name
      << "); do not edit.\n"
      << "#pragma once\n\nnamespace setup_params {\n"
      << "constexpr const char* CONFIG = \"" << sf.name << "\";  // the configuration\n"
      << "constexpr long long VEC_W = " << sf.vec_w << ";  // end vector components, two's complement\n"
      << "constexpr long long VEC_FRAC = " << sf.vec_frac << ";  // fraction bits of a component\n"
      << "constexpr long long STR_W = " << sf.str_w << ";  // strength Is*ks, unsigned\n"
      << "constexpr long long STR_FRAC = " << sf.str_frac << ";  // fraction bits of the strength\n"
      << "constexpr long long BEAT_W = 256;  // the span-ends beat width\n"
      << "constexpr long long BEAT_VEC_LSB = 0;  // N1, N2, H1, H2 (x, y, z each) at [BEAT_VEC_LSB + 16 * k +: VEC_W]\n"
      << "constexpr long long BEAT_STR_LSB = 192;  // Is*ks\n"
      << "constexpr long long BEAT_N_LSB = 208;  // n\n"
      << "constexpr long long BEAT_L_LSB = 224;  // l\n"
      << "constexpr long long BEAT_RULE_BIT = 240;  // gamma rule (1: midpoint)\n"
      << "constexpr long long FLAGS_W = 7;  // flags on tuser\n"
      << "constexpr long long II = " << b.sched.ii << ";  // clocks a span\n"
      << "constexpr long long LATENCY = " << b.sched.latency << ";  // clocks from a span's start to its descriptor\n"
      << "constexpr long long FP_M = " << sf.fp.m << ";  // mantissa bits, the leading one included\n"
      << "constexpr long long FP_E = " << sf.fp.e << ";  // exponent bits\n"
      << "constexpr long long TAB_T = " << sf.tab_t << ";  // the EFU's tables: 2^TAB_T intervals\n"
      << "constexpr long long EXP_T = " << sf.exp_t << ";  // the finish stage's exp2 table: 2^EXP_T intervals\n";
    const char* names[kSetupUnitTypes] = {"IDOT", "MUL", "ADD", "EFU", "MISC"};
    const int units[kSetupUnitTypes] = {sf.mach.idot, sf.mach.mul, sf.mach.add, sf.mach.efu, sf.mach.misc};
    for (int t = 0; t < kSetupUnitTypes; ++t) {
        o << "constexpr long long UNITS_" << names[t] << " = " << units[t] << ";  // units of this kind\n"
          << "constexpr long long OPS_" << names[t] << " = " << b.prog.count(static_cast<SetupUnit>(t))
          << ";  // the program's operations on them, a span\n";
    }
    o << "constexpr long long BANKS = " << b.sched.banks.size() << ";  // operand banks (one per unit input and the finish's)\n"
      << "}  // namespace setup_params\n";
    return o.str();
}

std::string setup_efu_image(const SetupBuild& b) {
    const int t = b.sf.tab_t;
    const SetupTable* tabs[5] = {&b.tab.rsqrt_lo, &b.tab.rsqrt_hi, &b.tab.rcp, &b.tab.atang, &b.tab.log2};
    std::vector<uint64_t> w;   // address table * 2^TAB_T + index: rsqrt [1,2), rsqrt [2,4), rcp, atan(x)/x, log2
    for (int k = 0; k < 5; ++k)
        for (int i = 0; i < (1 << t); ++i) w.push_back(static_cast<uint64_t>(tabs[k]->w[static_cast<size_t>(i)]));
    return words_image(w, b.sf.tab_f + 1, "");
}

std::string setup_exp2_image(const SetupBuild& b) {
    std::vector<uint64_t> w;
    for (int i = 0; i < (1 << b.sf.exp_t); ++i) w.push_back(static_cast<uint64_t>(b.tab.exp2.w[static_cast<size_t>(i)]));
    return words_image(w, b.sf.exp_f + 1, "");
}

std::string setup_ucode_image(const SetupBuild& b) {
    const int w = b.lay.w, digits = (w + 3) / 4;
    std::string out;
    for (const auto& word : b.ucode) {
        std::string line;
        for (int d = digits - 1; d >= 0; --d) {
            int x = 0;
            for (int k = 3; k >= 0; --k) {
                const int pos = 4 * d + k;
                x = 2 * x + (pos < w ? static_cast<int>((word[static_cast<size_t>(pos / 64)] >> (pos % 64)) & 1) : 0);
            }
            line += "0123456789abcdef"[x];
        }
        out += line + "\n";
    }
    return out;
}

void write_setup_all(const SetupFormat& sf, const std::string& dir, const std::string& rom_dir) {
    sf.validate();
    const SetupBuild b(sf);
    // the schedule's self-check: spans of every kind through the microcoded machine against the program
    {
        std::mt19937_64 rng(20261203);
        std::vector<SetupBeat> beats;
        for (int i = 0; i < 256; ++i) {
            SetupBeat bt;
            for (int v = 0; v < BV_COUNT; ++v)
                for (int k = 0; k < 3; ++k) bt.v[v][k] = static_cast<int32_t>(rng() % 65536) - 32768;
            if (i % 4 == 1)
                for (int k = 0; k < 3; ++k) bt.v[BV_N2][k] = -bt.v[BV_N1][k];   // exactly opposite normals
            if (i % 4 == 2)
                for (int k = 0; k < 3; ++k) bt.v[BV_H2][k] = bt.v[BV_H1][k];
            bt.s[BS_RULE] = static_cast<int32_t>(rng() & 1);
            bt.s[BS_STRENGTH] = static_cast<int32_t>(rng() % 65536);
            bt.s[BS_N] = static_cast<int32_t>(rng() % 1024);
            bt.s[BS_L] = static_cast<int32_t>(rng() % 65536);
            beats.push_back(bt);
        }
        SetupMachineSim sim(sf, b.prog, b.tab, b.sched);
        const auto got = sim.run(beats);
        for (size_t i = 0; i < beats.size(); ++i) {
            const std::vector<Fp> v = setup_eval(sf, b.tab, b.prog, beats[i]);
            for (int o = 0; o < SO_COUNT; ++o)
                if (!(got[i][static_cast<size_t>(o)] == v[static_cast<size_t>(b.prog.out[o])]))
                    throw std::logic_error("setuprom: the schedule's machine differs from the program (span " +
                                           std::to_string(i) + ", " + setup_out_name(o) + ")");
        }
    }
    const std::string efu = setup_efu_image(b), ex = setup_exp2_image(b), uc = setup_ucode_image(b);
    const std::string vh = setup_verilog_header(b, rom_dir), h = setup_cpp_header(b);
    write_file(dir + "/setup_efu.hex", efu);
    write_file(dir + "/setup_exp2.hex", ex);
    write_file(dir + "/setup_ucode.hex", uc);
    write_file(dir + "/setup_params.vh", vh);
    write_file(dir + "/setup_params.h", h);
}

// ---- the up5k configuration's small CORDIC setup ---------------------------------------------------------------

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

SmallSetupConsts small_setup_consts(const SmallSetupFormat& sf) {
    sf.validate();
    SmallSetupConsts c;
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

std::vector<uint64_t> make_small_log2(const SmallSetupFormat& sf) {
    sf.validate();
    std::vector<uint64_t> t;
    const int n = 1 << sf.tb;
    for (int j = 0; j <= n; ++j) t.push_back(static_cast<uint64_t>(std::llround(std::ldexp(std::log2(1.0 + double(j) / n), sf.lf))));
    return t;
}

std::vector<uint64_t> make_small_exp2(const SmallSetupFormat& sf) {
    sf.validate();
    std::vector<uint64_t> t;
    const int n = 1 << sf.tb;
    for (int j = 0; j <= n; ++j) t.push_back(static_cast<uint64_t>(std::llround(std::ldexp(std::exp2(-double(j) / n), sf.ef))));
    return t;
}

namespace {

std::vector<Def> small_defs(const SmallSetupFormat& sf, const SmallSetupConsts& c) {
    std::vector<Def> d = {
        def("VEC_W", sf.vec_w, "end vector components, two's complement"),
        def("VEC_FRAC", sf.vec_frac, "fraction bits of a component"),
        def("STR_W", sf.str_w, "strength Is*ks, unsigned"),
        def("STR_FRAC", sf.str_frac, "fraction bits of the strength"),
        def("F", sf.f, "fraction bits of the CORDIC coordinates"),
        def("W", sf.w(), "coordinate width"),
        def("ITERS", sf.iters, "CORDIC micro-rotations per pass"),
        def("ZF", sf.zf, "fraction bits of the angle lanes"),
        def("ZW", sf.zw(), "angle lane width"),
        def("LF", sf.lf, "fraction bits of log2 values"),
        def("EF", sf.ef, "fraction bits of the exp2 table"),
        def("TB", sf.tb, "log2 and exp2 tables: 2^TB intervals"),
        def("RB", sf.rb, "interpolation fraction bits"),
        def("OPP_K", sf.opp_k, "opposite normals: tilt tangent below 1/OPP_K"),
        def("OPP_TAU", 1LL << (sf.f + sf.opp_tau_log2), "N2's projection below it after P2: exactly opposite normals"),
        def("N1_START", c.n1_start, "start length of the N1 lane, round(2^F * 4 / G^3)"),
        def("LOG2_GAIN", c.log2_gain, "round(log2(G) * 2^LF)"),
        def("HALF_PI", c.half_pi, "round(pi/2 * 2^ZF)"),
        def("PI", c.pi, "round(pi * 2^ZF)"),
        def("TWO_PI", c.two_pi, "round(2 pi * 2^ZF)", sf.zw()),
        def("FLAT_Z", c.flat_z, "gamma below 2^FLAT_LOG2 rad, in angle-lane units: the span is flat"),
        def("GAIN_N", static_cast<long long>(c.gain_terms.size()), "terms of the multiplication by G"),
        def("HALF_N", static_cast<long long>(c.half_terms.size()), "terms of the multiplication by G/2"),
    };
    return d;
}

std::string terms_fields(const std::vector<GainTerm>& t, bool signs) {
    std::vector<uint64_t> v;
    for (const GainTerm& g : t) v.push_back(signs ? (g.sign < 0 ? 1u : 0u) : static_cast<uint64_t>(g.shift & 0xff));
    return packed(v, signs ? 1 : 8);
}

}  // namespace

std::string small_verilog_header(const SmallSetupFormat& sf, const std::string& rom_dir) {
    const SmallSetupConsts c = small_setup_consts(sf);
    std::vector<uint64_t> atan;
    for (int64_t a : c.atan) atan.push_back(static_cast<uint64_t>(a));
    std::ostringstream o;
    o << "// setup_small_params.vh - generated by setuprom --config up5k from rom/gen/setup_small_format.h; do not edit.\n"
      << "// Parameters of spec_setup_small's arithmetic; setup_small_log2.hex and setup_small_exp2.hex beside this file\n"
      << "// are made for them.\n"
      << "`ifndef SETUP_SMALL_PARAMS_VH\n`define SETUP_SMALL_PARAMS_VH\n";
    for (const Def& p : small_defs(sf, c)) o << "`define SMALL_" << p.name << " " << p.value << "  // " << p.doc << "\n";
    o << "// atan(2^-i) * 2^ZF for i = 0 .. ITERS-1, ZW bits each, i = 0 in the lowest bits\n"
      << "`define SMALL_ATAN " << packed(atan, sf.zw()) << "\n"
      << "// t * G and t * G/2 as sums of sign * floor(t / 2^shift): shifts (8-bit two's complement) and signs (1 = minus)\n"
      << "`define SMALL_GAIN_SHIFT " << terms_fields(c.gain_terms, false) << "\n"
      << "`define SMALL_GAIN_NEG " << terms_fields(c.gain_terms, true) << "\n"
      << "`define SMALL_HALF_SHIFT " << terms_fields(c.half_terms, false) << "\n"
      << "`define SMALL_HALF_NEG " << terms_fields(c.half_terms, true) << "\n"
      << "`define SMALL_LOG2_FILE \"" << rom_dir << "/setup_small_log2.hex\"\n"
      << "`define SMALL_EXP2_FILE \"" << rom_dir << "/setup_small_exp2.hex\"\n"
      << "`endif\n";
    return o.str();
}

std::string small_cpp_header(const SmallSetupFormat& sf) {
    const SmallSetupConsts c = small_setup_consts(sf);
    std::ostringstream o;
    o << "// setup_small_params.h - generated by setuprom --config up5k from rom/gen/setup_small_format.h; do not edit.\n"
      << "#pragma once\n\nnamespace setup_small_params {\n";
    for (const Def& p : small_defs(sf, c)) o << "constexpr long long " << p.name << " = " << p.value << ";  // " << p.doc << "\n";
    o << "}  // namespace setup_small_params\n";
    return o.str();
}

void write_small_all(const SmallSetupFormat& sf, const std::string& dir, const std::string& rom_dir) {
    sf.validate();
    // The images hold words 0 .. 2^tb - 1; the RTL has the last word (2^lf, 2^(ef-1)) as a constant.
    const std::string hdr = "// generated by setuprom: tb=" + std::to_string(sf.tb) + " lf=" + std::to_string(sf.lf) +
                            " ef=" + std::to_string(sf.ef) + " words=" + std::to_string(1 << sf.tb) + "\n";
    std::vector<uint64_t> lw = make_small_log2(sf), ew = make_small_exp2(sf);
    lw.pop_back();
    ew.pop_back();
    const std::string lg = words_image(lw, sf.lf, hdr);
    const std::string ex = words_image(ew, sf.ef + 1, hdr);
    const std::string vh = small_verilog_header(sf, rom_dir);
    const std::string h = small_cpp_header(sf);
    write_file(dir + "/setup_small_log2.hex", lg);
    write_file(dir + "/setup_small_exp2.hex", ex);
    write_file(dir + "/setup_small_params.vh", vh);
    write_file(dir + "/setup_small_params.h", h);
}

}  // namespace spec
