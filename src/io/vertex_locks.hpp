// Per-vertex locks for `sansui subdivide`, read from the mesh file itself, so an artist marks
// the points to keep in the modelling tool they already use:
//   OBJ:  a vertex colour ("v x y z r g b", as Blender writes with Colors on) that is red:
//         r >= 0.5 and g, b < 0.5.
//   glTF: a custom vertex attribute "_LOCK" (scalar; float, unsigned byte or unsigned short),
//         non-zero meaning locked, as Blender writes attributes whose names start with "_".
// The locks are returned as positions and matched to io::read_mesh's vertices by position, so
// they do not depend on how the mesh reader numbers or duplicates vertices.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "core/triangle_mesh.hpp"

namespace sansui::io {

/// Positions of the locked vertices of an OBJ or glTF/.glb file (empty if none is marked).
/// Throws InputError naming the file if it cannot be read.
std::vector<glm::vec3> read_locked_positions(const std::filesystem::path& path);

/// One flag per position of `mesh`: 1 where the position is one of `locked`.
std::vector<std::uint8_t> lock_flags_for(const TriangleMesh& mesh, std::span<const glm::vec3> locked);

}  // namespace sansui::io
