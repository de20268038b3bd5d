#include "look/terrain_mesh.hpp"

#include <set>

#include <gtest/gtest.h>

namespace sansui::look {
namespace {

Heightfield ramp(int width, int height) {
  Heightfield heights(width, height, 0.0f, 5.0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) heights(x, y) = static_cast<float>(10 * x + y);
  return heights;
}

TEST(TerrainMesh, SurfaceVerticesCarryTheirPositionAndHeight) {
  const Heightfield heights = ramp(5, 3);
  const TerrainMesh mesh = build_terrain_mesh(heights);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) {
      const float* vertex = &mesh.vertices[static_cast<std::size_t>(y * 5 + x) * 4];
      EXPECT_FLOAT_EQ(vertex[0], static_cast<float>(x) / 4.0f);
      EXPECT_FLOAT_EQ(vertex[1], static_cast<float>(y) / 2.0f);
      EXPECT_FLOAT_EQ(vertex[2], heights(x, y));
      EXPECT_FLOAT_EQ(vertex[3], 0.0f);
    }
  // Sides: a top and a base vertex for every edge sample.
  EXPECT_EQ(mesh.vertices.size(), (5u * 3u + 2u * (2u * 5u + 2u * 3u)) * 4u);
}

TEST(TerrainMesh, EveryOrderCoversEveryCellOnce) {
  const TerrainMesh mesh = build_terrain_mesh(ramp(6, 4));
  for (const IndexRange& order : mesh.surface_orders) {
    // Walk the strips; each quad of the grid shows up as two triangles of one strip.
    std::multiset<std::set<std::uint32_t>> quads;
    std::vector<std::uint32_t> strip;
    for (int i = order.first; i < order.first + order.count; ++i) {
      const std::uint32_t index = mesh.indices[i];
      if (index != strip_restart) {
        ASSERT_LT(index, 24u);
        strip.push_back(index);
        continue;
      }
      ASSERT_EQ(strip.size() % 2, 0u);
      for (std::size_t k = 0; k + 3 < strip.size(); k += 2) quads.insert({strip[k], strip[k + 1], strip[k + 2], strip[k + 3]});
      strip.clear();
    }
    EXPECT_TRUE(strip.empty());
    EXPECT_EQ(quads.size(), 5u * 3u);
    EXPECT_EQ(std::set<std::set<std::uint32_t>>(quads.begin(), quads.end()).size(), 15u);
  }
  EXPECT_EQ(mesh.sides.first + mesh.sides.count, static_cast<int>(mesh.indices.size()));
}

TEST(TerrainMesh, OrderRunsAwayFromTheCamera) {
  EXPECT_EQ(surface_order_for(0.1f, 0.9f), 0);   // looking south: rows from north to south
  EXPECT_EQ(surface_order_for(0.1f, -0.9f), 1);  // looking north
  EXPECT_EQ(surface_order_for(0.9f, 0.2f), 2);   // looking east
  EXPECT_EQ(surface_order_for(-0.9f, 0.2f), 3);  // looking west
  const TerrainMesh mesh = build_terrain_mesh(ramp(4, 4));
  // Rows running south start at the north edge (row 0), rows running north at the south edge.
  EXPECT_EQ(mesh.indices[mesh.surface_orders[0].first], 0u);
  EXPECT_EQ(mesh.indices[mesh.surface_orders[1].first], 8u);
}

}  // namespace
}  // namespace sansui::look
