// An indexed triangle mesh in metres: x east, y up, z south (right-handed, glTF's convention).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace sansui {

struct TriangleMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;      ///< one per position, unit length; may be empty
  std::vector<glm::vec3> colors;       ///< one per position, sRGB in [0, 1]; may be empty
  std::vector<std::uint32_t> indices;  ///< three per triangle, counter-clockwise seen from above
  /// Texture coordinates, one per position, (0, 0) at the north-west corner of a terrain and
  /// (1, 1) at its south-east (u east, v south: glTF's image convention); may be empty.
  std::vector<glm::vec2> uvs;

  std::size_t triangle_count() const { return indices.size() / 3; }
};

}  // namespace sansui
