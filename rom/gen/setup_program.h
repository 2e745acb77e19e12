// setup_program.h - spec_setup's arithmetic as a dataflow program: the operations, their bit-exact evaluation
// (the model), and the one definition of the algorithm (build_setup_program) that the schedule
// (setup_sched.h) maps onto the machine. docs/setup.md derives the formulas.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "setup_format.h"
#include "setup_fp.h"

namespace spec {

enum class SetupOp : uint8_t {
    CONST,   // a constant (never scheduled: an immediate of the ports that read it)
    IDOT,    // exact integer product of beat fields, rounded to floating point (unit IDOT)
    FMUL,    // a * b                                  (unit MUL)
    FADD,    // a + b * 2^bscale                       (unit ADD)
    RSQRT,   // 1/sqrt(a), 0 for a <= 0                (unit EFU)
    RCP,     // 1/a, 0 for a = 0                       (unit EFU)
    ATANG,   // atan(|a|)/|a| for |a| in [0, 1] (1 at 0; |a| > 1 read as 1)   (unit EFU)
    LOG2,    // log2(a), -1024 for a <= 0              (unit EFU)
    CMPLT,   // a < b ? 1 : 0                          (unit MISC)
    SEL,     // a != 0 ? b : c                         (unit MISC)
    MIN,     // the smaller of a, b (signed)           (unit MISC)
    MAX,     // the larger                             (unit MISC)
};
enum class SetupUnit : uint8_t { IDOT = 0, MUL, ADD, EFU, MISC, COUNT, NONE };
constexpr int kSetupUnitTypes = static_cast<int>(SetupUnit::COUNT);
SetupUnit setup_op_unit(SetupOp o);
const char* setup_op_name(SetupOp o);
const char* setup_unit_name(SetupUnit u);
int setup_op_operands(SetupOp o);   // operands read from the machine's banks (IDOT: 0, it reads the beat)

// The IDOT unit: sum over j < 3 of sign_j * x_j * y_j on 16-bit beat fields, exact, then rounded to floating
// point and scaled by 2^scale.
enum class IdotMode : uint8_t { DOT, CRX, CRY, CRZ, COMP, SCALAR };
enum BeatVec : uint8_t { BV_N1 = 0, BV_N2, BV_H1, BV_H2, BV_PN, BV_COUNT };   // PN = N1 x e_k (the pre-stage's)
enum BeatScalar : uint8_t { BS_RULE = 0, BS_STRENGTH, BS_N, BS_L, BS_COUNT };

struct SetupRef {
    int id = -1;
    bool neg = false, abs = false;   // operand modifiers (abs first, then neg)
};

struct SetupNode {
    SetupOp op = SetupOp::CONST;
    SetupRef a, b, c;
    int scale = 0;        // the result times 2^scale (every operation but CONST)
    int bscale = 0;       // FADD: operand b times 2^bscale
    Fp k;                 // CONST
    IdotMode mode = IdotMode::DOT;
    uint8_t va = 0, vb = 0, comp = 0;   // IDOT: vectors (BeatVec), component (COMP) or field (BeatScalar)
};

// The values the finish stage (fixed-function: descriptor, flags) reads, in the order it reads them.
enum SetupField : int {
    SO_GAMMA_P = 0,   // the patent's gamma (flat test)
    SO_GAMMA,         // the chosen rule's gamma
    SO_LAMBDA,        // lambda, (-pi, pi]
    SO_DZETA,         // gamma / l
    SO_P_NF,          // -log2 C (p) of a span that is not flat
    SO_P_F,           // p of a flat span (A = cos theta1)
    SO_C1,            // cos theta1 (its sign: no highlight on a flat span)
    SO_OPC,           // 1 + N1.N2 (opposite normals)
    SO_OK,            // 1: the midpoint rule was used
    SO_COUNT
};
const char* setup_out_name(int o);

struct SetupProgram {
    std::vector<SetupNode> n;                 // topological order, every node live
    std::array<int, SO_COUNT> out{};          // node ids
    std::vector<std::pair<std::string, int>> probes;   // named intermediate values (tests, `specsim setup --trace`)
    int count(SetupUnit u) const;             // operations that unit type executes
};

// The algorithm, for a format (its thresholds and tolerances are constants of the program).
SetupProgram build_setup_program(const SetupFormat& sf);

// ---- evaluation ---------------------------------------------------------------------------------------------
// The EFU's tables: 2^t intervals, 2^t + 2 words of round(f * 2^tab_f); a read interpolates linearly.
struct SetupTable {
    int t = 0, r = 0, f = 0;
    std::vector<int64_t> w;
    int64_t at(uint64_t pos) const;   // pos: t + r fraction bits, 0 .. 2^(t+r)
};
struct SetupTables {
    SetupTable rsqrt_lo, rsqrt_hi, rcp, atang, log2, exp2;   // exp2: 2^-x on [0, 1) for the finish stage
};
SetupTables make_setup_tables(const SetupFormat& sf);
// The EFU's operations (bit-exact), the result times 2^k.
Fp setup_efu(const SetupFormat& sf, const SetupTables& t, SetupOp op, const Fp& x, int k = 0);

// The beat as the IDOT unit reads it: the vectors' 16-bit components (PN from the pre-stage) and the scalars.
struct SetupBeat {
    int32_t v[BV_COUNT][3] = {};
    int32_t s[BS_COUNT] = {};
};
int64_t setup_idot(const SetupNode& n, const SetupBeat& b);   // the exact integer

Fp setup_eval_node(const SetupFormat& sf, const SetupTables& t, const SetupNode& n, const std::vector<Fp>& v,
                   const SetupBeat& beat);
std::vector<Fp> setup_eval(const SetupFormat& sf, const SetupTables& t, const SetupProgram& p, const SetupBeat& beat);

}  // namespace spec
