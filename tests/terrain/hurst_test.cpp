#include "terrain/hurst.hpp"

#include <gtest/gtest.h>

#include "terrain/midpoint.hpp"

namespace sansui::terrain {
namespace {

class MeasuredHurst : public ::testing::TestWithParam<double> {};

TEST_P(MeasuredHurst, IsWithinATenthOfTheRequestedOne) {
  const double requested = GetParam();
  double sum = 0.0;
  const int seeds = 4;
  for (int seed = 1; seed <= seeds; ++seed) {
    MidpointParams params;
    params.seed = std::uint64_t(seed);
    params.hurst = requested;
    const Heightfield h = generate_midpoint(params, 1025);
    const VariogramFit fit = measure_hurst(h.view(), 2, 128);
    EXPECT_GT(fit.r_squared, 0.95);
    sum += fit.hurst;
  }
  EXPECT_NEAR(sum / seeds, requested, 0.1);
}

INSTANTIATE_TEST_SUITE_P(Hurst, MeasuredHurst, ::testing::Values(0.3, 0.5, 0.8));

}  // namespace
}  // namespace sansui::terrain
