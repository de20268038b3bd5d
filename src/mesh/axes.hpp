// Meshes in the axes of the programs they go to. Sansui's meshes use glTF's axes (x east, y up,
// z south); Blender, GIS and most modelling tools take x east, y north, z up. The turn between
// them is a proper rotation (a quarter turn about x), so triangles keep their winding and
// normals stay outward.
#pragma once

#include "core/triangle_mesh.hpp"

namespace sansui::mesh {

/// Turns `mesh` from Sansui's axes (x east, y up, z south) to x east, y north, z up: a point
/// (x, y, z) becomes (x, -z, y); normals likewise. Indices, colours and UVs are unchanged.
void turn_to_z_up(TriangleMesh& mesh);

}  // namespace sansui::mesh
