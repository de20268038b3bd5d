// Meshes turned to z up (mesh/axes.hpp): north is -z_south, up is y, and a heightfield's
// triangles stay counter-clockwise seen from above with their normals up.
#include "mesh/axes.hpp"

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include "mesh/heightfield_mesh.hpp"
#include "tests/io/io_test_util.hpp"

namespace sansui {
namespace {

TEST(MeshAxes, TurnsEastUpSouthToEastNorthUp) {
  TriangleMesh mesh;
  mesh.positions = {{1.0f, 2.0f, 3.0f}};
  mesh.normals = {{0.0f, 1.0f, 0.0f}};
  mesh::turn_to_z_up(mesh);
  EXPECT_EQ(mesh.positions[0], glm::vec3(1.0f, -3.0f, 2.0f));
  EXPECT_EQ(mesh.normals[0], glm::vec3(0.0f, 0.0f, 1.0f));
}

TEST(MeshAxes, AHeightfieldStaysCounterClockwiseSeenFromAboveWithItsNormalsUp) {
  TriangleMesh mesh = mesh::heightfield_to_mesh(test::sample_heights(9, 9, 3, -500.0, 500.0));
  const std::vector<std::uint32_t> indices = mesh.indices;
  mesh::turn_to_z_up(mesh);
  EXPECT_EQ(mesh.indices, indices);
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    const glm::vec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]], c = mesh.positions[mesh.indices[t + 2]];
    ASSERT_GT(glm::cross(b - a, c - a).z, 0.0f) << "triangle " << t / 3;
  }
  for (const glm::vec3& n : mesh.normals) ASSERT_GT(n.z, 0.0f);
  // Row 1 lies south of row 0: at a lower y.
  EXPECT_LT(mesh.positions[9].y, mesh.positions[0].y);
}

}  // namespace
}  // namespace sansui
