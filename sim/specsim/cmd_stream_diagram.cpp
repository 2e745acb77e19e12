// cmd_stream_diagram.cpp - specsim stream-diagram (make docs; ctest docs_stream_timing_matches_simulation).
#include <fstream>
#include <iostream>
#include <sstream>

#include "Vspec_stream.h"
#include "cli.h"
#include "cmd_bench.h"
#include "commands.h"

namespace spec {

StreamTrace stream_trace() {
    const Model m;
    StreamTrace tr;
    tr.spans = {SpanRegs{m.quantize_c(0.9), m.quantize_angle(0.05), m.quantize_angle(-0.05), 10, 2},
                SpanRegs{m.quantize_c(0.5), 0, 0, 0, 0},
                SpanRegs{m.quantize_c(0.7), m.quantize_angle(0.1), m.quantize_angle(0.0), 3, 1}};
    StreamDriver<Vspec_stream> d;
    auto& t = d.top();
    tr.rows.assign(7, {});
    size_t next = 0;
    // the sink stalls for two cycles while the second and third spans come out (after the core's latency)
    const int stall0 = spec_params::STREAM_LATENCY + 4;
    tr.stall0 = stall0;
    for (int c = 0; c < spec_params::STREAM_LATENCY + 12; ++c) {
        t.s_axis_tvalid = next < tr.spans.size();
        if (next < tr.spans.size()) {
            uint32_t w[kDescWords];
            pack_descriptor(tr.spans[next], w);
            for (int i = 0; i < kDescWords; ++i) t.s_axis_tdata[i] = w[i];
        }
        t.m_axis_tready = !(c == stall0 || c == stall0 + 1);
        t.eval();
        const bool in_fire = t.s_axis_tvalid && t.s_axis_tready;
        const bool out_fire = t.m_axis_tvalid && t.m_axis_tready;
        const bool v[7] = {bool(t.s_axis_tvalid), bool(t.s_axis_tready), in_fire, bool(t.m_axis_tvalid),
                           bool(t.m_axis_tready), bool(t.m_axis_tlast && t.m_axis_tvalid), out_fire};
        for (int r = 0; r < 7; ++r) tr.rows[r].push_back(v[r]);
        if (out_fire) tr.pixels.push_back(t.m_axis_tdata);
        d.step();
        if (in_fire) ++next;
    }
    return tr;
}

std::string stream_diagram(const StreamTrace& tr) {
    const Model m;
    std::ostringstream o;
    o << "spec_stream: descriptors l = 2, 0, 1 back to back, the sink stalls in cycles " << tr.stall0 << "-"
      << tr.stall0 + 1 << "; one character per\n"
      << "clock, from the Verilated spec_stream (specsim stream-diagram)\n\n";
    const size_t ncyc = tr.rows[0].size();
    std::string ruler;
    for (size_t c = 0; c < ncyc; ++c) ruler += (c % 5 == 0) ? std::to_string(c % 10) : " ";
    o << "                 " << ruler << "\n";
    const char* names[] = {"s_axis_tvalid    ", "s_axis_tready    ", "  descriptor in  ", "m_axis_tvalid    ",
                           "m_axis_tready    ", "m_axis_tlast     ", "  pixel out      "};
    for (int r = 0; r < 7; ++r) {
        o << names[r];
        for (bool b : tr.rows[r]) o << (b ? "\u203e" : "_");
        o << "\n";
    }
    o << "\npixels out: ";
    for (size_t i = 0; i < tr.pixels.size(); ++i) o << (i ? ", " : "") << tr.pixels[i];
    o << "  (UQ0.16 codes; model: ";
    size_t k = 0;
    for (const auto& s : tr.spans)
        for (uint32_t p : m.span(s)) o << (k++ ? ", " : "") << p;
    o << ")\n";
    return o.str();
}

int cmd_stream_diagram(int argc, char** argv) {
    std::string out;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string fl = a.flag();
        if (fl == "--out") out = a.value(fl);
        else throw UsageError("stream-diagram: unknown option " + fl);
    }
    const std::string text = stream_diagram(stream_trace());
    std::cout << text;
    if (!out.empty()) {
        std::ofstream os(out);
        if (!(os << text)) throw InputError("cannot write " + out);
    }
    return 0;
}

}  // namespace spec
