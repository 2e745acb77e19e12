// plots.h - the patent's Fig. 5 and Fig. 9 redrawn from the analysis, as PNG through gnuplot.
#pragma once

#include <string>

namespace spec {
namespace render {

// Writes fig5.png (worst relative error in the epicentre against n: the prototype's cos^2(sqrt(n/2) d),
// the patent's cos^k(sqrt(n/k) d) with the Fig. 10 rule, and the fixed-point core), fig9.png (relative
// error against the angle, n = 1, 3, 10, 100, 1000, for both approximations), their .dat tables and the
// gnuplot script into dir. Returns a short text report. Throws std::runtime_error (no gnuplot, cannot write).
std::string make_plots(const std::string& dir);

}  // namespace render
}  // namespace spec
