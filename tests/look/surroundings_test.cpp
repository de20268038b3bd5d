// The land around the terrain (look/surroundings.hpp): the grid's uneven axes, the seam with the
// terrain, and the same bytes for the same terrain.
#include "look/surroundings.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "terrain/midpoint.hpp"
#include "tests/test_util.hpp"

namespace sansui::look {
namespace {

Heightfield hills() {
  terrain::MidpointParams midpoint;
  midpoint.seed = 3;
  Heightfield heights = terrain::generate_midpoint(midpoint, 129);
  heights.cell_size_m = 50.0;
  return heights;
}

TEST(Surroundings, AxisSpansTheAreaEvenlyAndGrowsOutwardToItsReach) {
  const SurroundingsAxis axis = make_surroundings_axis(6400.0, 80e3, 513);
  EXPECT_NEAR(axis.position_m(axis.first_inside()), 0.0, 1e-6);
  EXPECT_NEAR(axis.position_m(axis.last_inside()), 6400.0, 1e-6);
  EXPECT_NEAR(axis.position_m(512), 3200.0 + 80e3, 1.0);
  EXPECT_NEAR(axis.position_m(0), 3200.0 - 80e3, 1.0);
  // Even inside; outside each step a little longer than the one before, starting from the
  // inside's step (no jump in spacing at the border).
  const double inside = axis.position_m(axis.first_inside() + 1) - axis.position_m(axis.first_inside());
  const double first_outside = axis.position_m(axis.last_inside() + 1) - axis.position_m(axis.last_inside());
  EXPECT_NEAR(first_outside / inside, 1.0, 0.1);
  for (int i = axis.last_inside() + 1; i < 512; ++i)
    EXPECT_GT(axis.position_m(i + 1) - axis.position_m(i), axis.position_m(i) - axis.position_m(i - 1)) << i;
  for (int i = 0; i < 513; i += 7) EXPECT_NEAR(axis.index_of(axis.position_m(i)), i, 1e-6) << i;
}

TEST(Surroundings, MeetTheTerrainAtItsBorderWithoutASeam) {
  const Heightfield area = hills();
  const Surroundings s = build_surroundings(area, 0.0, Beyond::land);
  ASSERT_FALSE(s.empty());
  // On the border the surroundings have the terrain's own heights; one step out, nearly the same.
  double largest_step = 0.0;
  for (int zi = s.z_axis.first_inside(); zi <= s.z_axis.last_inside(); ++zi) {
    const double z = s.z_axis.position_m(zi);
    const int row = static_cast<int>(std::lround(z / area.cell_size_m));
    if (std::abs(z - row * area.cell_size_m) > 1e-6) continue;  // border samples that fall on the area's own
    EXPECT_NEAR(s.heights(s.x_axis.first_inside(), zi), area(0, row), 1e-3);
    largest_step = std::max(largest_step, static_cast<double>(std::abs(s.heights(s.x_axis.first_inside() - 1, zi) - area(0, row))));
  }
  double relief = 0.0;
  for (float h : area.values()) relief = std::max(relief, std::abs(static_cast<double>(h)));
  EXPECT_LT(largest_step, 0.25 * relief);
  EXPECT_GE(s.reach_m, 80e3);
  // The mesh leaves the terrain's own cells to the terrain: no triangle has all corners inside.
  EXPECT_LT(s.indices.size(), 2u * 513u * 513u + 513u);
}

// Issue 49: land beyond keeps the terrain's character to the horizon: far out its relief is near
// the terrain's own (ranges continue its spectrum), not a plain (before: 0.27 of it).
TEST(Surroundings, LandFarOutIsAtLeastAsRoughAsTheTerrain) {
  const Heightfield area = hills();
  const Surroundings s = build_surroundings(area, 0.0, Beyond::land);
  const double size = (area.width() - 1) * area.cell_size_m;
  const auto deviation = [](const std::vector<double>& values) {
    double sum = 0.0, squares = 0.0;
    for (double v : values) sum += v, squares += v * v;
    const double mean = sum / static_cast<double>(values.size());
    return std::sqrt(std::max(squares / static_cast<double>(values.size()) - mean * mean, 0.0));
  };
  std::vector<double> terrain(area.values().begin(), area.values().end()), far;
  for (int zi = 0; zi < s.z_axis.samples; ++zi)
    for (int xi = 0; xi < s.x_axis.samples; ++xi) {
      const double x = s.x_axis.position_m(xi), z = s.z_axis.position_m(zi);
      const double d = std::hypot(x - std::clamp(x, 0.0, size), z - std::clamp(z, 0.0, size));
      if (d > 3.0 * size && d < 12.0 * size) far.push_back(s.heights(xi, zi));
    }
  ASSERT_GT(far.size(), 1000u);
  EXPECT_GE(deviation(far), 0.75 * deviation(terrain));
}

TEST(Surroundings, OpenSeaFallsBelowSeaLevelFarOut) {
  const Heightfield area = hills();
  const Surroundings s = build_surroundings(area, 0.0, Beyond::sea);
  int above = 0;
  for (int zi = 0; zi < 40; ++zi)
    for (int xi = 0; xi < s.x_axis.samples; ++xi) above += s.heights(xi, zi) > 0.0f ? 1 : 0;
  EXPECT_EQ(above, 0);
}

TEST(Surroundings, WithoutASeaStayAboveTheFloor) {
  const Heightfield area = hills();
  // The renderer's floor is the terrain's lowest point: a valley's mirror image reaches it.
  const float lowest = *std::ranges::min_element(area.values());
  const Surroundings s = build_surroundings(area, 0.0, Beyond::land, lowest);
  for (float h : s.heights.values()) ASSERT_GE(h, lowest);
}

TEST(Surroundings, SameTerrainSameBytes) {
  const Heightfield area = hills();
  const Surroundings a = build_surroundings(area, 0.0, Beyond::land);
  const Surroundings b = build_surroundings(area, 0.0, Beyond::land);
  EXPECT_EQ(test::fnv1a(a.heights.data(), a.heights.size() * sizeof(float)),
            test::fnv1a(b.heights.data(), b.heights.size() * sizeof(float)));
  EXPECT_EQ(surroundings_shading_texels(a, 6400.0), surroundings_shading_texels(b, 6400.0));
}

}  // namespace
}  // namespace sansui::look
