// tmds.h - DVI 1.0 TMDS coding in C++: the encoder as tmds_encoder.v implements it (the model the RTL is
// tested against), the decoder a receiver uses, and a receiver that recovers pixels from the four lanes'
// bit streams (docs/boards.md, "ULX3S: from pins back to pixels").
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace spec {
namespace board {

class TmdsEncoder {
public:
    // The next character: data (de) or the control character of c = {c1, c0}.
    uint32_t encode(bool de, unsigned c, uint8_t d);
    int disparity() const { return cnt_; }
    void set_disparity(int cnt) { cnt_ = cnt; }
    void reset() { cnt_ = 0; }

private:
    int cnt_ = 0;
};

struct TmdsChar {
    bool is_control = false;  // one of the four control characters
    unsigned c = 0;           // its {c1, c0}
    bool valid = true;        // false: neither a control character nor what the encoder makes of any byte
    uint8_t d = 0;            // the data byte (data characters)
};
TmdsChar tmds_decode(uint32_t q);

// A lane's 10-bit characters from its bit stream (bit 0 of a character first), once the character boundary
// is known: the receiver looks for the offset at which the blue lane shows a run of control characters
// (DVI receivers align on the blanking's control characters the same way).
// Returns -1 if no offset shows `run` consecutive control characters.
int find_alignment(const std::vector<uint8_t>& blue_bits, int run);
std::vector<uint32_t> to_chars(const std::vector<uint8_t>& bits, int offset);

}  // namespace board
}  // namespace spec
