// cmd_vectors.h - specsim vectors: test vectors from the bit-exact model for the Icarus testbenches
// (tests/iverilog/tb_*.v), parse -> compute -> report (write).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "spec_model.h"

namespace spec {

struct VectorsOptions {
    std::string out;
    uint32_t spans = 200;
    uint64_t seed = 1;
    Format fmt;   // --mode, --tables
};
VectorsOptions parse_vectors(int argc, char** argv);

// The spans: the first 1024 visit n = 37 s mod 1024 (every n), later ones a random n; C random, l = 0..23,
// angles within two epicentres (plus 0.1 rad).
std::vector<SpanRegs> vector_spans(const Model& m, uint32_t count, uint64_t seed);
// The vector file: a comment line, the count, then per span c, dzeta, zeta0, n, len and the model's pixels,
// one 32-bit hex word a line.
std::string vectors_text(const Model& m, const std::vector<SpanRegs>& spans);

}  // namespace spec
