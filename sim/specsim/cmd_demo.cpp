// cmd_demo.cpp - specsim demo (make sim): the Fig. 11/12 span and representative spans through the RTL.
#include "cmd_demo.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "analysis.h"
#include "cli.h"
#include "commands.h"
#include "unit_driver.h"

namespace spec {

const char* const kDemoUsage =
    "  demo     the Fig. 11/12 span and representative spans through the RTL beside the double reference\n"
    "           --vcd FILE      waveform of the Fig. 11 run\n"
    "           --diagram FILE  text timing diagram of the Fig. 11 run\n";

namespace {
struct DemoOptions {
    std::string vcd, diagram;
};

DemoOptions parse_demo(int argc, char** argv) {
    DemoOptions o;
    Args a(argc, argv, 2);
    while (!a.done()) {
        std::string fl = a.flag();
        if (fl == "--vcd") o.vcd = a.value(fl);
        else if (fl == "--diagram") o.diagram = a.value(fl);
        else throw UsageError("demo: unknown option " + fl);
    }
    return o;
}

std::string fmt_out(const Format& f, uint32_t raw) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", f.out_w, std::ldexp(static_cast<double>(raw), -f.out_w));
    return buf;
}

// One-character-per-cycle waveform row.
std::string wave(const std::vector<bool>& v) {
    std::string s;
    for (bool b : v) s += b ? "\u203e" : "_";
    return s;
}
}  // namespace

Fig11Run fig11_run(const std::string& vcd) {
    const Model m;
    Fig11Run run;
    run.regs = SpanRegs{m.quantize_c(0.75), m.quantize_angle(0.1), m.quantize_angle(-0.15), 10, 3};
    std::unique_ptr<UnitDriver> d;
    try {
        d.reset(new UnitDriver(vcd));
    } catch (const std::runtime_error& e) {   // the waveform file
        throw InputError(e.what());
    }
    d->steps(2);
    d->write(run.regs);
    run.rows.assign(8, {});
    auto record = [&](bool start, const CtrlSignals& c) {
        const bool v[8] = {start, c.s28, c.s37, c.s36, c.s34, c.s35_n, c.busy, c.valid};
        for (int r = 0; r < 8; ++r) run.rows[r].push_back(v[r]);
    };
    record(true, d->signals());
    d->observer = [&](uint64_t, const CtrlSignals& c) { record(false, c); };
    run.pixels = d->run();
    d->steps(3);
    return run;
}

std::string fig11_diagram(const Fig11Run& r) {
    const Format f;
    const size_t ncyc = r.rows[0].size();
    std::ostringstream t;
    t << "Fig. 11 run (l = 3, n = 10, C = 0.75, zeta0 = -0.15, dzeta = 0.1), one character per clock,\n"
      << "cycle 0 = the cycle Start is high; from the Verilated spec_unit (specsim demo --diagram)\n\n";
    const char* names[] = {"start      26 ", "ff39       28 ", "strobe     37 ", "select     36 ",
                           "count      34 ", "borrow_n   35 ", "busy_o     28 ", "valid_o    29 "};
    std::string ruler;
    for (size_t c = 0; c < ncyc; ++c) ruler += (c % 5 == 0) ? std::to_string(c % 10) : " ";
    t << "              " << ruler << "\n";
    for (int row = 0; row < 8; ++row) t << names[row] << wave(r.rows[row]) << "\n";
    t << "\npixels (valid_o): ";
    for (size_t i = 0; i < r.pixels.size(); ++i) t << (i ? ", " : "") << fmt_out(f, r.pixels[i]);
    t << "\n";
    return t.str();
}

std::vector<DemoPixel> representative_spans(SpanCore& core) {
    const Model m;
    std::vector<DemoPixel> out;
    for (unsigned n : {1u, 3u, 10u, 100u, 1000u}) {
        const double e = epicentre_end(n);
        const double z0 = -1.5 * e, dz = 3.0 * e / 8.0, c = 0.9;
        const SpanRegs r{m.quantize_c(c), m.quantize_angle(dz), m.quantize_angle(z0), n, 8};
        const auto px = core.span(r);
        for (size_t i = 0; i < px.size(); ++i) {
            const double ang = z0 + double(i) * dz;
            out.push_back({n, i, ang, m.out_value(px[i]), c * std::pow(std::max(0.0, std::cos(ang)), double(n)),
                           std::fabs(ang) <= e});
        }
    }
    return out;
}

std::string representative_report(const std::vector<DemoPixel>& px) {
    const Format f;
    std::ostringstream o;
    char b[256];
    o << "Representative spans through the RTL (C = 0.9, 9 pixels across the highlight):\n";
    for (const DemoPixel& p : px) {
        if (p.i == 0) {
            std::snprintf(b, sizeof b, "\n n = %u (k = %d), epicentre |angle| <= %.4f rad\n", p.n, k_of_n(p.n),
                          epicentre_end(p.n));
            o << b << "   i   angle(rad)       rtl          ref        error   error(LSB)  in epicentre\n";
        }
        std::snprintf(b, sizeof b, "  %2zu  %+9.5f  %11.8f  %11.8f  %+10.2e  %+9.2f   %s\n", p.i, p.angle, p.out,
                      p.ref, p.out - p.ref, std::ldexp(p.out - p.ref, f.out_w), p.in_epicentre ? "yes" : "no");
        o << b;
    }
    return o.str();
}

int cmd_demo(int argc, char** argv) {
    const DemoOptions o = parse_demo(argc, argv);
    const Fig11Run run = fig11_run(o.vcd);
    const std::string diagram = fig11_diagram(run);
    std::cout << diagram << "\n";
    if (!o.diagram.empty()) {
        std::ofstream os(o.diagram);
        if (!(os << diagram)) throw InputError("cannot write " + o.diagram);
    }
    if (!o.vcd.empty()) std::cout << "waveform of the Fig. 11 run: " << o.vcd << "\n\n";
    UnitDriver d;
    std::cout << representative_report(representative_spans(d));
    return 0;
}

}  // namespace spec
