// A heightfield as a triangle mesh: one vertex per sample (x east, y up, z south, metres),
// two triangles per cell, per-vertex normals from central differences.
#pragma once

#include "core/grid.hpp"
#include "core/triangle_mesh.hpp"

namespace sansui::mesh {

TriangleMesh heightfield_to_mesh(const Heightfield& heights);

}  // namespace sansui::mesh
