// parallax_eval.h - companion paper C measured: texture-coordinate error against the exact intersection, per
// method, fetch budget, height map and camera elevation (`specsim parallax`, docs/methods.md; the verdict
// tests call these functions with the document's parameters).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "parallax.h"
#include "parallax_fixed.h"

namespace spec {
namespace methods {

// The error of a set of fragments, in texels (|(u', v') - exact| * map size).
struct ErrSummary {
    uint64_t n = 0;
    double mean = 0, p95 = 0, p99 = 0, max = 0;
    double miss1 = 0;    // share of fragments more than 1 texel off
    double miss10 = 0;   // share 10 texels or more off
    double fetches = 0;  // mean height fetches
    double converged = 0;  // share stopped by the threshold (iterations)
};
// Summarizes errors (and fetch counts, convergence flags: same length, or empty).
ErrSummary summarize(std::vector<double> err, const std::vector<int>& fetches, const std::vector<uint8_t>& conv);

struct ParallaxSetup {
    int map_size = 256;
    double depth = 0.05;     // s, texture units
    double threshold = 0;    // 0: depth / 512
    int grid = 24;           // fragments grid x grid per view
    int azimuths = 8;        // views per elevation, 360 / azimuths apart, from 10 degrees
    double thr() const { return threshold > 0 ? threshold : depth / 512; }
};

// The fragments of one map and elevation, with their exact intersections.
struct Fragment {
    double u0, v0;
    View V;
    Hit ref;
};
std::vector<Fragment> fragments(const HeightMap& m, const ParallaxSetup& p, double elevation_deg);

// Error against budget: one cell per map (and "all": the maps pooled), elevation, method, budget.
struct SweepCell {
    std::string map;
    double elevation = 0;
    Pm method = Pm::paper;
    int budget = 0;
    ErrSummary e;
};
struct Sweep {
    std::vector<std::string> maps;  // as given, then "all"
    std::vector<double> elevations;
    std::vector<int> budgets;
    std::vector<Pm> methods;
    std::vector<SweepCell> cells;
    const SweepCell& at(const std::string& map, double elevation, Pm m, int budget) const;  // throws if absent
};
Sweep run_sweep(const std::vector<HeightMap>& maps, const ParallaxSetup& p, const std::vector<double>& elevations,
                const std::vector<int>& budgets, const std::vector<Pm>& methods);

// The paper's iteration (from the polygon and from the top) in detail, per map and elevation, at one cap.
struct IterRow {
    std::string map;
    double elevation = 0;
    ErrSummary kaneko, welsh;
    ErrSummary paper, top;                 // double precision
    double paper_other = 0, top_other = 0;  // converged more than a texel from the nearest intersection
    double bad_slope = 0;                  // share with f'(t*) outside (0, 2): the iteration cannot converge there
    ErrSummary paper_fixed, top_fixed;     // rtl/parallax_iter.v's arithmetic (8-bit heights, nearest texel)
};
std::vector<IterRow> iteration_rows(const std::vector<HeightMap>& maps, const ParallaxSetup& p,
                                    const std::vector<double>& elevations, int cap);

}  // namespace methods
}  // namespace spec
