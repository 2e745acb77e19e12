// cmd_vectors.cpp - specsim vectors (the icarus_* ctests).
#include "cmd_vectors.h"

#include <cstdio>
#include <random>
#include <sstream>

#include "analysis.h"
#include "cli.h"
#include "cmd_span.h"
#include "commands.h"
#include "fileutil.h"

namespace spec {

const char* const kVectorsUsage =
    "  vectors  test vectors from the bit-exact model for the Icarus testbench\n"
    "           --out FILE --spans N (1..5000, default 200) --seed S --mode patent|tuned|pow --tables K,K,...\n"
    "           --config NAME (a named configuration of specrom, e.g. up5k; before --mode/--tables)\n";

VectorsOptions parse_vectors(int argc, char** argv) {
    VectorsOptions o;
    Args a(argc, argv, 2);
    while (!a.done()) {
        std::string fl = a.flag();
        if (fl == "--out") o.out = a.value(fl);
        else if (fl == "--spans") o.spans = static_cast<uint32_t>(parse_int(fl, a.value(fl), 1, 5000));
        else if (fl == "--seed") o.seed = static_cast<uint64_t>(parse_int(fl, a.value(fl), 0, 1LL << 40));
        else if (fl == "--config") {
            try {
                o.fmt = config_format(a.value(fl));
            } catch (const std::invalid_argument& e) {
                throw UsageError(fl + ": " + e.what());
            }
        } else if (fl == "--mode") o.fmt.mode = parse_mode_flag(fl, a.value(fl));
        else if (fl == "--tables") o.fmt.tables = parse_tables(fl, a.value(fl));
        else throw UsageError("vectors: unknown option " + fl);
    }
    if (o.out.empty()) throw UsageError("vectors: --out is required");
    return o;
}

std::vector<SpanRegs> vector_spans(const Model& m, uint32_t count, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::vector<SpanRegs> v;
    for (uint32_t s = 0; s < count; ++s) {
        SpanRegs r;
        r.n = (s < 1024) ? static_cast<uint32_t>((s * 37) % 1024) : static_cast<uint32_t>(rng() % 1024);
        r.c = static_cast<uint32_t>(rng() % 65536);
        r.len = static_cast<uint32_t>(rng() % 24);
        // around the highlight; in pow mode every third span also reaches past pi/2 (the log table's side 1, where
        // the angle nears pi/2) and every third one stays near 0 (its smallest segments)
        const double e = epicentre_end(r.n);
        const int kind = m.format().pow() ? int(s % 3) : 0;
        const double reach = kind == 1 ? 1.8 : kind == 2 ? 0.002 : 2.0 * e + 0.1;
        std::uniform_real_distribution<double> z(-reach, reach);
        r.zeta0 = m.quantize_angle(z(rng));
        r.dzeta = m.quantize_angle((z(rng) - m.angle_value(r.zeta0)) / (r.len ? r.len : 1));
        v.push_back(r);
    }
    return v;
}

std::string vectors_text(const Model& m, const std::vector<SpanRegs>& spans) {
    std::ostringstream o;
    char buf[32];
    auto word = [&](uint64_t w) {
        std::snprintf(buf, sizeof buf, "%08llx\n", static_cast<unsigned long long>(w & 0xffffffffULL));
        o << buf;
    };
    o << "// spans for tests/iverilog/tb_spec_unit.v: count, then per span c, dzeta, zeta0, n, len, pixels\n";
    word(spans.size());
    for (const SpanRegs& r : spans) {
        word(r.c);
        word(static_cast<uint64_t>(r.dzeta));
        word(static_cast<uint64_t>(r.zeta0));
        word(r.n);
        word(r.len);
        for (uint32_t p : m.span(r)) word(p);
    }
    return o.str();
}

int cmd_vectors(int argc, char** argv) {
    const VectorsOptions o = parse_vectors(argc, argv);
    const Model m(o.fmt);
    const std::string text = vectors_text(m, vector_spans(m, o.spans, o.seed));
    render::write_atomic(o.out, [&](const std::string& tmp) {
        std::FILE* f = std::fopen(tmp.c_str(), "w");
        if (!f) throw InputError("cannot write " + o.out);
        const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
        if (std::fclose(f) != 0 || !ok) throw InputError("cannot write " + o.out);
    });
    return 0;
}

}  // namespace spec
