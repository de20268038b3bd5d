// Heightfield to mesh: layout, positions in metres, counter-clockwise winding seen from above,
// central-difference normals (exact for planes), bad sizes.
#include "mesh/heightfield_mesh.hpp"

#include <glm/geometric.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/io/io_test_util.hpp"

namespace sansui {
namespace {

TEST(HeightfieldMesh, HasOneVertexPerSampleAndTwoTrianglesPerCell) {
  const TriangleMesh mesh = mesh::heightfield_to_mesh(test::sample_heights(7, 4));
  EXPECT_EQ(mesh.positions.size(), 28u);
  EXPECT_EQ(mesh.normals.size(), 28u);
  EXPECT_EQ(mesh.triangle_count(), 2u * 6u * 3u);
  for (const auto index : mesh.indices) EXPECT_LT(index, 28u);
}

TEST(HeightfieldMesh, PlacesSamplesEastUpSouthInMetres) {
  Heightfield heights = test::sample_heights(5, 3);
  heights.cell_size_m = 30.0;
  heights.origin_x_m = 1000.0;
  heights.origin_y_m = -500.0;
  const TriangleMesh mesh = mesh::heightfield_to_mesh(heights);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 5; ++i)
      EXPECT_EQ(mesh.positions[static_cast<std::size_t>(j * 5 + i)],
                glm::vec3(1000.0f + 30.0f * static_cast<float>(i), heights(i, j), -500.0f + 30.0f * static_cast<float>(j)));
}

TEST(HeightfieldMesh, TrianglesAreCounterClockwiseSeenFromAbove) {
  // Steep random heights: the winding must not depend on them.
  const TriangleMesh mesh = mesh::heightfield_to_mesh(test::sample_heights(9, 9, 3, -5000.0, 5000.0));
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    const glm::vec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]], c = mesh.positions[mesh.indices[t + 2]];
    ASSERT_GT(glm::cross(b - a, c - a).y, 0.0f) << "triangle " << t / 3;
  }
}

TEST(HeightfieldMesh, NormalsOfAPlaneAreItsNormalEverywhere) {
  // h = 0.5 x - 0.25 z (x east, z south, metres): normal (-0.5, 1, 0.25) normalised, also on the border.
  Heightfield heights(6, 5, 0.0f, 20.0);
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 6; ++i) heights(i, j) = static_cast<float>(0.5 * i * 20.0 - 0.25 * j * 20.0);
  const TriangleMesh mesh = mesh::heightfield_to_mesh(heights);
  const glm::vec3 expected = glm::normalize(glm::vec3(-0.5f, 1.0f, 0.25f));
  for (const auto& normal : mesh.normals) {
    EXPECT_NEAR(normal.x, expected.x, 1e-6f);
    EXPECT_NEAR(normal.y, expected.y, 1e-6f);
    EXPECT_NEAR(normal.z, expected.z, 1e-6f);
  }
}

TEST(HeightfieldMesh, NormalsUseCentralDifferences) {
  Heightfield heights(3, 3, 0.0f, 2.0);
  heights(0, 1) = 1.0f;
  heights(2, 1) = 5.0f;  // dh/dx at the centre = (5 - 1) / (2 * 2) = 1
  heights(1, 0) = 4.0f;  // dh/dz at the centre = (0 - 4) / 4 = -1
  const TriangleMesh mesh = mesh::heightfield_to_mesh(heights);
  const glm::vec3 expected = glm::normalize(glm::vec3(-1.0f, 1.0f, 1.0f));
  EXPECT_NEAR(glm::distance(mesh.normals[4], expected), 0.0f, 1e-6f);
}

TEST(HeightfieldMesh, TooSmallGridsAreAnInputError) {
  EXPECT_THAT(test::input_error_of([] { mesh::heightfield_to_mesh(Heightfield(1, 5, 0.0f)); }),
              ::testing::HasSubstr("1 x 5 samples has no cells"));
}

}  // namespace
}  // namespace sansui
