// fuzz_host - the host's span parameters (sim/host/span_host.h, setup_span) on any end vectors, strength,
// n, l and gamma rule. Promise (docs/host.md): std::invalid_argument with a one-line message for a vector
// that is zero or not finite, a strength that is negative or not finite, n or l outside the formats; else
// register contents the core accepts - C a UQ0.16 code, the angles and the span's last angle inside
// [-8, 8), n and l as given - and finite values everywhere, whatever degenerate case the span is.
#include <algorithm>
#include <cmath>
#include <string>
#include <stdexcept>

#include "fuzz_input.h"
#include "span_host.h"

using spec::host::Vec;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const spec::Model m;
    fuzz::Input in(data, size);
    spec::host::SpanEnds e;
    Vec* v[4] = {&e.n1, &e.n2, &e.h1, &e.h2};
    const int shared = in.byte();   // often make vectors equal or opposite: the degenerate cases
    for (int k = 0; k < 4; ++k) *v[k] = Vec(in.real(), in.real(), in.real());
    if (shared & 1) e.n2 = e.n1;
    if (shared & 2) e.h2 = e.h1;
    if (shared & 4) e.n2 = -e.n1;
    if (shared & 8) e.h1 = e.n1;
    if (shared & 64) e.h2 = -e.h1;   // opposite halfway vectors (gamma = pi, fuzz/regress/host)
    const double strength = (shared & 16) ? in.real(2.0) : std::fabs(in.real(1.0));
    const unsigned n = static_cast<unsigned>(in.range(0, 1100));
    const uint32_t l = static_cast<uint32_t>(in.range(0, 70000));
    const auto rule = (shared & 32) ? spec::host::GammaRule::midpoint : spec::host::GammaRule::patent;
    spec::host::SpanSetup s;
    try {
        s = spec::host::setup_span(m, e, strength, n, l, rule);
    } catch (const std::invalid_argument& x) {
        fuzz::one_line(x.what());
        // only bad input may be rejected: a zero or non-finite vector, a bad strength, n or l
        bool bad = !std::isfinite(strength) || strength < 0.0 || n >= 1024 || l >= 65536;
        for (int k = 0; k < 4; ++k) {
            const Vec& w = *v[k];
            const double big = std::max({std::fabs(w.x), std::fabs(w.y), std::fabs(w.z)});
            bad = bad || !std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.z) || !(big > 1e-300);
        }
        fuzz::check(bad, std::string("valid input rejected: ") + x.what());
        return 0;
    }
    fuzz::check(n < 1024 && l < 65536, "accepted n or l outside the formats");
    const double fields[] = {s.cos_t1, s.cos_t2, s.gamma, s.a, s.lambda, s.c, s.c_used, s.zeta0, s.dzeta};
    for (double x : fields) fuzz::check(std::isfinite(x), "a span parameter is not finite");
    fuzz::check(s.a >= 0.0 && s.a <= 1.0, "amplitude outside [0, 1]");
    fuzz::check(s.regs.c < 65536 && s.regs.n == n && s.regs.len == l, "register contents");
    const int64_t last = s.regs.zeta0 + int64_t(l) * s.regs.dzeta;
    fuzz::check(s.regs.zeta0 >= m.angle_min() && s.regs.zeta0 <= m.angle_max(), "zeta0 outside the format");
    fuzz::check(last >= m.angle_min() && last <= m.angle_max(), "the span's last angle leaves the format");
    fuzz::check(std::isfinite(s.value(0)) && std::isfinite(s.value(l)), "value() not finite");
    fuzz::check(std::isfinite(s.value_quantized(m, l)), "value_quantized() not finite");
    return 0;
}
