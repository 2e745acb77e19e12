#include "stats.h"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace spec {
namespace render {

ImageStats compare(const Image& a, const Image& ref, const std::vector<uint8_t>& covered) {
    if (a.w != ref.w || a.h != ref.h) throw std::runtime_error("compare: images differ in size");
    if (covered.size() != size_t(a.w) * size_t(a.h)) throw std::runtime_error("compare: coverage mask size");
    ImageStats s;
    double sum_cov = 0, sum_sq = 0;
    for (int y = 0; y < a.h; ++y) {
        for (int x = 0; x < a.w; ++x) {
            const size_t p = size_t(y) * size_t(a.w) + size_t(x);
            int worst = 0;
            for (int c = 0; c < 3; ++c) {
                const int d = std::abs(int(a.at(x, y)[c]) - int(ref.at(x, y)[c]));
                worst = std::max(worst, d);
                sum_sq += double(d) * d;
                if (covered[p]) sum_cov += d;
            }
            if (covered[p]) ++s.covered;
            if (worst > 0) ++s.differing;
            if (worst > 4) ++s.over_4;
            if (worst > s.max_abs) {
                s.max_abs = worst;
                s.worst_x = x;
                s.worst_y = y;
            }
        }
    }
    s.mean_abs = s.covered ? sum_cov / (3.0 * double(s.covered)) : 0.0;
    const double mse = sum_sq / (3.0 * double(a.w) * double(a.h));
    s.psnr = mse > 0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : std::numeric_limits<double>::infinity();
    return s;
}

}  // namespace render
}  // namespace spec
