// pow_table.h - pow mode's log table (ROM 9) and exp2 table (ROM 12): where an angle falls in the log table, the
// table's grid, its words, and the exp2 table (docs/pow.md). The generator writes the images from these functions
// and the bit-exact model reads the angle's position with them, so the two cannot drift.
#pragma once

#include <cstdint>
#include <vector>

#include "spec_format.h"

namespace spec {

// Where register 8's angle falls in the log table (rtl/spec_powpath.v, stages 1 to 3 + pow_seg_w):
//   a = |angle|; past: a > K (K = pi/2 in the angle format: the BRDF is 0 there, for n >= 1);
//   side 0 (a < 1 rad): t = a; side 1 (1 rad <= a <= K): t = K - a; t < 2^ang_frac either way;
//   segment: the octave of t, [2^(ang_frac-1-j), 2^(ang_frac-j)) in angle LSBs for j = 0 .. 2^seg_w - 2, or
//   2^seg_w - 1 for t below the last octave; index: the pow_idx_w bits of t after its leading one (in the last
//   segment, the bits where the last octave's are); frac: the pow_frac bits after them (truncated).
struct PowPos {
    bool past = false;
    int side = 0;
    int seg = 0;
    uint32_t idx = 0;
    uint32_t frac = 0;
    uint32_t address(const Format& f) const {   // ROM 9's address {side, segment, index}
        return (uint32_t(side) << (f.pow_seg_w + f.pow_idx_w)) | (uint32_t(seg) << f.pow_idx_w) | idx;
    }
};
PowPos pow_position(const Format& f, int64_t angle);

// t (angle LSBs) of entry idx of a segment (idx = 2^pow_idx_w: the point after its last entry, which is the next
// segment's first) and, for a position, the t its truncated fraction stands for.
double pow_grid_t(const Format& f, int seg, double idx);
// The angle (radians) that t stands for on a side, and the log table's function there: -log2 cos(angle).
double pow_angle(const Format& f, int side, double t);
double pow_log_exact(const Format& f, int side, double t);
// The value ROM 9's entry 0 of side 1's last segment holds instead of -log2 cos(K) (nearly infinite there):
// the next entry's plus kPowEdgeStep, which keeps the interpolated cos within 0.144 of the last step's width of
// the true one for n = 1 (the minimax of 2^-(c (1 - f)) against f; docs/pow.md).
constexpr double kPowEdgeStep = 2.8;
// The table's function at entry idx of (side, seg), with that replacement: what the words interpolate.
double pow_log_entry(const Format& f, int side, int seg, double idx);

// One word of ROM 9 in pow mode: L = (val +- step * frac / 2^pow_frac) * 2^-(pow_xb + shift).
struct PowWord {
    uint32_t val = 0;    // pow_val_w bits
    uint32_t dlt = 0;    // |step|: the next entry's value minus this one's, in this entry's scale (pow_dlt_w bits)
    bool neg = false;    // the step is negative (side 1: L falls as t grows)
    uint32_t shift = 0;  // pow_sh_w bits
    uint64_t pack(const Format& f) const;
    static PowWord unpack(const Format& f, uint64_t w);
};
// ROM 9 in pow mode: 2^rom9_aw() words (std::out_of_range when a value, step or shift does not fit its field).
std::vector<uint64_t> make_pow_log(const Format& f);
// ROM 12 in pow mode: 2^tbl_aw words, round(2^(-p / 2^tbl_aw) * 2^tbl_frac) for position p (1.0 exact at p = 0),
// with interp: | (word_p - word_(p+1)) << tbl_dw (the point after the last is 2^-1).
std::vector<uint64_t> make_pow_exp(const Format& f);

}  // namespace spec
