#include "mesh/edge_mesh.hpp"

#include <cmath>
#include <limits>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "mesh/mesh_test_util.hpp"
#include "mesh/pyramid.hpp"

namespace sansui::mesh {
namespace {

using test::expect_valid_surface;
using ::testing::HasSubstr;

std::string error_of(const TriangleMesh& mesh, std::span<const std::uint8_t> locks = {}) {
  try {
    build_edge_mesh(mesh, locks);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(EdgeMesh, PyramidHasFiveVerticesEightEdgesFourBoundaryEdges) {
  const EdgeMesh m = build_edge_mesh(make_pyramid(100, 50));
  EXPECT_EQ(m.vertex_count(), 5u);
  EXPECT_EQ(m.edge_count(), 8u);
  EXPECT_EQ(m.triangle_count(), 4u);
  EXPECT_EQ(expect_valid_surface(m), 4u);
  EXPECT_EQ(euler_characteristic(m), 1);
}

TEST(EdgeMesh, OctahedronIsClosedAndFacesOutwards) {
  const EdgeMesh m = build_edge_mesh(test::octahedron());
  EXPECT_EQ(expect_valid_surface(m), 0u);
  EXPECT_EQ(euler_characteristic(m), 2);
  for (const auto& c : m.triangles) {
    const glm::vec3 a = m.positions[c[0]], b = m.positions[c[1]], d = m.positions[c[2]];
    EXPECT_GT(glm::dot(glm::cross(b - a, d - a), a + b + d), 0.0f);
  }
}

TEST(EdgeMesh, WeldsCopiesOfAVertexAndDropsUnusedOnes) {
  const TriangleMesh closed = test::octahedron();
  TriangleMesh split;  // every triangle with its own three vertices, plus one stray vertex
  for (std::uint32_t index : closed.indices) {
    split.indices.push_back(std::uint32_t(split.positions.size()));
    split.positions.push_back(closed.positions[index]);
  }
  split.positions.push_back({7, 7, 7});
  BuildReport report;
  const EdgeMesh m = build_edge_mesh(split, {}, &report);
  EXPECT_EQ(m.vertex_count(), 6u);
  EXPECT_EQ(report.welded_vertices, 24u - 6u);
  EXPECT_EQ(report.unused_vertices, 1u);
  EXPECT_EQ(euler_characteristic(m), 2);
}

TEST(EdgeMesh, NegativeZeroWeldsWithZero) {
  TriangleMesh m = make_pyramid(10, 5);
  m.positions.push_back({-0.0f, 0.0f, -0.0f});  // the same point as vertex 0
  m.indices[9 + 1] = 5;                         // triangle 3 uses the copy
  EXPECT_EQ(build_edge_mesh(m).vertex_count(), 5u);
}

TEST(EdgeMesh, TurnsTrianglesOverToAgreeAndFaceUp) {
  TriangleMesh m = test::flat_square(4, 10.0f);
  for (std::size_t t = 0; t < m.triangle_count(); t += 3) std::swap(m.indices[3 * t + 1], m.indices[3 * t + 2]);
  BuildReport report;
  const EdgeMesh e = build_edge_mesh(m, {}, &report);
  EXPECT_EQ(report.flipped_triangles, 11u);
  expect_valid_surface(e);
  for (const auto& c : e.triangles)
    EXPECT_GT(glm::cross(e.positions[c[1]] - e.positions[c[0]], e.positions[c[2]] - e.positions[c[0]]).y, 0.0f);
  // Everything upside down: turned over as a whole to face up.
  TriangleMesh down = test::flat_square(2, 1.0f);
  for (std::size_t t = 0; t < down.triangle_count(); ++t) std::swap(down.indices[3 * t + 1], down.indices[3 * t + 2]);
  BuildReport all;
  build_edge_mesh(down, {}, &all);
  EXPECT_EQ(all.flipped_triangles, down.triangle_count());
}

TEST(EdgeMesh, ShuffledInputGivesTheSameBytes) {
  const TriangleMesh original = test::flat_square(5, 3.0f);
  const EdgeMesh a = build_edge_mesh(original);
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const EdgeMesh b = build_edge_mesh(test::shuffled(original, seed));
    ASSERT_EQ(a.positions.size(), b.positions.size());
    EXPECT_EQ(0, std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(glm::vec3)));
    EXPECT_EQ(a.keys, b.keys);
    EXPECT_EQ(a.triangles, b.triangles);
    EXPECT_EQ(a.triangle_edges, b.triangle_edges);
    ASSERT_EQ(a.edges.size(), b.edges.size());
    for (std::size_t e = 0; e < a.edges.size(); ++e) {
      EXPECT_EQ(a.edges[e].v, b.edges[e].v);
      EXPECT_EQ(a.edges[e].t, b.edges[e].t);
    }
  }
}

TEST(EdgeMesh, LocksFollowTheirVertexThroughWelding) {
  TriangleMesh m = make_pyramid(10, 5);
  std::vector<std::uint8_t> locks(m.positions.size(), 0);
  locks[4] = 1;  // the apex
  const EdgeMesh locked = build_edge_mesh(m, locks);
  int count = 0;
  for (std::uint32_t v = 0; v < locked.vertex_count(); ++v)
    if (locked.locked(v)) {
      ++count;
      EXPECT_EQ(locked.positions[v].y, 5.0f);
    }
  EXPECT_EQ(count, 1);
}

TEST(EdgeMesh, KeysAndMidpointKeysDoNotDependOnOrder) {
  EXPECT_EQ(midpoint_key(1, 2), midpoint_key(2, 1));
  EXPECT_NE(midpoint_key(1, 2), midpoint_key(1, 3));
  EXPECT_EQ(position_key({0.0f, 1.0f, -0.0f}), position_key({-0.0f, 1.0f, 0.0f}));
  EXPECT_NE(position_key({0.0f, 1.0f, 2.0f}), position_key({0.0f, 2.0f, 1.0f}));
}

TEST(EdgeMesh, BadInputsAreRefusedWithAMessage) {
  EXPECT_THAT(error_of(TriangleMesh{}), HasSubstr("the mesh is empty"));

  TriangleMesh m = make_pyramid(10, 5);
  m.indices.pop_back();
  EXPECT_THAT(error_of(m), HasSubstr("not a multiple of 3"));

  m = make_pyramid(10, 5);
  m.indices[7] = 99;
  EXPECT_THAT(error_of(m), HasSubstr("triangle 3 of the input (counting from 1) refers to vertex 100"));

  m = make_pyramid(10, 5);
  m.positions[2].y = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THAT(error_of(m), HasSubstr("vertex 3 of the input (counting from 1) has a coordinate that is not a finite number"));
  m.positions[2].y = std::numeric_limits<float>::infinity();
  EXPECT_THAT(error_of(m), HasSubstr("not a finite number"));

  m = make_pyramid(10, 5);
  m.indices[4] = m.indices[3];
  EXPECT_THAT(error_of(m), HasSubstr("triangle 2 of the input (counting from 1) has zero area: two of its corners"));

  m = make_pyramid(10, 5);
  m.positions.push_back({5, 0, 0});  // on the line between vertices 0 and 3
  m.indices.insert(m.indices.end(), {0, 5, 3});
  EXPECT_THAT(error_of(m), HasSubstr("triangle 5 of the input (counting from 1) has zero area: its corners"));

  m = make_pyramid(10, 5);
  m.indices.insert(m.indices.end(), {4, 2, 1});  // triangle 2 again, other winding
  EXPECT_THAT(error_of(m), HasSubstr("triangles 2 and 5 of the input (counting from 1) have the same three corners"));

  m = make_pyramid(10, 5);  // a fin on the edge from corner 0 to the apex
  m.positions.push_back({-5, 10, -5});
  m.indices.insert(m.indices.end(), {0, 4, 5});
  EXPECT_THAT(error_of(m), HasSubstr("is shared by 3 triangles (input triangles 1, 4, 5, counting from 1)"));

  TriangleMesh strip;  // a Moebius strip
  const int n = 8;
  for (int i = 0; i < n; ++i) {
    const double theta = 2 * M_PI * i / n, phi = theta / 2;
    const glm::vec3 centre(float(100 * std::cos(theta)), 0.0f, float(100 * std::sin(theta)));
    const glm::vec3 offset = float(20 * std::cos(phi)) * glm::vec3(float(std::cos(theta)), 0, float(std::sin(theta))) +
                             float(20 * std::sin(phi)) * glm::vec3(0, 1, 0);
    strip.positions.push_back(centre + offset);
    strip.positions.push_back(centre - offset);
  }
  auto a = [](int i) { return std::uint32_t(2 * i); };
  auto b = [](int i) { return std::uint32_t(2 * i + 1); };
  for (int i = 0; i + 1 < n; ++i) strip.indices.insert(strip.indices.end(), {a(i), b(i), b(i + 1), a(i), b(i + 1), a(i + 1)});
  strip.indices.insert(strip.indices.end(), {a(n - 1), b(n - 1), a(0), a(n - 1), a(0), b(0)});
  EXPECT_THAT(error_of(strip), HasSubstr("cannot be oriented"));

  const std::vector<std::uint8_t> short_locks(2, 1);
  EXPECT_THAT(error_of(make_pyramid(10, 5), short_locks), HasSubstr("the vertex locks list 2 entries for 5 vertices"));
}

}  // namespace
}  // namespace sansui::mesh
