// cmd_tuned.h - specsim compare and specsim tables (issue 7, docs/tuned.md): patent mode against tuned mode
// and the prototype, and other table sets and table sizes against ROM bits (parse -> compute -> report).
#pragma once

#include <string>
#include <vector>

#include "analysis.h"

namespace spec {

// The BRDF ranges of the tables (the last two: every n of the patent's range, every n the core takes).
struct BrdfRange {
    const char* name;
    unsigned lo, hi;
};
extern const BrdfRange kBrdfRanges[7];

struct Worst {
    double v = 0;
    unsigned n = 0;
};
// The largest v[n] over n = lo..hi and its n.
Worst worst_of(const std::vector<double>& v, unsigned lo, unsigned hi);

// A format for the table set with ROM 9's integer bits and (with interpolation) ROM 12's step field as narrow
// as the contents allow, so that ROM bits compare fairly. The patent's set keeps its 18-bit UQ3.15 word.
Format sized_format(Mode mode, const std::vector<int>& tables, int tbl_aw, bool interp);

// compare: the columns (prototype, patent, tuned, pow) in double precision and through the bit-exact core, and the
// per-material table (MaterialLut, the PICA200's way) in double and in its fixed point, on the same spans.
struct CompareColumn {
    std::string name;
    Format f;
    ErrorTable dbl;
    CoreErrors core;
};
std::vector<CompareColumn> compare_modes(uint32_t points, uint32_t epi_points);
struct CompareLut {
    CoreErrors dbl, fixed;
};
CompareLut compare_lut(uint32_t points, uint32_t epi_points);
// ROM bits of a column's core: ROM 9 and ROM 12 (the words the generator writes)
double rom_bits(const Format& f);

// tables: one row per (table set, mode, ROM 12 size, interpolation).
struct TablesRow {
    std::vector<int> tables;
    Mode mode;
    int aw;
    bool interp;
    Format f;
    double rom9_bits, rom12_bits;
    Worst q, core_rel, core_abs;
};
struct TablesPlan {
    std::vector<std::vector<int>> sets;
    std::vector<int> plain, interp;   // ROM 12 sizes (address bits) without and with interpolation
    uint32_t points = 2000, epi = 500;
};
TablesPlan tables_plan(bool quick);
std::vector<TablesRow> tables_rows(const TablesPlan& p);

}  // namespace spec
