// opcount.h - a double that counts the arithmetic done with it: operation counts that reproduce (the tables of
// docs/methods.md), where timings would not. Set a tally with OpScope; every +, -, *, /, sqrt and comparison
// of Counted values on this thread is added to it.
#pragma once

#include <cmath>
#include <cstdint>

namespace spec {
namespace methods {

struct OpTally {
    uint64_t add = 0, mul = 0, div = 0, sqrt = 0, cmp = 0;
    OpTally& operator+=(const OpTally& o) {
        add += o.add, mul += o.mul, div += o.div, sqrt += o.sqrt, cmp += o.cmp;
        return *this;
    }
};

inline thread_local OpTally* g_op_tally = nullptr;

// Counts into `t` while alive.
class OpScope {
public:
    explicit OpScope(OpTally* t) : prev_(g_op_tally) { g_op_tally = t; }
    ~OpScope() { g_op_tally = prev_; }
    OpScope(const OpScope&) = delete;
    OpScope& operator=(const OpScope&) = delete;

private:
    OpTally* prev_;
};

class Counted {
public:
    Counted() = default;
    Counted(double v) : v_(v) {}  // NOLINT: implicit, as a double literal would be
    double value() const { return v_; }

    friend Counted operator+(Counted a, Counted b) { return tick(&OpTally::add), Counted(a.v_ + b.v_); }
    friend Counted operator-(Counted a, Counted b) { return tick(&OpTally::add), Counted(a.v_ - b.v_); }
    friend Counted operator*(Counted a, Counted b) { return tick(&OpTally::mul), Counted(a.v_ * b.v_); }
    friend Counted operator/(Counted a, Counted b) { return tick(&OpTally::div), Counted(a.v_ / b.v_); }
    friend Counted operator-(Counted a) { return Counted(-a.v_); }  // a sign flip: free
    friend bool operator<(Counted a, Counted b) { return tick(&OpTally::cmp), a.v_ < b.v_; }
    friend bool operator>(Counted a, Counted b) { return tick(&OpTally::cmp), a.v_ > b.v_; }
    friend bool operator<=(Counted a, Counted b) { return tick(&OpTally::cmp), a.v_ <= b.v_; }
    friend bool operator>=(Counted a, Counted b) { return tick(&OpTally::cmp), a.v_ >= b.v_; }
    friend Counted sqrt(Counted a) { return tick(&OpTally::sqrt), Counted(std::sqrt(a.v_)); }
    friend Counted fabs(Counted a) { return Counted(std::fabs(a.v_)); }  // a sign bit: free

private:
    static void tick(uint64_t OpTally::*f) {
        if (g_op_tally) ++(g_op_tally->*f);
    }
    double v_ = 0;
};

}  // namespace methods
}  // namespace spec
