// setup_sched.h - the setup program (setup_program.h) mapped onto the machine of rtl/spec_setup_machine.v: every
// operation bound to a unit instance and given a start time in a modulo schedule of II clocks (a new span every
// II clocks, several in flight), every value given a place in the banks of the ports that read it, and the
// microcode that makes the machine do it. docs/setup.md describes the machine.
//
// The machine's contract (rtl/spec_setup_machine.v implements it, SetupMachineSim below simulates it):
//   - a slot counter tau counts 0 .. II-1; the span counter S grows by one when tau returns to 0. The span that
//     starts there has time 0 in that clock; an operation of span s at time t issues in the clock where
//     tau = t mod II and S - s = t div II (its "stage").
//   - every input port of every unit has a bank: a RAM with one write and one read port. An operation reads its
//     operands from its unit's banks (or a constant of the port) in its issue clock; its result leaves the unit
//     LAT clocks later and is written, in that clock, into the bank of every port that reads it. A bank address
//     is {slot, (S - stage) mod LMAX}: a value keeps its slot for one span in LMAX, so it must be read within
//     LMAX * II clocks of its write.
//   - the IDOT unit reads the beat of span S - stage from a buffer of LIN beats instead of banks.
//   - the finish stage reads the program's results (SetupField order) from the OUT bank, field j at time
//     T_FIN + j, and writes the descriptor.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "setup_program.h"

namespace spec {

// Clocks from an operation's issue to its result, per unit (the RTL's pipelines; docs/setup.md).
struct SetupLatency {
    int lat[kSetupUnitTypes];
};
SetupLatency setup_latency(const SetupFormat& sf);
constexpr int kSetupLin = 2;      // beats in the IDOT unit's buffer: IDOT operations run in stage 0 or 1

// One unit instance (global index: IDOT instances first, then MUL, ADD, EFU, MISC; then the OUT pseudo-unit).
struct SetupUnitRef {
    SetupUnit type;
    int inst;
};

struct SetupBank {
    int unit = 0;                  // global unit index (the OUT pseudo-unit: the finish's bank)
    int port = 0;                  // 0: a, 1: b, 2: c (MISC's SEL condition: only "not zero" is kept)
    std::vector<int> sources;      // global unit indices that write into it
    std::vector<Fp> consts;        // constants the port reads instead of the bank
    int slots = 0;                 // values a span keeps in it at once (address = {slot, span mod LMAX})
};

struct SetupSchedule {
    int ii = 0;
    int lmax_log2 = 0;             // LMAX = 2^lmax_log2
    int t_fin = 0;                 // the finish reads field j of span s at time t_fin + j
    int latency = 0;               // clocks from a span's time 0 to its descriptor in the finish's output register
    int units = 0;                 // global unit count (the OUT pseudo-unit excluded)
    std::vector<SetupUnitRef> unit;          // by global index
    std::vector<int> unit_first;             // first global index of each type
    std::vector<SetupBank> banks;
    std::vector<int> bank_of;                // (global unit) * 3 + port -> bank index, -1: none
    int out_unit = 0;                        // global index of the OUT pseudo-unit (= units)

    // per node (program order)
    std::vector<int> t;                      // issue time, -1 for constants
    std::vector<int> inst;                   // global unit index
    std::vector<std::array<int, 3>> src;     // operand on port j: bank slot (>= 0) or -1 - constant index
    std::vector<char> swapped;               // a commutative operation's operands a, b on ports 1, 0
    std::vector<int> out_slot;               // OUT bank slot per SetupField

    // utilisation, for the reports
    std::vector<int> ops_per_unit;           // by global unit
    int max_sources = 0, max_slots = 0;
};

// Throws std::runtime_error when no schedule exists within the machine's max_ii (or 4 * the least bound).
SetupSchedule setup_schedule(const SetupFormat& sf, const SetupProgram& p);
std::string setup_schedule_report(const SetupFormat& sf, const SetupProgram& p, const SetupSchedule& s);

// ---- the microcode ---------------------------------------------------------------------------------------------
// Field layout of one microcode word (one per slot); every width and offset is also in setup_params.vh.
struct SetupUcodeLayout {
    int w = 0;                       // word width
    // per global unit: issue bit, op field, scale field; per port: read address, stage, const select, neg, abs
    std::vector<int> go, op, scale;
    std::vector<std::array<int, 3>> addr, stage, csel, neg, absb;
    // per bank: write enable, source select, address, stage
    std::vector<int> we, wsrc, waddr, wstage;
    int op_w = 0, scale_w = 4, addr_w = 0, csel_w = 0, wsrc_w = 0, stage_w = 0;
};
SetupUcodeLayout setup_ucode_layout(const SetupFormat& sf, const SetupSchedule& s);
// The II words, each as little-endian 64-bit chunks of layout.w bits.
std::vector<std::vector<uint64_t>> setup_ucode(const SetupFormat& sf, const SetupProgram& p, const SetupSchedule& s,
                                               const SetupUcodeLayout& lay);

// ---- a cycle-level simulation of the machine running the microcode (the generator's self-check, and the
// reference for the RTL's internal timing) -----------------------------------------------------------------------
class SetupMachineSim {
public:
    SetupMachineSim(const SetupFormat& sf, const SetupProgram& p, const SetupTables& t, const SetupSchedule& s);
    // Runs the beats through the machine back to back (one span every II clocks) and returns each span's results
    // as the finish stage reads them (SetupField order).
    std::vector<std::array<Fp, SO_COUNT>> run(const std::vector<SetupBeat>& beats);
    // After run: span 0's value of every node as the machine computed it (a node's issue clock is its time t).
    const std::vector<Fp>& trace() const { return trace_; }

private:
    const SetupFormat& sf_;
    const SetupProgram& p_;
    const SetupTables& t_;
    const SetupSchedule& s_;
    SetupUcodeLayout lay_;
    std::vector<std::vector<uint64_t>> uc_;
    std::vector<Fp> trace_;
};

}  // namespace spec
