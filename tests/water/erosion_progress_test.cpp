#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "water/erode.hpp"
#include "water/water_test_util.hpp"

namespace sansui::water {
namespace {

TEST(ErosionProgress, OneStageThatOnlyGoesForwardToTheEnd) {
  // The whole default erosion reports as one stage, "erosion", whose fraction never goes back
  // and ends at 1: a bar's remaining time is its elapsed time scaled by what is left.
  const Heightfield h = test::midpoint_terrain(129, 10.0, 3);
  std::vector<std::string> stages;
  std::vector<double> fractions;
  Context context;
  context.on_progress = [&](std::string_view stage, double fraction) {
    stages.emplace_back(stage);
    fractions.push_back(fraction);
  };
  ErosionChainParams params;
  params.fluvial.sea_level_m = 0.0;
  (void)erode(h, params, context);
  ASSERT_GE(fractions.size(), 9u);  // at least one report a step
  for (const std::string& stage : stages) EXPECT_EQ(stage, "erosion");
  for (std::size_t k = 1; k < fractions.size(); ++k) EXPECT_GE(fractions[k], fractions[k - 1]) << k;
  EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
}

TEST(ErosionProgress, PartsOfAContextReportInTheWholesFractions) {
  std::vector<double> fractions;
  Context whole;
  whole.on_progress = [&](std::string_view stage, double fraction) {
    EXPECT_EQ(stage, "whole");
    fractions.push_back(fraction);
  };
  const Context part = part_of(whole, "whole", 0.25, 0.75);
  part.report("anything", 0.0);
  part.report("anything", 0.5);
  part.report("anything", 1.0);
  EXPECT_EQ(fractions, (std::vector<double>{0.25, 0.5, 0.75}));
  EXPECT_FALSE(static_cast<bool>(part_of(quiet_context(), "none", 0.0, 1.0).on_progress));
}

TEST(ErosionProgress, TheEstimateGrowsWithTheWork) {
  // The default erosion of 8193^2 cells is announced (over 30 s); of 257^2, not.
  ErosionChainParams params;
  EXPECT_GT(estimated_erosion_seconds(std::size_t{8193} * 8193, params, true), 30.0);
  EXPECT_LT(estimated_erosion_seconds(std::size_t{257} * 257, params, true), 1.0);
  ErosionChainParams more = params;
  more.fluvial.steps *= 2;
  EXPECT_GT(estimated_erosion_seconds(1 << 20, more), estimated_erosion_seconds(1 << 20, params));
}

}  // namespace
}  // namespace sansui::water
