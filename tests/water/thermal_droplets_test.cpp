#include <cmath>
#include <numbers>
#include <tuple>

#include <gtest/gtest.h>

#include "test_util.hpp"
#include "water/droplets.hpp"
#include "water/thermal.hpp"
#include "water/water_test_util.hpp"

namespace sansui::water {
namespace {

double steepest_step(const Heightfield& h) {
  double steepest = 0.0;
  for (int y = 0; y < h.height(); ++y)
    for (int x = 0; x + 1 < h.width(); ++x)
      steepest = std::max(steepest, std::abs(static_cast<double>(h(x + 1, y)) - h(x, y)) / h.cell_size_m);
  return steepest;
}

double total(const Heightfield& h) {
  double sum = 0.0;
  for (float z : h.values()) sum += z;
  return sum;
}

TEST(Thermal, SlopesRelaxTowardTheTalusAngleAndMassStays) {
  Heightfield h(33, 33, 0.0f, 1.0);
  h(16, 16) = 40.0f;  // a spike far steeper than the talus angle
  ThermalParams p;
  p.talus_angle_deg = 30.0;
  p.iterations = 400;
  const Heightfield eroded = erode_thermal(h, p);
  EXPECT_LT(eroded(16, 16), 20.0f);
  EXPECT_NEAR(total(eroded), total(h), 1e-3);
  EXPECT_LT(steepest_step(eroded), std::tan(30.0 * std::numbers::pi / 180.0) * 1.3);
}

TEST(Thermal, SameBytesWithOneAndTwoThreads) {
  const Heightfield h = test::midpoint_terrain(129, 5.0, 11);
  ThermalParams p;
  p.iterations = 10;
  test::expect_same_bytes_with_one_and_two_threads([&] { return test::hash_of(erode_thermal(h, p)); });
}

TEST(Droplets, SameBytesWithOneAndTwoThreads) {
  const Heightfield h = test::midpoint_terrain(129, 10.0, 12);
  DropletParams p;
  p.droplets = 20000;
  test::expect_same_bytes_with_one_and_two_threads([&] { return test::hash_of(erode_droplets(h, p)); });
}

TEST(Droplets, CarveChannelsAndDependOnTheSeed) {
  const Heightfield h = test::midpoint_terrain(129, 10.0, 13);
  DropletParams p;
  p.droplets = 30000;
  const Heightfield a = erode_droplets(h, p);
  p.seed = 2;
  const Heightfield b = erode_droplets(h, p);
  EXPECT_NE(test::hash_of(a), test::hash_of(b));
  int lowered = 0, raised = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    lowered += a.data()[i] < h.data()[i];
    raised += a.data()[i] > h.data()[i];
    ASSERT_TRUE(std::isfinite(a.data()[i]));
  }
  EXPECT_GT(lowered, 1000);
  EXPECT_GT(raised, 100);
  // Droplets only lose sediment off the map: the total never rises.
  EXPECT_LE(total(a), total(h) + 1e-2 * static_cast<double>(h.size()));
}

TEST(Droplets, SteepTerrainInMetresStaysWithinItsRelief) {
  // 2 km of relief on 10 m cells: steps of whole cells. Droplets that worked in raw cell units
  // carried hundreds of metres each and the terrain grew to +-600 km; now the relief only wears.
  // A small map crowded with droplets (12 per cell) once blew up to +-1e23 m: each droplet kept
  // its changes until it dried up, so one that rocked in a pit dug it deeper at every step.
  for (const auto& [size, scale, seed] : {std::tuple{257, 4.0f, 7}, std::tuple{129, 1.0f, 1}, std::tuple{129, 1.0f, 4}}) {
    Heightfield h = test::midpoint_terrain(size, 10.0, static_cast<std::uint64_t>(seed));
    for (float& v : h.values()) v *= scale;
    float low = h.values()[0], high = low;
    for (float v : h.values()) low = std::min(low, v), high = std::max(high, v);
    DropletParams p;
    p.droplets = 200000;
    const Heightfield eroded = erode_droplets(h, p);
    float eroded_low = eroded.values()[0], eroded_high = eroded_low;
    for (float v : eroded.values()) eroded_low = std::min(eroded_low, v), eroded_high = std::max(eroded_high, v);
    EXPECT_GE(eroded_low, low - 0.05f * (high - low)) << size << " seed " << seed;
    EXPECT_LE(eroded_high, high + 1e-3f) << size << " seed " << seed;
  }
}

TEST(Droplets, BadValuesAreRejectedByName) {
  const Heightfield h(9, 9, 0.0f);
  DropletParams p;
  p.droplets = -5;
  EXPECT_NE(sansui::test::message_of([&] { erode_droplets(h, p); }).find("droplets.droplets"), std::string::npos);
  ThermalParams t;
  t.talus_angle_deg = -3;
  EXPECT_NE(sansui::test::message_of([&] { erode_thermal(h, t); }).find("thermal.talus_angle"), std::string::npos);
  t.talus_angle_deg = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(sansui::test::message_of([&] { erode_thermal(h, t); }).find("thermal.talus_angle"), std::string::npos);
  Heightfield broken(9, 9, 0.0f);
  broken(4, 4) = std::numeric_limits<float>::infinity();
  EXPECT_NE(sansui::test::message_of([&] { erode_droplets(broken, DropletParams{}); }).find("not a finite number"), std::string::npos);
  EXPECT_NE(sansui::test::message_of([&] { erode_thermal(broken, ThermalParams{}); }).find("not a finite number"), std::string::npos);
}

}  // namespace
}  // namespace sansui::water
