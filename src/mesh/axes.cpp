#include "mesh/axes.hpp"

namespace sansui::mesh {
namespace {

glm::vec3 z_up(const glm::vec3& p) {
  return {p.x, 0.0f - p.z, p.y};  // 0 - z: the north row at y = +0, not -0
}

}  // namespace

void turn_to_z_up(TriangleMesh& mesh) {
  for (glm::vec3& p : mesh.positions) p = z_up(p);
  for (glm::vec3& n : mesh.normals) n = z_up(n);
}

}  // namespace sansui::mesh
