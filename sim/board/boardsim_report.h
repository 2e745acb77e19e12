// boardsim_report.h - boardsim's output: tables on stdout, PNGs and a JSON summary.
#pragma once

#include <string>
#include <vector>

#include "boardsim_compute.h"

namespace spec {
namespace board {

void print_run(const RunReport& r);
// Frame PNGs (board, model, reference, error map x16), summary.json into r.opt.out_dir.
void write_run(const RunReport& r);
void print_split(const SplitOptions& o, const std::vector<SplitRow>& rows);

}  // namespace board
}  // namespace spec
