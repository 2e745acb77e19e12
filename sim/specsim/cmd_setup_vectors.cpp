// cmd_setup_vectors.cpp - specsim setup-vectors: test vectors for the Icarus testbench of spec_shader
// (tests/iverilog/tb_spec_shader.v, ctest icarus_spec_shader): random and degenerate span ends and, from the
// bit-exact models (the configuration's setup model, then the core's Model), every pixel the shader must give.
//
//   FILE.beats   one span-ends beat a line, 64 hex digits (docs/setup.md's layout)
//   FILE.pixels  one pixel a line, 6 hex digits: {flags (7 bits), tlast, value (16 bits)}
// and on stdout "spans S pixels P".
#include <cstdio>
#include <fstream>
#include <iostream>
#include <random>
#include <string>

#include "cli.h"
#include "commands.h"
#include "setup_driver.h"
#include "setup_eval.h"
#include "setup_rtl.h"

namespace spec {

const char* const kSetupVectorsUsage =
    "  setup-vectors  test vectors for the Icarus testbench of spec_shader: --out PREFIX (PREFIX.beats,\n"
    "                PREFIX.pixels) --spans N (1..100000, default 200) --seed S --max-len L (0..255, default 12)\n"
    "                --config ecp5|up5k (the configuration the pixels are for; default ecp5)\n";

int cmd_setup_vectors(int argc, char** argv) {
    std::string out;
    long long spans = 200, seed = 1, max_len = 12;
    SetupConfig cfg = SetupConfig::ecp5;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string fl = a.flag();
        if (fl == "--out") out = a.value(fl);
        else if (fl == "--spans") spans = parse_int(fl, a.value(fl), 1, 100000);
        else if (fl == "--seed") seed = parse_int(fl, a.value(fl), 0, 1LL << 40);
        else if (fl == "--max-len") max_len = parse_int(fl, a.value(fl), 0, 255);
        else if (fl == "--config") {
            try {
                cfg = parse_setup_config(a.value(fl));
            } catch (const std::invalid_argument& e) {
                throw UsageError(std::string("--config: ") + e.what());
            }
        } else {
            throw UsageError("setup-vectors: unknown option " + fl);
        }
    }
    if (out.empty()) throw UsageError("setup-vectors: --out PREFIX is required");
    const ConfigSetupModel sm(cfg);
    const Model core(shader_core_format(cfg));
    std::mt19937_64 rng(static_cast<uint64_t>(seed));
    std::ofstream fb(out + ".beats"), fp(out + ".pixels");
    if (!fb || !fp) throw UsageError("setup-vectors: cannot write " + out + ".beats / .pixels");
    uint64_t pixels = 0;
    for (long long s = 0; s < spans; ++s) {
        SetupInput in = rng() % 5 == 4 ? random_raw(rng, sm.format())
                                       : random_case(rng, sm.format(), SpanKind(rng() % unsigned(SpanKind::count)),
                                                     static_cast<unsigned>(rng() % 1024), static_cast<uint32_t>(max_len));
        in.l %= static_cast<uint32_t>(max_len) + 1;
        if (rng() % 2) in.midpoint = !in.midpoint;
        uint32_t w[setup_params::BEAT_W / 32];
        pack_setup_beat(in, w);
        for (int i = setup_params::BEAT_W / 32 - 1; i >= 0; --i) {
            char b[12];
            std::snprintf(b, sizeof b, "%08x", w[i]);
            fb << b;
        }
        fb << "\n";
        const SetupResult r = sm.run(in);
        const std::vector<uint32_t> px = core.span(r.regs);
        for (size_t i = 0; i < px.size(); ++i) {
            char b[16];
            std::snprintf(b, sizeof b, "%06x\n",
                          (unsigned(r.flags & 0x7f) << 17) | (unsigned(i + 1 == px.size()) << 16) | (px[i] & 0xffffu));
            fp << b;
        }
        pixels += px.size();
    }
    fb.close();
    fp.close();
    if (!fb || !fp) throw UsageError("setup-vectors: cannot write " + out + ".beats / .pixels");
    std::printf("spans %lld pixels %llu\n", spans, (unsigned long long)pixels);
    return 0;
}

}  // namespace spec
