#include "look/terrain_mesh.hpp"

#include <cassert>
#include <cmath>
#include <utility>

namespace sansui::look {

TerrainMesh build_terrain_mesh(const Heightfield& heights) {
  const int columns = heights.width(), rows = heights.height();
  assert(columns >= 2 && rows >= 2);
  TerrainMesh mesh;
  auto& vertices = mesh.vertices;
  auto& indices = mesh.indices;
  // Heights ride along as a vertex attribute rather than a vertex texture fetch, which
  // software rasterisers do slowly.
  vertices.reserve(static_cast<std::size_t>(columns) * rows * 4 + static_cast<std::size_t>(columns + rows) * 16);
  auto u_of = [&](int x) { return static_cast<float>(x) / static_cast<float>(columns - 1); };
  auto v_of = [&](int y) { return static_cast<float>(y) / static_cast<float>(rows - 1); };
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < columns; ++x) vertices.insert(vertices.end(), {u_of(x), v_of(y), heights(x, y), 0.0f});

  // Surface: one strip per pair of rows (or columns), in the four orders.
  auto index_of = [&](int x, int y) { return static_cast<std::uint32_t>(y * columns + x); };
  auto add_rows = [&](bool southward) {
    const int first = static_cast<int>(indices.size());
    for (int i = 0; i + 1 < rows; ++i) {
      const int y = southward ? i : rows - 2 - i;
      for (int x = 0; x < columns; ++x) indices.insert(indices.end(), {index_of(x, y), index_of(x, y + 1)});
      indices.push_back(strip_restart);
    }
    return IndexRange{first, static_cast<int>(indices.size()) - first};
  };
  auto add_columns = [&](bool eastward) {
    const int first = static_cast<int>(indices.size());
    for (int i = 0; i + 1 < columns; ++i) {
      const int x = eastward ? i : columns - 2 - i;
      for (int y = 0; y < rows; ++y) indices.insert(indices.end(), {index_of(x + 1, y), index_of(x, y)});
      indices.push_back(strip_restart);
    }
    return IndexRange{first, static_cast<int>(indices.size()) - first};
  };
  mesh.surface_orders[0] = add_rows(true);
  mesh.surface_orders[1] = add_rows(false);
  mesh.surface_orders[2] = add_columns(true);
  mesh.surface_orders[3] = add_columns(false);

  // Sides: a strip along each edge, between the ground (or sea) and the base of the block.
  const int sides_first = static_cast<int>(indices.size());
  auto add_side = [&](int count, auto sample) {
    const auto first = static_cast<std::uint32_t>(vertices.size() / 4);
    for (int i = 0; i < count; ++i) {
      const auto [x, y] = sample(i);
      const float u = u_of(x), v = v_of(y), h = heights(x, y);
      vertices.insert(vertices.end(), {u, v, h, 1.0f, u, v, h, 2.0f});
      indices.push_back(first + 2 * static_cast<std::uint32_t>(i));
      indices.push_back(first + 2 * static_cast<std::uint32_t>(i) + 1);
    }
    indices.push_back(strip_restart);
  };
  add_side(columns, [&](int i) { return std::pair{i, 0}; });
  add_side(columns, [&](int i) { return std::pair{i, rows - 1}; });
  add_side(rows, [&](int i) { return std::pair{0, i}; });
  add_side(rows, [&](int i) { return std::pair{columns - 1, i}; });
  mesh.sides = {sides_first, static_cast<int>(indices.size()) - sides_first};
  return mesh;
}

int surface_order_for(float forward_x, float forward_z) {
  if (std::abs(forward_z) >= std::abs(forward_x)) return forward_z > 0.0f ? 0 : 1;
  return forward_x > 0.0f ? 2 : 3;
}

}  // namespace sansui::look
