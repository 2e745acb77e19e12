// parallax.h - companion paper C (seeds/002): iterative parallax mapping, its variants, and the baselines it
// has to beat, all in double precision against the exact intersection of the view ray with the height field.
//
// Tangent space, texture units: the polygon is the plane z = 0 and the relief is z = s h(u, v), h in [0, 1]
// (a height map, heightmap.h), s the relief depth. V = (Vu, Vv, Vh) is the unit vector from the fragment
// P0 = (u0, v0) toward the viewer (Vh > 0). Going back toward the viewer, the ray through P0 is
// P(t) = P0 + t (Vu, Vv) at height t Vh; it enters the slab at T = s / Vh. The visible relief point is the
// intersection nearest the viewer: the largest root t* of f(t) = t Vh - s h(P(t)) in [0, T]. f(0) <= 0 and
// f(T) >= 0 are known without a fetch (h in [0, 1]).
//
// Every method returns t (and P(t)) after a budget of height fetches; docs/methods.md measures them at equal
// budgets. "Divisions" counts the per-fragment divisions (1 / Vh) beyond the fetches.
//   kaneko      t = s h(P0) / Vh                                     1 fetch, 1 division   (Kaneko 2001)
//   welsh       t = s h(P0): offset limiting                         1 fetch               (Welsh 2004)
//   welsh_bias  offset limiting from the slab's mid-plane (Welsh's scale and bias -s/2: the polygon taken as
//               the relief's mean level): t_m = T / 2, t = t_m + s (h(P(t_m)) - 1/2)   1 fetch, 1 division
//   paper       the paper's (4)-(5) from the polygon, t_0 = 0: t <- t + d, d = s h(P(t)) - t Vh, until
//               |d| <= threshold or the budget is spent             (Romanyuk et al. 2012)
//   paper_top   the same iteration started at the slab's top, t_0 = T: it descends, and where f' < 1 it
//               cannot pass the first hit                            1 division
//   premecz     iterative parallax mapping with slope information (Premecz 2006), as the survey the paper
//               cites ([4], Szirmay-Kalos and Umenhoffer) writes it: from the top, t <- t + d N_z with N the
//               relief's unit normal at P(t) (a normal map's texel, read with the height)      1 division
//   hybrid      a linear search of L = max(1, budget / 4) steps brackets the first hit, then paper_top's
//               iteration from the bracket's upper end, kept inside the bracket                1 division
//   steep       steep parallax mapping (McGuire and McGuire 2005): a linear search of `budget` samples
//               t_k = T (1 - k / (budget + 1)); the first sample below the relief              1 division
//   pom         parallax occlusion mapping (Tatarchuk 2006): the same search, then the secant through the
//               bracket's two samples (no fetch; the bracket's midpoint when an end is T or 0, not sampled)
//   relief      relief mapping (Policarpo et al. 2005): a linear search of up to budget - B samples, then
//               bisections for the rest of the budget (at least B = min(6, budget / 3)); the final
//               bracket's midpoint
//   interval    interval mapping (Risser et al. 2005): the same split, secant (regula falsi) steps
// None of the searches samples t = T or t = 0, where the sign of f is known.
#pragma once

#include <string>
#include <vector>

#include "heightmap.h"

namespace spec {
namespace methods {

struct View {
    double u = 0, v = 0, h = 1;  // unit, h > 0
};
View view_from_angles(double elevation_deg, double azimuth_deg);

struct Hit {
    double u = 0, v = 0;  // texture coordinates found
    double t = 0;         // ray parameter
    int fetches = 0;      // height fetches spent
    bool converged = true;  // iterations: stopped by the threshold (false: the budget ran out)
};

enum class Pm { none, kaneko, welsh, welsh_bias, paper, paper_top, premecz, hybrid, steep, pom, relief, interval, exact };

struct PmInfo {
    const char* key;    // the name on the command line and in tables
    const char* label;  // a short description
    int divisions;      // per fragment, besides the fetches
    bool iterative;     // stops early at the threshold (mean fetches below the budget)
};
const PmInfo& pm_info(Pm m);
// By key; throws std::invalid_argument for an unknown one.
Pm pm_from_key(const std::string& key);
// The methods measured at equal fetch budgets, in table order.
std::vector<Pm> pm_compared();

// One fragment by method m with at most `budget` height fetches (>= 1; ignored by kaneko, welsh, welsh_bias,
// exact, none); the iterations stop at |d| <= threshold.
Hit run_method(Pm m, const HeightMap& hm, double s, double u0, double v0, const View& V, int budget, double threshold);

Hit kaneko(const HeightMap& m, double s, double u0, double v0, const View& V);
Hit welsh(const HeightMap& m, double s, double u0, double v0, const View& V);
Hit welsh_bias(const HeightMap& m, double s, double u0, double v0, const View& V);
// The paper's iteration from ray height t0 Vh (t0 = 0: the paper; t0 = s / Vh: from the top). max_iter = 1
// from t0 = 0 is Welsh's offset limiting.
Hit iterative(const HeightMap& m, double s, double u0, double v0, const View& V, double threshold, int max_iter,
              double t0 = 0);
Hit premecz(const HeightMap& m, double s, double u0, double v0, const View& V, double threshold, int max_iter);
Hit hybrid(const HeightMap& m, double s, double u0, double v0, const View& V, double threshold, int budget);
// Linear search of up to `steps` samples (it stops at the first below the relief), then `refine` bisections
// (secant = false) or regula falsi steps (secant = true), more when spend_all: the samples the linear search
// did not use. The answer: the first sample below the relief, the final bracket's midpoint, or the secant
// through it.
enum class SearchEnd { first_below, midpoint, secant };
Hit search(const HeightMap& m, double s, double u0, double v0, const View& V, int steps, int refine, bool secant,
           SearchEnd end, bool spend_all = false);
// The exact nearest intersection (largest root of f), by walking the texel cells from the top of the relief
// slab down and solving the quadratic in each.
Hit exact(const HeightMap& m, double s, double u0, double v0, const View& V);
// Brute force for the tests: f sampled at `samples` points from t_max down, the first sign change refined by
// bisection.
Hit dense_search(const HeightMap& m, double s, double u0, double v0, const View& V, int samples);
// f(t) = t Vh - s h(P(t))
double f_at(const HeightMap& m, double s, double u0, double v0, const View& V, double t);

}  // namespace methods
}  // namespace spec
