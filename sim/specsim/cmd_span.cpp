// cmd_span.cpp - specsim span: one span through the core, printed as CSV.
#include "cmd_span.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "Vspec_stream.h"
#include "Vspec_stream_l2.h"
#include "Vspec_stream_l4.h"
#include "Vspec_stream_l4p.h"
#include "Vspec_stream_pow.h"
#include "Vspec_stream_pow_l4p.h"
#include "Vspec_stream_tuned.h"
#include "cli.h"
#include "commands.h"
#include "stream_driver.h"
#include "unit_driver.h"

namespace spec {

const char* const kSpanUsage =
    "  span     one span through the core; prints CSV 'i,value', l + 1 rows\n"
    "           --n N        exponent, 0..1023\n"
    "           --c C        intensity factor C, decimal in [0, 1)\n"
    "           --zeta0 Z    start angle in radians (the unscaled -lambda), |Z| < 8\n"
    "           --dzeta D    angle step per pixel in radians\n"
    "           --len L      number of intervals l, 0..65535 (l + 1 pixels)\n"
    "           --model M    rtl (Verilated spec_unit, default) | stream (Verilated spec_stream) |\n"
    "                        golden (bit-exact C++ model) |\n"
    "                        ref (double precision C * max(0, cos(zeta0 + i*dzeta))^n)\n"
    "           --mode M     patent (default: ROM 9 holds sqrt(n/k), Fig. 10 decoder) | tuned (minimax scale and\n"
    "                        table in ROM 9, the RTL Verilated with DECODER_ROM = 1; docs/tuned.md) | pow\n"
    "                        (exp2(n log2 cos): ROM 9 the log table, the RTL Verilated with POW = 1; docs/pow.md)\n"
    "           --lanes N    with --model stream: spec_stream with LANES = N pixels per beat (1, 2, 4 in patent\n"
    "                        mode; 1, and 4 with --pack, in pow mode); the same pixels as --model rtl\n"
    "           --pack       with --model stream --lanes 4: PACK = 1 (a beat may end one span and start the next)\n"
    "           --vcd FILE   with --model rtl: write a waveform of the run\n";

Mode parse_mode_flag(const std::string& fl, const std::string& v) {
    try {
        return parse_mode(v);
    } catch (const std::invalid_argument& e) {
        throw UsageError(fl + ": " + e.what());
    }
}

SpanOptions parse_span(int argc, char** argv) {
    const Model m;
    const Format& f = m.format();
    SpanOptions s;
    bool have_n = false, have_c = false, have_z = false, have_d = false, have_l = false;
    Args a(argc, argv, 2);
    while (!a.done()) {
        std::string fl = a.flag();
        if (fl == "--n") {
            s.regs.n = static_cast<uint32_t>(parse_int(fl, a.value(fl), 0, (1 << f.n_w) - 1));
            have_n = true;
        } else if (fl == "--c") {
            s.c = parse_double(fl, a.value(fl));
            if (s.c < 0.0 || s.c >= 1.0) throw UsageError("--c: C must be in [0, 1)");
            s.regs.c = m.quantize_c(s.c);
            have_c = true;
        } else if (fl == "--zeta0" || fl == "--dzeta") {
            double v = parse_double(fl, a.value(fl));
            int64_t q;
            try {
                q = m.quantize_angle(v);
            } catch (const std::out_of_range& e) {
                throw UsageError(fl + ": " + e.what());
            }
            if (fl == "--zeta0") { s.zeta0 = v; s.regs.zeta0 = q; have_z = true; }
            else { s.dzeta = v; s.regs.dzeta = q; have_d = true; }
        } else if (fl == "--len") {
            s.regs.len = static_cast<uint32_t>(parse_int(fl, a.value(fl), 0, (int64_t(1) << f.l_w) - 1));
            have_l = true;
        } else if (fl == "--model") {
            s.model = a.value(fl);
            if (s.model != "rtl" && s.model != "stream" && s.model != "golden" && s.model != "ref") {
                throw UsageError("--model: '" + s.model + "' is not one of rtl, stream, golden, ref");
            }
        } else if (fl == "--vcd") {
            s.vcd = a.value(fl);
        } else if (fl == "--lanes") {
            s.lanes = static_cast<int>(parse_int(fl, a.value(fl), 1, 4));
            if (s.lanes == 3) throw UsageError("--lanes: must be 1, 2 or 4");
        } else if (fl == "--pack") {
            s.pack = true;
        } else if (fl == "--mode") {
            s.mode = parse_mode_flag(fl, a.value(fl));
        } else {
            throw UsageError("span: unknown option " + fl);
        }
    }
    if (!have_n) throw UsageError("span: --n is required");
    if (!have_c) throw UsageError("span: --c is required");
    if (!have_z) throw UsageError("span: --zeta0 is required");
    if (!have_d) throw UsageError("span: --dzeta is required");
    if (!have_l) throw UsageError("span: --len is required");
    const int64_t last = s.regs.zeta0 + int64_t(s.regs.len) * s.regs.dzeta;
    if (last < m.angle_min() || last > m.angle_max()) {
        throw UsageError("span: the last angle zeta0 + len*dzeta = " + std::to_string(m.angle_value(last)) +
                         " rad leaves the angle format's range [-8, 8)");
    }
    if (!s.vcd.empty() && s.model != "rtl") throw UsageError("--vcd: only with --model rtl");
    if (s.lanes != 1 && s.model != "stream") throw UsageError("--lanes: only with --model stream");
    if (s.lanes != 1 && s.mode == Mode::tuned) throw UsageError("--lanes: only in patent and pow mode");
    if (s.mode == Mode::pow && s.lanes != 1 && !(s.lanes == 4 && s.pack)) {
        throw UsageError("--lanes: pow mode's spec_stream is Verilated with LANES = 1, and 4 with --pack");
    }
    if (s.pack && (s.model != "stream" || s.lanes != 4)) throw UsageError("--pack: only with --model stream --lanes 4");
    return s;
}

std::vector<uint32_t> span_pixels(const SpanOptions& s) {
    Format fmt;
    fmt.mode = s.mode;
    std::unique_ptr<SpanCore> core;
    const Model m(fmt);
    if (s.model == "golden") {
        core.reset(new ModelCore(m));
    } else if (s.model == "stream") {
        if (s.mode == Mode::tuned) core.reset(new StreamCore<Vspec_stream_tuned>());
        else if (s.mode == Mode::pow && s.lanes == 4) core.reset(new StreamCore<Vspec_stream_pow_l4p, 4, true>());
        else if (s.mode == Mode::pow) core.reset(new StreamCore<Vspec_stream_pow>());
        else if (s.lanes == 2) core.reset(new StreamCore<Vspec_stream_l2, 2>());
        else if (s.lanes == 4 && s.pack) core.reset(new StreamCore<Vspec_stream_l4p, 4, true>());
        else if (s.lanes == 4) core.reset(new StreamCore<Vspec_stream_l4, 4>());
        else core.reset(new StreamCore<Vspec_stream>());
    } else if (s.model == "rtl") {
        try {
            core = make_unit_driver(s.mode, s.vcd);
        } catch (const std::runtime_error& e) {   // the waveform file (the only thing the driver opens)
            throw InputError(e.what());
        }
    } else {
        throw std::invalid_argument("span_pixels: model '" + s.model + "' does not run the core");
    }
    std::vector<uint32_t> px = core->span(s.regs);
    if (px.size() != size_t(s.regs.len) + 1) {
        throw std::runtime_error("the core produced " + std::to_string(px.size()) + " pixels, expected " +
                                 std::to_string(size_t(s.regs.len) + 1));
    }
    return px;
}

std::vector<double> span_reference(const SpanOptions& s) {
    std::vector<double> v;
    for (uint64_t i = 0; i <= s.regs.len; ++i) {
        v.push_back(s.c * std::pow(std::max(0.0, std::cos(s.zeta0 + double(i) * s.dzeta)), double(s.regs.n)));
    }
    return v;
}

std::string span_csv(const Format& f, const std::vector<uint32_t>& px) {
    std::ostringstream o;
    char buf[64];
    o << "i,value\n";
    for (size_t i = 0; i < px.size(); ++i) {
        std::snprintf(buf, sizeof buf, "%.*f", f.out_w, std::ldexp(static_cast<double>(px[i]), -f.out_w));
        o << i << "," << buf << "\n";
    }
    return o.str();
}

std::string span_csv(const std::vector<double>& ref) {
    std::ostringstream o;
    char buf[64];
    o << "i,value\n";
    for (size_t i = 0; i < ref.size(); ++i) {
        std::snprintf(buf, sizeof buf, "%.16f", ref[i]);
        o << i << "," << buf << "\n";
    }
    return o.str();
}

int cmd_span(int argc, char** argv) {
    const SpanOptions s = parse_span(argc, argv);
    Format fmt;
    fmt.mode = s.mode;
    std::cout << (s.model == "ref" ? span_csv(span_reference(s)) : span_csv(fmt, span_pixels(s)));
    return 0;
}

}  // namespace spec
