// cmd_setup.cpp - specsim setup: a span's end vectors, n, l and strength through spec_setup (the Verilated
// RTL, its bit-exact model or the host's double-precision setup), printed as CSV; --pixels adds the span's
// pixels through the whole shader.
#include "cmd_setup.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "cli.h"
#include "commands.h"
#include "setup_eval.h"
#include "span_host.h"

namespace spec {

const char* const kSetupUsage =
    "  setup    one span's end vectors through spec_setup (the patent's external device in hardware); prints\n"
    "           CSV 'c,zeta0,dzeta,n,l,flags' (register codes; --model host: the host's values in double)\n"
    "           --n1 X,Y,Z --n2 X,Y,Z   normals at the span's first and last pixel (any length, not zero;\n"
    "           --h1 X,Y,Z --h2 X,Y,Z   halfway vectors      components in [-2, 2), quantized to Q1.14)\n"
    "           --n N          exponent, 0..1023\n"
    "           --strength S   Is*ks, decimal in [0, 2) (UQ1.15)\n"
    "           --len L        intervals l, 0..65535 (l + 1 pixels)\n"
    "           --model M      rtl (Verilated spec_setup, default) | golden (bit-exact model) | host (double)\n"
    "           --gamma G      patent (default) | midpoint (docs/host.md, docs/setup.md)\n"
    "           --config C     ecp5 (default: the multiplier setup, spec_stream) | up5k (the small CORDIC setup,\n"
    "                          spec_stream_seq and spec_stream's up5k tables; docs/setup.md)\n"
    "           --pixels       also the span's pixels through the whole shader, CSV 'i,value' (rtl: the\n"
    "                          Verilated spec_shader; golden: the models; host: exact cos^n in double)\n";

namespace {

void parse_vector(const SetupFormat& sf, const std::string& fl, const std::string& v, int32_t out[3]) {
    std::vector<std::string> parts;
    size_t pos = 0;
    while (true) {
        const size_t comma = v.find(',', pos);
        parts.push_back(v.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos));
        if (comma == std::string::npos) break;
        pos = comma + 1;
    }
    if (parts.size() != 3) throw UsageError(fl + ": '" + v + "' is not three components X,Y,Z");
    const double top = std::ldexp(1.0, sf.vec_w - 1 - sf.vec_frac);
    for (int k = 0; k < 3; ++k) {
        const double x = parse_double(fl, parts[k]);
        const double q = std::nearbyint(std::ldexp(x, sf.vec_frac));
        if (q < -std::ldexp(1.0, sf.vec_w - 1) || q > std::ldexp(1.0, sf.vec_w - 1) - 1) {
            throw UsageError(fl + ": component " + parts[k] + " is outside the format's range [-" + std::to_string(int(top)) +
                             ", " + std::to_string(int(top)) + ")");
        }
        out[k] = static_cast<int32_t>(q);
    }
    if (out[0] == 0 && out[1] == 0 && out[2] == 0) throw UsageError(fl + ": a zero vector has no direction");
}

std::string fmt_out(const Format& f, uint32_t raw) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", f.out_w, std::ldexp(static_cast<double>(raw), -f.out_w));
    return buf;
}

}  // namespace

SetupOptions parse_setup(int argc, char** argv) {
    const SetupFormat sf;
    const Format f;
    SetupOptions o;
    bool have[7] = {false, false, false, false, false, false, false};
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string fl = a.flag();
        if (fl == "--n1" || fl == "--n2" || fl == "--h1" || fl == "--h2") {
            const int k = fl == "--n1" ? 0 : fl == "--n2" ? 1 : fl == "--h1" ? 2 : 3;
            int32_t* dst[4] = {o.in.n1, o.in.n2, o.in.h1, o.in.h2};
            parse_vector(sf, fl, a.value(fl), dst[k]);
            have[k] = true;
        } else if (fl == "--n") {
            o.in.n = static_cast<uint32_t>(parse_int(fl, a.value(fl), 0, (1 << f.n_w) - 1));
            have[4] = true;
        } else if (fl == "--strength") {
            const double s = parse_double(fl, a.value(fl));
            const double q = std::nearbyint(std::ldexp(s, sf.str_frac));
            if (s < 0.0 || q > std::ldexp(1.0, sf.str_w) - 1) {
                throw UsageError("--strength: Is*ks must be in [0, " + std::to_string(int(std::ldexp(1.0, sf.str_w - sf.str_frac))) + ")");
            }
            o.in.strength = static_cast<uint32_t>(q);
            have[5] = true;
        } else if (fl == "--len") {
            o.in.l = static_cast<uint32_t>(parse_int(fl, a.value(fl), 0, (int64_t(1) << f.l_w) - 1));
            have[6] = true;
        } else if (fl == "--model") {
            o.model = a.value(fl);
            if (o.model != "rtl" && o.model != "golden" && o.model != "host") {
                throw UsageError("--model: '" + o.model + "' is not one of rtl, golden, host");
            }
        } else if (fl == "--gamma") {
            const std::string g = a.value(fl);
            if (g != "patent" && g != "midpoint") throw UsageError("--gamma: '" + g + "' is not patent or midpoint");
            o.in.midpoint = g == "midpoint";
        } else if (fl == "--config") {
            try {
                o.config = parse_setup_config(a.value(fl));
            } catch (const std::invalid_argument& e) {
                throw UsageError(std::string("--config: ") + e.what());
            }
        } else if (fl == "--pixels") {
            o.pixels = true;
        } else {
            throw UsageError("setup: unknown option " + fl);
        }
    }
    const char* names[7] = {"--n1", "--n2", "--h1", "--h2", "--n", "--strength", "--len"};
    for (int k = 0; k < 7; ++k)
        if (!have[k]) throw UsageError(std::string("setup: ") + names[k] + " is required");
    return o;
}

SetupReport setup_compute(const SetupOptions& o) {
    SetupReport r;
    const ConfigSetupModel sm(o.config);
    if (o.model == "host") {
        r.host = true;
        const Model core(shader_core_format(o.config));
        const host::SpanSetup s = host::setup_span(core, host_ends(sm.format(), o.in), host_strength(sm.format(), o.in),
                                                   o.in.n, o.in.l, host_rule(o.in));
        r.c = s.c_used;
        r.zeta0 = s.zeta0;
        r.dzeta = s.dzeta;
        r.flags = s.flags;
        r.regs.n = o.in.n;
        r.regs.len = o.in.l;
        if (o.pixels)
            for (uint32_t i = 0; i <= o.in.l; ++i) r.values.push_back(s.value(i));
        return r;
    }
    if (o.model == "golden") {
        const SetupResult g = sm.run(o.in);
        r.regs = g.regs;
        r.flags = g.flags;
        if (o.pixels) r.pixels = Model(shader_core_format(o.config)).span(g.regs);
        return r;
    }
    const SetupDescriptor d = setup_rtl(o.config, o.in);
    r.regs = d.regs;
    r.flags = d.flags;
    if (o.pixels) {
        const std::vector<ShaderRtl::Span> px = make_shader_rtl(o.config)->run({o.in});
        r.pixels = px.at(0).pixels;
    }
    return r;
}

std::string setup_csv(const SetupOptions& o, const SetupReport& r) {
    std::ostringstream os;
    char buf[160];
    os << "c,zeta0,dzeta,n,l,flags\n";
    if (r.host) {
        std::snprintf(buf, sizeof buf, "%.10f,%.12f,%.12f,%u,%u,%u\n", r.c, r.zeta0, r.dzeta, r.regs.n, r.regs.len, r.flags);
    } else {
        std::snprintf(buf, sizeof buf, "%u,%lld,%lld,%u,%u,%u\n", r.regs.c, static_cast<long long>(r.regs.zeta0),
                      static_cast<long long>(r.regs.dzeta), r.regs.n, r.regs.len, r.flags);
    }
    os << buf;
    if (o.pixels) {
        os << "i,value\n";
        const Format f = shader_core_format(o.config);
        if (r.host) {
            for (size_t i = 0; i < r.values.size(); ++i) {
                std::snprintf(buf, sizeof buf, "%zu,%.16f\n", i, r.values[i]);
                os << buf;
            }
        } else {
            for (size_t i = 0; i < r.pixels.size(); ++i) os << i << "," << fmt_out(f, r.pixels[i]) << "\n";
        }
    }
    return os.str();
}

int cmd_setup(int argc, char** argv) {
    for (int i = 2; i < argc; ++i) {
        if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
            std::cout << "usage: specsim setup [options]\n" << kSetupUsage;
            return 0;
        }
    }
    const SetupOptions o = parse_setup(argc, argv);
    std::cout << setup_csv(o, setup_compute(o));
    return 0;
}

}  // namespace spec
