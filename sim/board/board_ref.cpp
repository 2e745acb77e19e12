// board_ref.cpp - the double-precision rendering of the board scene (see board_ref.h).
#include "board_ref.h"

#include <algorithm>
#include <cmath>

namespace spec {
namespace board {

Frame ref_frame(const BoardScene& s, unsigned f, int out_bits, int y0, int y1, std::vector<uint8_t>* covered) {
    Frame fr;
    fr.w = s.mode.h_active;
    fr.h = s.mode.v_active;
    fr.out_bits = out_bits;
    const double scale = double((1u << out_bits) - 1u);
    std::array<uint32_t, 3> bg{};
    for (int c = 0; c < 3; ++c) bg[size_t(c)] = uint32_t(std::lround(s.background[c] * scale));
    fr.px.assign(size_t(fr.w) * size_t(fr.h), bg);
    if (covered) covered->assign(fr.px.size(), 0);
    const double e = s.elevation_deg * M_PI / 180.0;
    const double t = 2.0 * M_PI * double(f % unsigned(s.frames_per_turn)) / double(s.frames_per_turn);
    const double L[3] = {std::sin(e) * std::cos(t), std::sin(e) * std::sin(t), std::cos(e)};
    const double H[3] = {std::sin(e / 2) * std::cos(t), std::sin(e / 2) * std::sin(t), std::cos(e / 2)};
    for (int y = y0; y < y1; ++y) {
        for (const Sphere& sp : s.spheres) {
            const double dy = y + 0.5 - sp.cy;
            for (int x = sp.cx - sp.r; x < sp.cx + sp.r; ++x) {
                const int64_t DX = 2 * int64_t(x) + 1 - 2 * int64_t(sp.cx), DY = 2 * int64_t(y) + 1 - 2 * int64_t(sp.cy);
                if (DX * DX + DY * DY > 4 * int64_t(sp.r) * sp.r) continue;
                const double dx = x + 0.5 - sp.cx;
                const double z = std::sqrt(std::max(0.0, double(sp.r) * sp.r - dx * dx - dy * dy));
                const double N[3] = {dx / sp.r, dy / sp.r, z / sp.r};
                const double nl = std::max(0.0, N[0] * L[0] + N[1] * L[1] + N[2] * L[2]);
                const double nh = std::max(0.0, N[0] * H[0] + N[1] * H[1] + N[2] * H[2]);
                const double spec = sp.ks * std::pow(nh, double(sp.n));
                std::array<uint32_t, 3> rgb{};
                for (int c = 0; c < 3; ++c) {
                    const double v = std::min(1.0, (sp.ka + sp.kd * nl) * sp.color[c] + spec);
                    rgb[size_t(c)] = uint32_t(std::lround(v * scale));
                }
                const size_t i = size_t(y) * size_t(fr.w) + size_t(x);
                fr.px[i] = rgb;
                if (covered) (*covered)[i] = 1;
            }
        }
    }
    return fr;
}

render::Image to_image(const Frame& f) {
    render::Image img(f.w, f.h);
    const uint32_t mx = (1u << f.out_bits) - 1u;
    for (size_t i = 0; i < f.px.size(); ++i) {
        for (int c = 0; c < 3; ++c) img.rgb[i * 3 + size_t(c)] = uint8_t((f.px[i][size_t(c)] * 255u + mx / 2) / mx);
    }
    return img;
}

}  // namespace board
}  // namespace spec
