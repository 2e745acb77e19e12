// parallax_eval.cpp - the measurements of companion paper C (parallax_eval.h).
#include "parallax_eval.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace spec {
namespace methods {

namespace {
double texels(const HeightMap& m, double u, double v, const Hit& ref) { return std::hypot(u - ref.u, v - ref.v) * m.size; }
}  // namespace

ErrSummary summarize(std::vector<double> err, const std::vector<int>& fetches, const std::vector<uint8_t>& conv) {
    ErrSummary s;
    s.n = err.size();
    if (err.empty()) return s;
    std::sort(err.begin(), err.end());
    double sum = 0;
    uint64_t m1 = 0, m10 = 0;
    for (double e : err) {
        sum += e;
        m1 += e > 1.0;
        m10 += e >= 10.0;
    }
    const double n = double(err.size());
    auto q = [&](double p) { return err[std::min(err.size() - 1, size_t(p * n))]; };
    s.mean = sum / n;
    s.p95 = q(0.95);
    s.p99 = q(0.99);
    s.max = err.back();
    s.miss1 = double(m1) / n;
    s.miss10 = double(m10) / n;
    double f = 0;
    for (int x : fetches) f += x;
    s.fetches = fetches.empty() ? 0 : f / double(fetches.size());
    double c = 0;
    for (uint8_t x : conv) c += x;
    s.converged = conv.empty() ? 0 : c / double(conv.size());
    return s;
}

std::vector<Fragment> fragments(const HeightMap& m, const ParallaxSetup& p, double elevation_deg) {
    std::vector<Fragment> out;
    out.reserve(size_t(p.azimuths) * size_t(p.grid) * size_t(p.grid));
    for (int az = 0; az < p.azimuths; ++az) {
        const View V = view_from_angles(elevation_deg, 360.0 * az / p.azimuths + 10.0);
        for (int gy = 0; gy < p.grid; ++gy) {
            for (int gx = 0; gx < p.grid; ++gx) {
                Fragment f;
                f.u0 = (gx + 0.37) / p.grid;
                f.v0 = (gy + 0.61) / p.grid;
                f.V = V;
                f.ref = exact(m, p.depth, f.u0, f.v0, V);
                out.push_back(f);
            }
        }
    }
    return out;
}

const SweepCell& Sweep::at(const std::string& map, double elevation, Pm m, int budget) const {
    for (const auto& c : cells) {
        if (c.map == map && c.elevation == elevation && c.method == m && c.budget == budget) return c;
    }
    throw std::out_of_range("no sweep cell for " + map + ", " + pm_info(m).key);
}

Sweep run_sweep(const std::vector<HeightMap>& maps, const ParallaxSetup& p, const std::vector<double>& elevations,
                const std::vector<int>& budgets, const std::vector<Pm>& methods) {
    Sweep sw;
    for (const auto& m : maps) sw.maps.push_back(m.name);
    sw.maps.push_back("all");
    sw.elevations = elevations;
    sw.budgets = budgets;
    sw.methods = methods;
    const double thr = p.thr();
    for (double el : elevations) {
        std::vector<std::vector<Fragment>> frags;
        for (const auto& m : maps) frags.push_back(fragments(m, p, el));
        for (Pm pm : methods) {
            for (int b : budgets) {
                std::vector<double> all_e;
                std::vector<int> all_f;
                std::vector<uint8_t> all_c;
                for (size_t k = 0; k < maps.size(); ++k) {
                    std::vector<double> e;
                    std::vector<int> f;
                    std::vector<uint8_t> c;
                    for (const Fragment& fr : frags[k]) {
                        const Hit h = run_method(pm, maps[k], p.depth, fr.u0, fr.v0, fr.V, b, thr);
                        e.push_back(texels(maps[k], h.u, h.v, fr.ref));
                        f.push_back(h.fetches);
                        c.push_back(h.converged);
                    }
                    all_e.insert(all_e.end(), e.begin(), e.end());
                    all_f.insert(all_f.end(), f.begin(), f.end());
                    all_c.insert(all_c.end(), c.begin(), c.end());
                    sw.cells.push_back({maps[k].name, el, pm, b, summarize(std::move(e), f, c)});
                }
                sw.cells.push_back({"all", el, pm, b, summarize(std::move(all_e), all_f, all_c)});
            }
        }
    }
    return sw;
}

std::vector<IterRow> iteration_rows(const std::vector<HeightMap>& maps, const ParallaxSetup& p,
                                    const std::vector<double>& elevations, int cap) {
    std::vector<IterRow> rows;
    const double thr = p.thr();
    const StepFormat fmt;
    for (const auto& m : maps) {
        const FixedParallax fp = make_fixed(m, p.depth, fmt);
        const HeightFetch fetch = [&](int64_t u, int64_t v) { return fp.lookup(u, v); };
        const uint64_t thr_fixed = uint64_t(to_fixed(thr, fmt.f));
        for (double el : elevations) {
            IterRow r;
            r.map = m.name;
            r.elevation = el;
            std::vector<double> ek, ew, ep, et, epf, etf;
            std::vector<int> fp_n, ft_n, fpf_n, ftf_n;
            std::vector<uint8_t> cp, ct, cpf, ctf;
            uint64_t other_p = 0, other_t = 0, bad = 0;
            const std::vector<Fragment> frags = fragments(m, p, el);
            for (const Fragment& fr : frags) {
                const Hit k = kaneko(m, p.depth, fr.u0, fr.v0, fr.V);
                const Hit w = welsh(m, p.depth, fr.u0, fr.v0, fr.V);
                const Hit ip = iterative(m, p.depth, fr.u0, fr.v0, fr.V, thr, cap);
                const Hit it = iterative(m, p.depth, fr.u0, fr.v0, fr.V, thr, cap, p.depth / fr.V.h);
                ek.push_back(texels(m, k.u, k.v, fr.ref));
                ew.push_back(texels(m, w.u, w.v, fr.ref));
                ep.push_back(texels(m, ip.u, ip.v, fr.ref));
                et.push_back(texels(m, it.u, it.v, fr.ref));
                fp_n.push_back(ip.fetches);
                ft_n.push_back(it.fetches);
                cp.push_back(ip.converged);
                ct.push_back(it.converged);
                other_p += ip.converged && ep.back() > 1.0;
                other_t += it.converged && et.back() > 1.0;
                double gu, gv;
                m.gradient(fr.ref.u, fr.ref.v, &gu, &gv);
                const double slope = fr.V.h - p.depth * (gu * fr.V.u + gv * fr.V.v);
                bad += !(slope > 0 && slope < 2);
                for (int top = 0; top < 2; ++top) {
                    const IterJob j = job_for(fmt, p.depth, fr.u0, fr.v0, fr.V.u, fr.V.v, fr.V.h, top, thr_fixed,
                                              uint32_t(cap));
                    const FixedHit fh = iterate_fixed(fmt, j, fetch);
                    const double e = texels(m, std::ldexp(double(fh.u), -fmt.f), std::ldexp(double(fh.v), -fmt.f), fr.ref);
                    (top ? etf : epf).push_back(e);
                    (top ? ftf_n : fpf_n).push_back(fh.iterations);
                    (top ? ctf : cpf).push_back(fh.converged);
                }
            }
            const double n = double(frags.size());
            r.kaneko = summarize(ek, {}, {});
            r.welsh = summarize(ew, {}, {});
            r.paper = summarize(ep, fp_n, cp);
            r.top = summarize(et, ft_n, ct);
            r.paper_fixed = summarize(epf, fpf_n, cpf);
            r.top_fixed = summarize(etf, ftf_n, ctf);
            r.paper_other = double(other_p) / n;
            r.top_other = double(other_t) / n;
            r.bad_slope = double(bad) / n;
            rows.push_back(r);
        }
    }
    return rows;
}

}  // namespace methods
}  // namespace spec
