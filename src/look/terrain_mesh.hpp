// The triangles the GPU draws for a heightfield: a grid of triangle strips over the surface,
// and the four cut sides of the terrain block. Plain data, built on the CPU.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/grid.hpp"

namespace sansui::look {

/// Separates triangle strips in the index list (GL primitive restart).
inline constexpr std::uint32_t strip_restart = 0xFFFFFFFFu;

/// A run of the index list: [first, first + count).
struct IndexRange {
  int first = 0;
  int count = 0;
};

struct TerrainMesh {
  /// Four floats per vertex: u, v (0..1 east and south across the terrain), the true height in
  /// metres, and the kind: 0 surface, 1 top of a side (the ground, or the sea where higher),
  /// 2 base of a side. The surface vertices come first, row by row (index y * width + x).
  std::vector<float> vertices;
  /// Triangle-strip indices, strips separated by strip_restart.
  std::vector<std::uint32_t> indices;
  /// The whole surface in four orders: strips of rows running south, rows running north,
  /// columns running east, columns running west. Drawing the one that moves away from the
  /// camera lets the depth test reject hidden fragments before they are shaded.
  std::array<IndexRange, 4> surface_orders;
  /// The four sides of the block.
  IndexRange sides;
};

/// The mesh of `heights` (at least 2x2 samples).
TerrainMesh build_terrain_mesh(const Heightfield& heights);

/// Which of TerrainMesh::surface_orders runs away from a camera looking along (forward_x,
/// forward_z) (x east, z south).
int surface_order_for(float forward_x, float forward_z);

}  // namespace sansui::look
