#include "terrain/stage_filter.hpp"

#include <gtest/gtest.h>

namespace sansui::terrain {
namespace {

constexpr Stage all_stages[] = {Stage::original, Stage::young, Stage::mature, Stage::old, Stage::peneplain};

TEST(StageFilter, EveryDefaultFilterIsMonotone) {
  for (Stage stage : all_stages) {
    double previous = stage_filter(stage, 0.0, false);
    EXPECT_EQ(previous, 0.0) << stage_name(stage);
    for (double x = 0.001; x < 6.0; x += 0.001) {
      const double y = stage_filter(stage, x, false);
      EXPECT_GT(y, previous) << stage_name(stage) << " at " << x;
      previous = y;
    }
  }
}

TEST(StageFilter, DefaultFiltersAreContinuousAtOne) {
  for (Stage stage : all_stages) {
    const double below = stage_filter(stage, 1.0 - 1e-9, false);
    const double at = stage_filter(stage, 1.0, false);
    EXPECT_NEAR(below, at, 1e-8) << stage_name(stage);
  }
}

TEST(StageFilter, PaperExactReproducesThePrintedJump) {
  EXPECT_NEAR(stage_filter(Stage::old, 1.0 - 1e-12, true), 1.0, 1e-9);
  EXPECT_NEAR(stage_filter(Stage::old, 1.0, true), 1.0 / 1.3, 1e-12);
  EXPECT_NEAR(stage_filter(Stage::peneplain, 1.0, true), 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(stage_filter(Stage::peneplain, 0.5, true), 0.125, 1e-12);
  EXPECT_NEAR(stage_filter(Stage::old, 2.6, true), 2.0, 1e-12);
  // The default keeps the printed slope above 1.
  EXPECT_NEAR(stage_filter(Stage::old, 2.3, false), 2.0, 1e-12);
}

TEST(StageFilter, MatchesThePrintedPowers) {
  EXPECT_NEAR(stage_filter(Stage::original, 0.5, false), std::pow(0.5, 0.1), 1e-12);
  EXPECT_NEAR(stage_filter(Stage::young, 0.25, false), 0.5, 1e-12);
  EXPECT_EQ(stage_filter(Stage::mature, 3.5, false), 3.5);
}

TEST(StageFilter, LeavesTheSeaFloorAndAppliesInUnitsOfSigma) {
  Heightfield h(3, 1, 0.0f);
  h(0, 0) = -50.0f;         // under the sea
  h(1, 0) = 10.0f + 25.0f;  // x = 0.25
  h(2, 0) = 10.0f;          // at the coast
  apply_stage_filter(h, StageFilterParams{Stage::young, false, 10.0, 100.0});
  EXPECT_EQ(h(0, 0), -50.0f);
  EXPECT_FLOAT_EQ(h(1, 0), 10.0f + 50.0f);
  EXPECT_EQ(h(2, 0), 10.0f);
}

TEST(StageFilter, NamesRoundTrip) {
  for (Stage stage : all_stages) EXPECT_EQ(stage_from_name(stage_name(stage)), stage);
  EXPECT_FALSE(stage_from_name("teenage"));
}

}  // namespace
}  // namespace sansui::terrain
