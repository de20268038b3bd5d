// Elementary functions written with +, -, *, / only, so that values that feed random
// processes (e.g. the midpoint displacement scale 0.5^(H/2)) are the same bytes on every
// platform; libm's exp/pow differ in the last bit between implementations.
#pragma once

#include <cmath>

namespace sansui {

/// 2^x to within an ulp or two, identical everywhere. [Range: |x| < 1000]
inline double exact_exp2(double x) {
  const double whole = std::nearbyint(x);                 // exact; rounding mode is round-to-nearest
  const double t = (x - whole) * 0.69314718055994530942;  // |t| <= 0.35
  double term = 1.0, sum = 1.0;
  for (int k = 1; k <= 20; ++k) {  // Taylor series of e^t; 20 terms reach double precision
    term = term * t / k;
    sum += term;
  }
  return std::ldexp(sum, static_cast<int>(whole));
}

}  // namespace sansui
