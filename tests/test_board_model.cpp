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
