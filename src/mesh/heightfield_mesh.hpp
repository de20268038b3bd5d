// A heightfield as a triangle mesh: one vertex per sample (x east, y up, z south, metres),
// two triangles per cell, per-vertex normals from central differences.
#pragma once

#include "core/grid.hpp"
#include "core/triangle_mesh.hpp"

namespace sansui::mesh {

TriangleMesh heightfield_to_mesh(const Heightfield& heights);

/// Texture coordinates of any mesh seen from above over the extent of `grid`: (0, 0) at its first
/// sample (north-west), (1, 1) at its last (south-east), as heightfield_to_mesh gives them, so a
/// picture of the grid (its band colours) drapes over the mesh. Clamped to [0, 1].
void set_uvs_over_grid(TriangleMesh& mesh, const Heightfield& grid);

}  // namespace sansui::mesh
