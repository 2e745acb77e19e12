// cmd_setup_accuracy.cpp - specsim setup-accuracy: spec_shader (setup, then the core) against the host's
// double-precision setup with exact cos^n, per pixel, for every n and every kind of span (issue 13, item 4;
// sim/setup/setup_eval.h has the bound and the conditioning rule). Prints the table docs/setup.md shows.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cli.h"
#include "commands.h"
#include "mesh.h"
#include "setup_eval.h"
#include "setup_rtl.h"

namespace spec {

const char* const kSetupAccuracyUsage =
    "  setup-accuracy  spec_shader against the host's double-precision setup with exact cos^n, per pixel, for\n"
    "                every n 0..1023 and every kind of span (random, nearly equal ends, constant normal, nearly\n"
    "                opposite normals, N.H <= 0, gamma -> 0, l = 0, C saturating); prints worst error / bound\n"
    "                --per-n K (1..64, default 2: spans per n and kind) --seed S --max-len L (0..65535, default 40)\n"
    "                --model golden|rtl (default golden; equal bit for bit) --config ecp5|up5k (default ecp5)\n"
    "                --gamma patent|midpoint|both (the rule each span asks for; both: chosen at random per span;\n"
    "                default both in ecp5, patent in up5k, whose small setup has only the patent's)\n"
    "                --share X (the setup's share of the bound, default the configuration's: 0.002 in ecp5,\n"
    "                issue 13's; 0.02 in up5k, what its format supports, docs/setup.md)\n"
    "                --json FILE (also write the figures as JSON)\n";

namespace {
struct Row {
    std::string name;
    size_t spans = 0, pixels = 0, widened = 0;
    double worst = 0, worst_plain = 0;
    unsigned worst_n = 0;
};
}  // namespace

int cmd_setup_accuracy(int argc, char** argv) {
    long long per_n = 2, seed = 1, max_len = 40;
    std::string model = "golden", json, gamma;
    double share = -1;
    SetupConfig cfg = SetupConfig::ecp5;
    Args a(argc, argv, 2);
    while (!a.done()) {
        const std::string fl = a.flag();
        if (fl == "--help" || fl == "-h") {
            std::cout << "usage: specsim setup-accuracy [options]\n" << kSetupAccuracyUsage;
            return 0;
        }
        if (fl == "--per-n") per_n = parse_int(fl, a.value(fl), 1, 64);
        else if (fl == "--seed") seed = parse_int(fl, a.value(fl), 0, 1LL << 40);
        else if (fl == "--max-len") max_len = parse_int(fl, a.value(fl), 0, 65535);
        else if (fl == "--json") json = a.value(fl);
        else if (fl == "--share") {
            share = parse_double(fl, a.value(fl));
            if (!(share >= 0.0 && share <= 1.0)) throw UsageError("--share: must be in [0, 1]");
        } else if (fl == "--gamma") {
            gamma = a.value(fl);
            if (gamma != "patent" && gamma != "midpoint" && gamma != "both")
                throw UsageError("--gamma: '" + gamma + "' is not patent, midpoint or both");
        }
        else if (fl == "--model") {
            model = a.value(fl);
            if (model != "golden" && model != "rtl") throw UsageError("--model: '" + model + "' is not golden or rtl");
        } else if (fl == "--config") {
            try {
                cfg = parse_setup_config(a.value(fl));
            } catch (const std::invalid_argument& e) {
                throw UsageError(std::string("--config: ") + e.what());
            }
        } else {
            throw UsageError("setup-accuracy: unknown option " + fl);
        }
    }
    const ConfigSetupModel sm(cfg);
    const Model core(shader_core_format(cfg));
    if (gamma.empty()) gamma = cfg == SetupConfig::up5k ? "patent" : "both";
    CheckOptions co = setup_config_check(cfg);
    if (share >= 0) co.setup_share = share;
    std::mt19937_64 rng(static_cast<uint64_t>(seed));
    std::unique_ptr<ShaderRtl> rtl;
    if (model == "rtl") rtl = make_shader_rtl(cfg);
    std::vector<Row> kinds(size_t(SpanKind::count));
    struct Range {
        const char* name;
        unsigned lo, hi;
    };
    const Range ranges[] = {{"n = 0", 0, 0}, {"n = 1", 1, 1}, {"n = 2", 2, 2}, {"n = 3..6", 3, 6},
                            {"n = 7..1000", 7, 1000}, {"n = 1001..1023", 1001, 1023}};
    std::vector<Row> by_n(6);
    for (int i = 0; i < 6; ++i) by_n[i].name = ranges[i].name;
    for (int k = 0; k < int(SpanKind::count); ++k) {
        kinds[k].name = kind_name(SpanKind(k));
        std::vector<SetupInput> ins;
        for (unsigned n = 0; n < 1024; ++n)
            for (long long r = 0; r < per_n; ++r) {
                ins.push_back(random_case(rng, sm.format(), SpanKind(k), n, uint32_t(max_len)));
                ins.back().midpoint = gamma == "midpoint" || (gamma == "both" && (rng() & 1));
            }
        std::vector<std::vector<uint32_t>> px;
        if (rtl) {
            for (auto& s : rtl->run(ins)) px.push_back(std::move(s.pixels));
        } else {
            for (const SetupInput& in : ins) px.push_back(core.span(sm.run(in).regs));
        }
        for (size_t i = 0; i < ins.size(); ++i) {
            const SpanCheck c = check_span(core, sm.format(), ins[i], px[i], rng, co);
            int rg = 0;
            while (!(ins[i].n >= ranges[rg].lo && ins[i].n <= ranges[rg].hi)) ++rg;
            for (Row* row : {&kinds[k], &by_n[rg]}) {
                ++row->spans;
                row->pixels += px[i].size();
                row->widened += c.widened;
                if (c.ratio > row->worst) {
                    row->worst = c.ratio;
                    row->worst_n = ins[i].n;
                }
                row->worst_plain = std::max(row->worst_plain, c.plain_ratio);
            }
        }
    }
    auto table = [](const char* head, const std::vector<Row>& rows) {
        std::ostringstream o;
        char b[256];
        o << "| " << head << " | spans | pixels | worst error / bound | at n | spans needing the widened bound |"
          << " worst error / plain bound |\n|---|---|---|---|---|---|---|\n";
        for (const Row& r : rows) {
            std::snprintf(b, sizeof b, "| %s | %zu | %zu | %.3f | %u | %zu | %.3g |\n", r.name.c_str(), r.spans, r.pixels,
                          r.worst, r.worst_n, r.widened, r.worst_plain);
            o << b;
        }
        return o.str();
    };
    std::printf("spec_shader (%s model, %s configuration, gamma rule %s) against the host in double precision with exact\n"
                "cos^n, %lld span(s) per n and kind, l = 0..%lld; bound per pixel: inside the epicentre host (q(n) + %.4g) +"
                " 2^-13,\nelsewhere C (a(n) + %.4g) + 2^-12; widened for ill-conditioned spans by the host's answers for"
                " end vectors\nmoved by 2^%d rad (sim/setup/setup_eval.h)\n\n",
                model.c_str(), setup_config_name(cfg), gamma.c_str(), per_n, max_len, 0.002 + co.setup_share,
                0.002 + co.setup_share, std::ilogb(co.eps));
    std::cout << table("kind of span", kinds) << "\n" << table("BRDF range", by_n);
    double worst = 0;
    size_t spans = 0, widened = 0;
    for (const Row& r : kinds) {
        worst = std::max(worst, r.worst);
        spans += r.spans;
        widened += r.widened;
    }
    std::printf("\nworst error / bound %.3f over %zu spans; %zu spans (%.2f %%) needed the widened bound\n", worst, spans,
                widened, 100.0 * double(widened) / double(spans));
    if (!json.empty()) {
        std::ostringstream o;
        o << "{\"config\": \"" << setup_config_name(cfg) << "\", \"gamma\": \"" << gamma << "\", \"share\": " << co.setup_share << ", \"eps_log2\": " << std::ilogb(co.eps)
          << ", \"worst\": " << worst << ", \"spans\": " << spans << ", \"widened\": " << widened << ", \"kinds\": [";
        for (size_t i = 0; i < kinds.size(); ++i)
            o << (i ? ", " : "") << "{\"name\": \"" << kinds[i].name << "\", \"worst\": " << kinds[i].worst
              << ", \"widened\": " << kinds[i].widened << ", \"spans\": " << kinds[i].spans << "}";
        o << "]}\n";
        std::ofstream os(json + ".tmp");
        os << o.str();
        os.close();
        if (!os || std::rename((json + ".tmp").c_str(), json.c_str()) != 0) {
            std::remove((json + ".tmp").c_str());
            throw render::InputError("cannot write " + json);
        }
    }
    if (worst > 1.0) std::printf("NOTE: a pixel exceeds its bound (worst error / bound %.3f)\n", worst);
    return 0;
}

}  // namespace spec
