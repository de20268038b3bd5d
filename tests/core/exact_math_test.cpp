#include "core/exact_math.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace sansui {
namespace {

TEST(ExactExp2, MatchesLibmWithinAFewUlps) {
  for (double x = -60.0; x <= 60.0; x += 0.0371) {
    const double expected = std::exp2(x);
    EXPECT_NEAR(exact_exp2(x), expected, 1e-15 * expected) << x;  // a few ulps
  }
  EXPECT_EQ(exact_exp2(0.0), 1.0);
  EXPECT_EQ(exact_exp2(-1.0), 0.5);
}

}  // namespace
}  // namespace sansui
