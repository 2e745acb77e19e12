// The frame stores (boards/common/frame_store.v: 16-bit words with nibble enables, the UP5K's SPRAM;
// frame_store_packed.v: 36-bit words of three pixels, read-modify-write, the ECP5's block RAM) against one
// definition: a pixel array where commands are applied in order, pixel writes and line clears, and each fetch
// of a 4-pixel group returns {blue, green, red} words, nibble k the colour of pixel 4g + k. Random commands
// and fetches at random times (a fetch as soon as the last one is done, often), on a 64 x 48 buffer. A command
// is held until taken (AXI4-Stream): frame_store takes it with its last write and keeps no copy of it.
#include <gtest/gtest.h>

#include <array>
#include <random>
#include <vector>

#include "Vframe_store.h"
#include "Vframe_store_packed.h"
#include "board_dut.h"

namespace {

constexpr int kW = 64, kH = 48;
constexpr uint32_t kBg = 0x111;

// A command's pixels: one pixel, or line y (clear)
struct Cmd {
    bool clear = false;
    uint32_t arg = 0;
    bool touches(int group) const {
        return clear ? (4 * group) / kW == int(arg) : int(arg) / 4 == group;
    }
};

template <class V>
void store_matches_definition(uint32_t seed) {
    BoardDut<V> d;
    std::vector<uint32_t> px(size_t(kW) * kH, 0);
    std::mt19937 rng(seed);
    d->rst_n = 0;
    d->cmd_valid = 0;
    d->fetch = 0;
    d.tick();
    d->rst_n = 1;
    d.tick();
    int cleared = 0, commands = 0, fetched = 0, overlapped = 0;
    int pending = -1;               // the group being fetched
    bool busy_seen = false;
    Cmd inflight;                   // the last command taken (frame_store_packed: in progress while cmd_ready is
                                    // low; frame_store takes a command with its last write)
    Cmd c;                          // the command offered (held until taken, AXI4-Stream)
    bool offer = false;
    uint32_t colour = 0;
    std::array<uint32_t, 4> expect{};
    for (int cyc = 0; cyc < 400000 && (cleared < kH || commands < 6000 || fetched < 3000); ++cyc) {
        // a command: a clear of every line first (the memory starts undefined), then mostly pixel writes;
        // never one that touches the group being fetched (the definition would not say which value it sees)
        if (!offer) {
            c.clear = cleared < kH || rng() % 40 == 0;
            c.arg = c.clear ? uint32_t(cleared < kH ? cleared : int(rng() % kH)) : rng() % uint32_t(kW * kH);
            colour = rng() & 0xfff;
            offer = (rng() % 3) != 0 && !(pending >= 0 && c.touches(pending));
            if (offer) {
                if (c.clear) {
                    for (int x = 0; x < kW; ++x) px[size_t(c.arg) * kW + size_t(x)] = kBg;
                    if (cleared < kH) ++cleared;
                } else {
                    px[c.arg] = colour;
                }
                ++commands;
            }
        }
        d->cmd_clear = c.clear;
        d->cmd_arg = c.arg;
        d->cmd_rgb = colour;
        d->cmd_valid = offer;
        d->eval();
        const bool took = offer && d->cmd_ready;
        // a fetch (once every line is cleared) of a group no command in progress or offered touches
        bool fetch = false;
        if (cleared == kH && pending < 0 && !d->fetch_busy && (rng() % 4) == 0) {
            const int g = int(rng() % uint32_t(kW * kH / 4));
            const bool in_progress = !d->cmd_ready;
            if (!(in_progress && inflight.touches(g)) && !(offer && c.touches(g))) {
                pending = g;
                d->fetch_group = uint32_t(g);
                for (int k = 0; k < 4; ++k) expect[size_t(k)] = px[size_t(4 * g + k)];
                fetch = true;
                if (in_progress || offer) ++overlapped;
            }
        }
        d->fetch = fetch;
        d.tick();
        if (took) {
            inflight = c;
            offer = false;
        }
        d->cmd_valid = 0;
        d->fetch = 0;
        if (d->fetch_busy) busy_seen = true;
        if (d->group_valid) {
            ASSERT_GE(pending, 0) << "a group nobody fetched, cycle " << cyc;
            const uint64_t g = d->group;
            for (int k = 0; k < 4; ++k) {
                const uint32_t r = uint32_t(g >> (4 * k)) & 15u, gr = uint32_t(g >> (16 + 4 * k)) & 15u,
                               b = uint32_t(g >> (32 + 4 * k)) & 15u;
                ASSERT_EQ((r << 8) | (gr << 4) | b, expect[size_t(k)])
                    << "group " << pending << " pixel " << k << ", cycle " << cyc;
            }
            pending = -1;
            ++fetched;
        }
    }
    EXPECT_EQ(cleared, kH);
    EXPECT_GE(commands, 6000);
    EXPECT_GE(fetched, 3000);
    EXPECT_GT(overlapped, 500);    // fetches while a command was being applied
    EXPECT_TRUE(busy_seen);
}

}  // namespace

TEST(BoardFrameStore, NibbleStoreMatchesDefinition) { store_matches_definition<Vframe_store>(3); }
TEST(BoardFrameStore, PackedStoreMatchesDefinition) { store_matches_definition<Vframe_store_packed>(4); }
