// fuzz_setup - both configurations' setup models (sim/setup/setup_config.h: the multiplier setup's SetupModel,
// the small CORDIC setup's SmallSetupModel) on any span-ends beat: components of any value (equal, opposite,
// tiny and extreme ones often), strength, n, l and gamma rule. Promises (docs/setup.md): no internal check
// fires (an internal error throws) and no undefined behaviour; a zero vector gives the invalid flag with C = zeta0 = dzeta = 0, and only a
// zero vector does; the descriptor is one spec_stream accepts (C a UQ0.16 code, n and l as given, zeta0 and
// the span's last angle inside the angle format, dzeta = 0 when flat or l = 0); the flags agree with C
// (no highlight: 0, saturated: the largest code); and the span's pixels through the core are within the
// configuration's bound of the host's double-precision setup with exact cos^n (setup_eval.h, check_span; widened
// by the host's own conditioning where the span is ill-conditioned; the host's patent rule where the gamma
// fallback flag is set; the small setup always falls back). Long spans are cut to 4096 intervals to keep an
// execution fast.
#include <random>
#include <string>

#include "fuzz_input.h"
#include "setup_eval.h"
#include "setup_config.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const spec::ConfigSetupModel models[2] = {spec::ConfigSetupModel(spec::SetupConfig::ecp5),
                                                      spec::ConfigSetupModel(spec::SetupConfig::up5k)};
    static const spec::Model core;
    const spec::SetupFormat& sf = models[0].format();
    fuzz::Input in(data, size);
    const int shared = in.byte();
    spec::SetupInput s;
    int32_t* v[4] = {s.n1, s.n2, s.h1, s.h2};
    const int32_t lim = int32_t(1) << (sf.vec_w - 1);
    for (int k = 0; k < 4; ++k) {
        for (int c = 0; c < 3; ++c) {
            const int kind = in.byte() & 7;
            v[k][c] = kind == 0 ? 0 : kind == 1 ? -lim : kind == 2 ? lim - 1 : kind == 3 ? int32_t(in.range(-3, 3))
                                                                                   : int32_t(in.range(-lim, lim - 1));
        }
    }
    for (int c = 0; c < 3; ++c) {
        if (shared & 1) s.n2[c] = s.n1[c];
        if (shared & 2) s.h2[c] = s.h1[c];
        if ((shared & 4) && s.n1[c] != -lim) s.n2[c] = -s.n1[c];
        if (shared & 8) s.h1[c] = s.n1[c];
    }
    s.strength = static_cast<uint32_t>(in.range(0, (int64_t(1) << sf.str_w) - 1));
    s.n = static_cast<uint32_t>(in.range(0, (1 << core.format().n_w) - 1));
    s.l = static_cast<uint32_t>(in.range(0, (shared & 16) ? 4096 : 64));
    s.midpoint = (shared & 32) != 0;

    const spec::ConfigSetupModel& sm = models[(shared >> 6) & 1];
    const spec::SetupResult r = sm.run(s);   // an internal error throws: a crash for the fuzzer
    bool zero = false;
    for (int k = 0; k < 4; ++k) zero = zero || (v[k][0] == 0 && v[k][1] == 0 && v[k][2] == 0);
    const bool invalid = (r.flags & spec::kSetupInvalid) != 0;
    fuzz::check(invalid == zero, "the invalid flag is not 'an end vector is zero'");
    fuzz::check(r.flags < (1u << spec::kSetupFlagBits), "flags outside tuser");
    fuzz::check(r.regs.n == s.n && r.regs.len == s.l, "n or l not passed on");
    fuzz::check(r.regs.c < (1u << core.format().c_w), "C outside its code");
    fuzz::check(((r.flags & spec::kSetupSinglePixel) != 0) == (s.l == 0), "single-pixel flag is not l = 0");
    if (invalid) {
        fuzz::check(r.regs.c == 0 && r.regs.zeta0 == 0 && r.regs.dzeta == 0, "an invalid span's descriptor is not 0");
        return 0;
    }
    const int64_t last = r.regs.zeta0 + int64_t(s.l) * r.regs.dzeta;
    fuzz::check(r.regs.zeta0 >= core.angle_min() && r.regs.zeta0 <= core.angle_max(), "zeta0 outside the format");
    fuzz::check(last >= core.angle_min() && last <= core.angle_max(), "the span's last angle leaves the format");
    fuzz::check(r.regs.dzeta >= 0, "dzeta negative");
    if ((r.flags & spec::kSetupFlat) || s.l == 0) fuzz::check(r.regs.dzeta == 0, "flat or single span with dzeta != 0");
    if (r.flags & spec::kSetupNoHighlight) fuzz::check(r.regs.c == 0, "no highlight but C != 0");
    if (r.flags & spec::kSetupCSaturated) fuzz::check(r.regs.c == (1u << core.format().c_w) - 1, "saturated but C not full");
    if (sm.small() && s.midpoint) fuzz::check((r.flags & spec::kSetupGammaFallback) != 0, "midpoint asked and no fallback flag");
    if (!s.midpoint) fuzz::check((r.flags & spec::kSetupGammaFallback) == 0, "a fallback without the midpoint rule");

    // the gamma fallback flag says the patent rule's gamma was used: the host's patent rule is the reference
    spec::SetupInput ref = s;
    if (r.flags & spec::kSetupGammaFallback) ref.midpoint = false;
    std::mt19937_64 rng(shared);
    const spec::CheckOptions co = spec::setup_config_check(sm.config());
    const spec::SpanCheck c = spec::check_span(core, sf, ref, core.span(r.regs), rng, co);
    if (c.ratio > 1.0) {
        fuzz::fail(std::string(spec::setup_config_name(sm.config())) + ": pixel " + std::to_string(c.worst_pixel) + ": " + std::to_string(c.out) + " vs host " +
                   std::to_string(c.ref) + ", bound " + std::to_string(c.bound) + " (ratio " + std::to_string(c.ratio) +
                   ")");
    }
    return 0;
}
