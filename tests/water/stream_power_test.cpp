#include "water/stream_power.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <gtest/gtest.h>

#include "test_util.hpp"
#include "water/erode.hpp"
#include "water/flow.hpp"
#include "water/neighbours.hpp"
#include "water/water_test_util.hpp"

namespace sansui::water {
namespace {

/// Relative error of the slope to the receiver against the analytic steady state
/// S = (U/K)^(1/n) A^(-m/n) (every D8 path is a 1-D river profile), worst over all land cells.
double worst_steady_state_error(const Heightfield& h, const StreamPowerParams& p) {
  const FlowRouting flow = route_flow(h, {});
  double worst = 0.0;
  for (int y = 1; y + 1 < h.height(); ++y)
    for (int x = 1; x + 1 < h.width(); ++x) {
      const CellIndex i = y * h.width() + x, r = flow.receiver.data()[i];
      const double length = h.cell_size_m * ((r % h.width() != x && r / h.width() != y) ? std::sqrt(2.0) : 1.0);
      const double slope = (static_cast<double>(h.data()[i]) - h.data()[r]) / length;
      const double expected = std::pow(p.uplift_m_per_yr / p.erodibility, 1.0 / p.slope_exponent) *
                              std::pow(flow.area_m2.data()[i], -p.area_exponent / p.slope_exponent);
      worst = std::max(worst, std::abs(slope / expected - 1.0));
    }
  return worst;
}

StreamPowerParams steady_params(double n) {
  StreamPowerParams p;
  p.erodibility = 1e-5;
  p.area_exponent = 0.45;
  p.slope_exponent = n;
  p.uplift_m_per_yr = 1e-3;
  p.diffusivity_m2_per_yr = 0.0;
  p.deposition = 0.0;
  p.time_step_yr = 1e5;
  p.steps = 400;
  return p;
}

TEST(StreamPower, ImplicitSolverReachesTheAnalyticSteadyProfile) {
  Heightfield start = test::random_heights(41, 31, 3, 100);
  for (float& z : start.values()) z *= 0.01f;  // 0 to 1 m of noise
  start.cell_size_m = 100.0;
  const StreamPowerParams p = steady_params(1.0);
  const ErosionResult result = erode_stream_power(start, p);
  EXPECT_LT(worst_steady_state_error(result.heights, p), 0.01);
}

TEST(StreamPower, NewtonSolverReachesTheSteadyProfileForSlopeExponentTwo) {
  Heightfield start = test::random_heights(25, 21, 4, 100);
  for (float& z : start.values()) z *= 0.01f;
  start.cell_size_m = 100.0;
  StreamPowerParams p = steady_params(2.0);
  p.erodibility = 1e-6;
  const ErosionResult result = erode_stream_power(start, p);
  EXPECT_LT(worst_steady_state_error(result.heights, p), 0.01);
}

TEST(StreamPower, MassBalanceHoldsToOnePartPerMillion) {
  Heightfield h = test::midpoint_terrain(65, 30.0, 8);
  StreamPowerParams p;
  p.uplift_m_per_yr = 1e-3;
  p.erodibility = 1e-4;
  p.deposition = 1.0;
  p.diffusivity_m2_per_yr = 0.0;
  p.time_step_yr = 2e3;
  Grid<float> eroded(65, 65, 0.0f), deposited(65, 65, 0.0f);
  for (int step = 0; step < 5; ++step) {
    const Heightfield before = h;
    const ErosionBudget budget = stream_power_step(h, p, nullptr, eroded, deposited);
    ASSERT_GT(budget.eroded_m3, 0.0);
    ASSERT_GT(budget.deposited_m3, 0.0);
    const double balance = budget.eroded_m3 - budget.deposited_m3 - budget.sediment_out_m3;
    EXPECT_LT(std::abs(balance), 1e-6 * budget.eroded_m3) << "step " << step;
    // The same from the heights themselves: what the land lost beyond its uplift.
    double lost = 0.0;
    for (int y = 1; y < 64; ++y)
      for (int x = 1; x < 64; ++x) lost += (static_cast<double>(before(x, y)) + p.uplift_m_per_yr * p.time_step_yr - h(x, y)) * 900.0;
    EXPECT_LT(std::abs(lost - budget.sediment_out_m3), 1e-6 * budget.eroded_m3) << "step " << step;
  }
}

TEST(StreamPower, LakesTrapSediment) {
  // A slope rising to the south with a closed hollow at its foot: the rivers above carry their
  // sediment into the hollow's lake, which fills from below.
  Heightfield h(33, 33, 0.0f, 50.0);
  for (int y = 0; y < 33; ++y)
    for (int x = 0; x < 33; ++x)
      h(x, y) = static_cast<float>(4.0 * y + 0.5 * std::abs(x - 16) - 30.0 * std::max(0.0, 1.0 - std::hypot(x - 16.0, y - 8.0) / 3.0));
  StreamPowerParams p;
  p.erodibility = 1e-4, p.uplift_m_per_yr = 0.0, p.diffusivity_m2_per_yr = 0.0, p.time_step_yr = 1e3, p.steps = 3;
  const ErosionResult result = erode_stream_power(h, p);
  EXPECT_GT(result.deposited_m(16, 8), 0.0f);
  EXPECT_GT(result.heights(16, 8), h(16, 8));
}

TEST(StreamPower, SameBytesWithOneAndTwoThreads) {
  const Heightfield h = test::midpoint_terrain(129, 30.0, 9);
  StreamPowerParams p;
  p.sea_level_m = 0.0;
  p.steps = 4;
  p.diffusivity_m2_per_yr = 0.5;
  const auto run = [&] {
    const ErosionResult r = erode_stream_power(h, p);
    return sansui::test::fnv1a(r.heights.values()) ^ sansui::test::fnv1a(r.eroded_m.values()) ^ sansui::test::fnv1a(r.deposited_m.values());
  };
  test::expect_same_bytes_with_one_and_two_threads(run);
}

TEST(StreamPower, AWorkspaceKeptAcrossStepsGivesTheSameBytes) {
  // The steps of a run keep their working memory, and the first takes the routing the response
  // time left in it: the same bytes as steps that start afresh.
  const Heightfield start = test::midpoint_terrain(129, 10.0, 5);
  StreamPowerParams p;
  p.sea_level_m = 0.0;
  const auto run = [&](bool kept) {
    StreamPowerWorkspace workspace;
    const StreamPowerParams staged = params_for_stage(start, p, ErosionStage::mature, quiet_context(), 2, kept ? &workspace : nullptr);
    Heightfield h = start;
    Grid<float> eroded(h.width(), h.height(), 0.0f), deposited(h.width(), h.height(), 0.0f);
    for (int step = 0; step < 3; ++step) {
      if (kept)
        stream_power_step(h, staged, nullptr, eroded, deposited, workspace, quiet_context(), step == 0 ? &workspace.flow : nullptr);
      else
        stream_power_step(h, staged, nullptr, eroded, deposited);
    }
    return sansui::test::fnv1a(std::as_const(h).values()) ^ sansui::test::fnv1a(std::as_const(eroded).values()) ^
           sansui::test::fnv1a(std::as_const(deposited).values());
  };
  EXPECT_EQ(run(true), run(false));
}

TEST(StreamPower, AStepRoutesItsHeightsUnlessGivenTheirRouting) {
  // The workspace holds the routing of `a`; a step on `b` routes `b` unless given a routing, and
  // a routing of another size is refused, never read past its end.
  const Heightfield a = test::midpoint_terrain(65, 10.0, 1), b = test::midpoint_terrain(65, 10.0, 2);
  StreamPowerParams p;
  p.sea_level_m = 0.0;
  p.diffusivity_m2_per_yr = 0.01;
  StreamPowerWorkspace workspace;
  (void)response_time_yr(a, p, quiet_context(), &workspace);
  Heightfield kept = b, fresh = b;
  Grid<float> e1(65, 65, 0.0f), d1(65, 65, 0.0f), e2(65, 65, 0.0f), d2(65, 65, 0.0f);
  stream_power_step(kept, p, nullptr, e1, d1, workspace);
  stream_power_step(fresh, p, nullptr, e2, d2);
  EXPECT_EQ(sansui::test::fnv1a(std::as_const(kept).values()), sansui::test::fnv1a(std::as_const(fresh).values()));
  const FlowRouting other = route_flow(test::midpoint_terrain(33, 10.0, 1), Outlets{0.0});
  EXPECT_THROW(stream_power_step(kept, p, nullptr, e1, d1, workspace, quiet_context(), &other), std::logic_error);
}

TEST(Erosion, AStageRoutesTheHeightsOnceForTheResponseTimeAndTheFirstStep) {
  // erode() with a stage gives the bytes of the stage's parameters found first and then the
  // erosion with them (which routes the first step's heights again).
  const Heightfield start = test::midpoint_terrain(129, 10.0, 3);
  ErosionChainParams chain;
  chain.fluvial.sea_level_m = 0.0;
  chain.fluvial.steps = 3;
  for (int model : {1, 2, 3}) {
    ErosionChainParams staged = chain;
    staged.fluvial = params_for_stage(start, chain.fluvial, ErosionStage::young, quiet_context(), model);
    const ErosionResult once = erode(start, chain, ErosionStage::young, quiet_context(), model);
    const ErosionResult twice = erode(start, staged, quiet_context(), model);
    EXPECT_EQ(test::hash_of(once.heights), test::hash_of(twice.heights)) << "model " << model;
    EXPECT_EQ(sansui::test::fnv1a(std::as_const(once.eroded_m).values()), sansui::test::fnv1a(std::as_const(twice.eroded_m).values()));
  }
}

/// The mean gradient of the cells above `sea_m`, centred differences inside the grid.
double mean_land_gradient(const Heightfield& h, double sea_m) {
  double sum = 0.0;
  int count = 0;
  for (int y = 1; y + 1 < h.height(); ++y)
    for (int x = 1; x + 1 < h.width(); ++x) {
      if (h(x, y) <= sea_m) continue;
      const double gx = (h(x + 1, y) - h(x - 1, y)) / (2.0 * h.cell_size_m), gy = (h(x, y + 1) - h(x, y - 1)) / (2.0 * h.cell_size_m);
      sum += std::hypot(gx, gy), ++count;
    }
  return count > 0 ? sum / count : 0.0;
}

TEST(Erosion, ModelThreePutsBackOnlyTheRoughnessTheErosionTookAway) {
  // With no stream power (the stage `original`), droplets alone touch the land: model 3 leaves it
  // about as steep as it was, where model 2 put its whole fine roughness back on top of itself
  // (issue 48: 18.6 % of the land steeper than 45 degrees, against 3.5 % before).
  const Heightfield start = test::midpoint_terrain(257, 10.0, 5);
  ErosionChainParams chain;
  chain.fluvial.sea_level_m = 0.0;
  chain.fluvial.steps = 0;
  const double before = mean_land_gradient(start, 0.0);
  const double doubled = mean_land_gradient(erode(start, chain, quiet_context(), 2).heights, 0.0);
  const double kept = mean_land_gradient(erode(start, chain, quiet_context(), 3).heights, 0.0);
  EXPECT_GT(doubled, 1.15 * before);
  EXPECT_NEAR(kept, before, 0.05 * before);
  // After a real erosion most of the roughness is gone either way, and model 3 puts back less of
  // it, never more than was there.
  chain.fluvial.steps = 4;
  const double eroded_2 = mean_land_gradient(erode(start, chain, ErosionStage::mature, quiet_context(), 2).heights, 0.0);
  const double eroded_3 = mean_land_gradient(erode(start, chain, ErosionStage::mature, quiet_context(), 3).heights, 0.0);
  EXPECT_LT(eroded_3, eroded_2);
  EXPECT_LT(eroded_2, before);
}

TEST(HillslopeDiffusion, StableAtAnyStepWithoutNewExtremes) {
  Heightfield h(41, 41, 0.0f, 10.0);
  h(20, 20) = 100.0f;
  h(21, 20) = -50.0f;
  const double total_before = 50.0 * 100.0;
  for (double years : {1.0, 1e3, 1e7}) {
    Heightfield d = h;
    const double out = diffuse_hillslopes(d, 0.01, years, std::nullopt);
    for (float z : d.values()) {
      EXPECT_LE(z, 100.0f);
      EXPECT_GE(z, -50.0f);
    }
    double total = 0.0;
    for (float z : d.values()) total += z * 100.0;
    EXPECT_NEAR(total + out, total_before, 1e-3 * total_before) << years;
    if (years == 1.0) {
      EXPECT_LT(d(20, 20), 100.0f);
    }
  }
}

TEST(StreamPower, StagesAreLongerErosionTimes) {
  const Heightfield h = test::midpoint_terrain(65, 30.0, 10);
  StreamPowerParams p;
  const double tau = response_time_yr(h, p);
  EXPECT_GT(tau, 0.0);
  EXPECT_TRUE(std::isfinite(tau));
  double previous = 0.0;
  for (ErosionStage stage : {ErosionStage::young, ErosionStage::mature, ErosionStage::old, ErosionStage::peneplain}) {
    const StreamPowerParams staged = params_for_stage(h, p, stage);
    const double time = staged.time_step_yr * staged.steps;
    EXPECT_NEAR(time, stage_response_times(stage) * tau, 1e-9 * time);
    EXPECT_GT(time, previous);
    previous = time;
  }
}

TEST(StreamPower, BadValuesAreRejectedByName) {
  const Heightfield h(9, 9, 0.0f);
  const auto message = [&](auto change) {
    StreamPowerParams p;
    change(p);
    return sansui::test::message_of([&] { erode_stream_power(h, p); });
  };
  EXPECT_NE(message([](StreamPowerParams& p) { p.erodibility = -1; }).find("erosion.erodibility"), std::string::npos);
  EXPECT_NE(message([](StreamPowerParams& p) { p.area_exponent = std::numeric_limits<double>::quiet_NaN(); }).find("erosion.area_exponent"),
            std::string::npos);
  EXPECT_NE(message([](StreamPowerParams& p) { p.slope_exponent = -1; }).find("erosion.slope_exponent"), std::string::npos);
  EXPECT_NE(message([](StreamPowerParams& p) { p.uplift_m_per_yr = -1e-3; }).find("erosion.uplift"), std::string::npos);
  EXPECT_NE(
      message([](StreamPowerParams& p) { p.diffusivity_m2_per_yr = std::numeric_limits<double>::infinity(); }).find("erosion.diffusivity"),
      std::string::npos);
  EXPECT_NE(message([](StreamPowerParams& p) { p.time_step_yr = -5; }).find("erosion.time_step"), std::string::npos);
  const Grid<float> wrong(8, 9, 0.0f);
  EXPECT_NE(sansui::test::message_of([&] { erode_stream_power(h, StreamPowerParams{}, &wrong); }).find("uplift map is 8x9"),
            std::string::npos);
}

TEST(StreamPower, UpliftMapRaisesOnlyWhereItIsSet) {
  const Heightfield h(17, 17, 0.0f, 100.0);
  Grid<float> uplift(17, 17, 0.0f);
  uplift(8, 8) = 1e-3f;
  StreamPowerParams p;
  p.steps = 1, p.time_step_yr = 1e4, p.diffusivity_m2_per_yr = 0.0, p.erodibility = 0.0;
  const ErosionResult r = erode_stream_power(h, p, &uplift);
  EXPECT_NEAR(r.heights(8, 8), 10.0f, 1e-4f);
  EXPECT_NEAR(r.heights(4, 4), 0.0f, 1e-6f);  // only float rounding of the uplifted cell's volume moves on
}

}  // namespace
}  // namespace sansui::water
