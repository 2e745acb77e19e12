// setup_rom.h - the files setuprom writes for a setup configuration (rom/gen/setup_format.h): the EFU's and the
// finish stage's tables, the machine's microcode, and the parameter headers that carry the schedule's shape to the
// RTL (setup_params.vh) and to C++ (setup_params.h). docs/setup.md describes each.
#pragma once

#include <string>

#include "setup_format.h"
#include "setup_program.h"
#include "setup_sched.h"

namespace spec {

// Everything a configuration generates, computed once.
struct SetupBuild {
    SetupFormat sf;
    SetupProgram prog;
    SetupTables tab;
    SetupSchedule sched;
    SetupUcodeLayout lay;
    std::vector<std::vector<uint64_t>> ucode;
    explicit SetupBuild(const SetupFormat& f);
};

std::string setup_verilog_header(const SetupBuild& b, const std::string& rom_dir);
std::string setup_cpp_header(const SetupBuild& b);
std::string setup_efu_image(const SetupBuild& b);     // the EFU's table ROM
std::string setup_exp2_image(const SetupBuild& b);    // the finish stage's exp2 table
std::string setup_ucode_image(const SetupBuild& b);   // II microcode words

// Writes setup_efu.hex, setup_exp2.hex, setup_ucode.hex, setup_params.vh and setup_params.h into dir (each through
// a temporary file and a rename). rom_dir: the directory name the header's default file parameters use.
// Before writing, the schedule runs spans through the cycle-level machine (SetupMachineSim) against the program;
// a difference is an internal error and nothing is written.
void write_setup_all(const SetupFormat& sf, const std::string& dir, const std::string& rom_dir);

}  // namespace spec
