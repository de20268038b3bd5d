// A sum of doubles whose bytes do not depend on the order of its terms: each term is cut once to
// a fixed point of 2^-40 (about 1e-12) in a 128-bit integer, and integers add exactly in any
// order. Terms are held within +-2^48 (2.8e14), so 2^38 of them (a world of 262145^2 cells)
// cannot overflow.
// For sums over a world cut into tiles, which every tiling and rank count must give alike.
#pragma once

#include <algorithm>
#include <cmath>

namespace sansui {

class ExactSum {
  __extension__ typedef __int128 Wide;  // GCC and Clang have it; __extension__ keeps -Wpedantic quiet

 public:
  /// Adds `term` (held within +-2^48).
  void add(double term) {
    const double scaled = std::ldexp(std::clamp(term, -limit, limit), fraction_bits);  // exact: a power of two
    total_ += static_cast<Wide>(scaled);                                               // toward zero, the same everywhere
  }
  void add(const ExactSum& other) { total_ += other.total_; }
  double value() const { return std::ldexp(static_cast<double>(total_), -fraction_bits); }
  /// The raw fixed-point total as two 64-bit halves (high, low), to send between ranks.
  void to_halves(long long& high, unsigned long long& low) const {
    high = static_cast<long long>(total_ >> 64), low = static_cast<unsigned long long>(total_);
  }
  static ExactSum from_halves(long long high, unsigned long long low) {
    ExactSum s;
    s.total_ = (static_cast<Wide>(high) << 64) | static_cast<Wide>(low);
    return s;
  }

 private:
  static constexpr int fraction_bits = 40;
  static constexpr double limit = 281474976710656.0;  // 2^48
  Wide total_ = 0;
};

}  // namespace sansui
