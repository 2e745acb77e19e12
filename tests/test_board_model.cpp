// The reference designs' C++ side (sim/board/): scene rules, the model's pieces, the reference, capture.
#include <gtest/gtest.h>

#include "board_model.h"
#include "board_scene.h"

using namespace spec::board;

TEST(BoardModel, IsqrtIsTheFloorOfTheRoot) {
    for (uint64_t x = 0; x < 100000; ++x) {
        const uint64_t r = isqrt(x);
        ASSERT_LE(r * r, x);
        ASSERT_GT((r + 1) * (r + 1), x);
    }
    EXPECT_EQ(isqrt((uint64_t(1) << 62) - 1), (uint64_t(1) << 31) - 1);
}

#include "board_capture.h"

// The raster check finds a wrong sync width, a missing line and a wrong polarity in a synthetic pixel stream.
TEST(BoardCapture, TimingCheckFindsWrongRasters) {
    const VideoMode m = video_mode("128x96");
    auto stream = [&](int hsync_width, bool hpos, int drop_line) {
        VideoCapture cap(8);
        uint64_t t = 0;
        for (int f = 0; f < 3; ++f) {
            for (int v = 0; v < m.v_total(); ++v) {
                if (f == 1 && v == drop_line) continue;
                for (int h = 0; h < m.h_total(); ++h) {
                    PixelSample s;
                    s.t_ps = t += 40000;
                    const int hs0 = m.h_active + m.h_fp;
                    const bool hs = h >= hs0 && h < hs0 + hsync_width;
                    // vsync switches with the hsync leading edge: lines counted from there
                    const int vl = (h >= hs0) ? (v + 1) % m.v_total() : v;
                    const bool vs = vl >= m.v_active + m.v_fp && vl < m.v_active + m.v_fp + m.v_sync;
                    s.hs = hs == hpos;
                    s.vs = !vs;
                    s.de = h < m.h_active && v < m.v_active;
                    cap.push(s);
                }
            }
        }
        return check_timing(cap.measure(), m, 25.0).ok;
    };
    EXPECT_TRUE(stream(m.h_sync, true == m.h_pos, -1));
    EXPECT_FALSE(stream(m.h_sync + 1, m.h_pos, -1));
    EXPECT_FALSE(stream(m.h_sync, !m.h_pos, -1));
    EXPECT_FALSE(stream(m.h_sync, m.h_pos, 50));
}

// The scene rules: spheres apart and inside the picture.
TEST(BoardScene, RulesAreChecked) {
    BoardScene s = make_board_scene("640x480", 16);
    EXPECT_NO_THROW(check_scene(s));
    s.spheres[1].cx = s.spheres[0].cx + 10;
    EXPECT_THROW(check_scene(s), std::runtime_error);
    s = make_board_scene("640x480", 16);
    s.spheres[0].cx = 20;
    EXPECT_THROW(check_scene(s), std::runtime_error);
}
