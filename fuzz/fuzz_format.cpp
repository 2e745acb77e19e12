// fuzz_format - the generator and the model on any format: specrom's options set Format's fields; whatever
// passes Format::validate() must give ROM images, headers and a working bit-exact model (any span), or a
// std::out_of_range / std::invalid_argument with a one-line message (specrom's exit 2). No other exception,
// no undefined behaviour (shifts, overflows, float-to-int conversions: UBSan).
#include <stdexcept>

#include "fuzz_input.h"
#include "romgen.h"
#include "spec_model.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    fuzz::Input in(data, size);
    spec::Format f;
    if (in.byte() & 1) f = spec::config_format("up5k");
    // specrom accepts 0..64 for each of these (parse_int); validate() must reject what does not work
    f.c_w = static_cast<int>(in.range(0, 64));
    f.out_w = (in.byte() & 7) ? f.c_w : static_cast<int>(in.range(0, 64));
    f.ang_w = static_cast<int>(in.range(0, 64));
    f.ang_frac = static_cast<int>(in.range(0, 64));
    f.n_w = static_cast<int>(in.range(0, 12));          // 2^n_w words: kept small enough to be quick
    f.l_w = static_cast<int>(in.range(0, 64));
    f.scale_w = static_cast<int>(in.range(0, 64));
    f.scale_frac = static_cast<int>(in.range(0, 64));
    f.tbl_aw = static_cast<int>(in.range(0, 14));
    f.tbl_frac = static_cast<int>(in.range(0, 64));
    f.interp = in.byte() & 1;
    f.interp_frac = static_cast<int>(in.range(0, 64));
    f.delta_w = static_cast<int>(in.range(0, 64));
    if (in.byte() % 4 == 0) {
        std::vector<int> t;
        const int k = static_cast<int>(in.range(0, 17));
        for (int i = 0; i < k; ++i) t.push_back(static_cast<int>(in.range(0, 300)));
        f.tables = t;
    }
    // tuned mode fits a minimax scale per n (slow): only for small n_w
    if (f.n_w <= 6 && (in.byte() & 1)) f.mode = spec::Mode::tuned;
    try {
        f.validate();
    } catch (const std::invalid_argument& e) {
        fuzz::one_line(e.what());
        return 0;
    }
    try {
        const auto r9 = spec::make_rom9(f);
        const auto r12 = spec::make_rom12(f);
        fuzz::check(r9.size() == (size_t(1) << f.n_w), "ROM 9 size");
        spec::hex_image(std::vector<uint64_t>(r9.begin(), r9.end()), f.rom9_dw(), "ROM 9");
        spec::hex_image(r12, f.rom12_dw(), "ROM 12");
        spec::verilog_header(f);
        spec::cpp_header(f);
    } catch (const std::out_of_range& e) {
        fuzz::one_line(e.what());
        return 0;
    } catch (const std::invalid_argument& e) {
        fuzz::one_line(e.what());
        return 0;
    }
    // a format the generator accepted gives a working model: any exception from here on escapes (a crash)
    const spec::Model m(f);
    // a few spans with raw register contents
    for (int s = 0; s < 4 && !in.empty(); ++s) {
        spec::SpanRegs r;
        r.c = static_cast<uint32_t>(in.range(0, (int64_t(1) << f.c_w) - 1));
        r.n = static_cast<uint32_t>(in.range(0, (int64_t(1) << f.n_w) - 1));
        r.len = static_cast<uint32_t>(in.range(0, std::min<int64_t>(64, (int64_t(1) << std::min(f.l_w, 20)) - 1)));
        r.zeta0 = in.range(m.angle_min(), m.angle_max());
        r.dzeta = in.range(m.angle_min(), m.angle_max());
        const auto px = m.span(r);
        fuzz::check(px.size() == r.len + 1u, "span length");
        for (uint32_t v : px) fuzz::check(v <= r.c, "pixel above C");
    }
    return 0;
}
