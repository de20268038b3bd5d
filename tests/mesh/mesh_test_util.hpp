// Small meshes and surface checks shared by the mesh tests.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <map>
#include <numeric>
#include <span>
#include <vector>

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include "core/random.hpp"
#include "core/triangle_mesh.hpp"
#include "mesh/edge_mesh.hpp"

namespace sansui::mesh::test {

/// A closed octahedron around the origin, faces outwards.
inline TriangleMesh octahedron(float r = 100.0f) {
  TriangleMesh m;
  m.positions = {{r, 0, 0}, {-r, 0, 0}, {0, r, 0}, {0, -r, 0}, {0, 0, r}, {0, 0, -r}};
  m.indices = {0, 2, 4, 4, 2, 1, 1, 2, 5, 5, 2, 0, 4, 3, 0, 1, 3, 4, 5, 3, 1, 0, 3, 5};
  return m;
}

/// A flat square of n x n cells of `size` m each (two triangles per cell), at height 0.
inline TriangleMesh flat_square(int n, float size) {
  TriangleMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.positions.push_back({float(i) * size, 0.0f, float(j) * size});
  auto at = [&](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      // Counter-clockwise seen from above (x east, z south): normal +y.
      m.indices.insert(m.indices.end(), {at(i, j), at(i, j + 1), at(i + 1, j + 1)});
      m.indices.insert(m.indices.end(), {at(i, j), at(i + 1, j + 1), at(i + 1, j)});
    }
  return m;
}

/// The same surface with vertices renumbered, triangles shuffled and corners rotated.
inline TriangleMesh shuffled(const TriangleMesh& in, std::uint64_t seed) {
  const std::size_t v = in.positions.size(), t = in.triangle_count();
  std::vector<std::uint32_t> order(v), tri(t);
  std::iota(order.begin(), order.end(), 0u);
  std::iota(tri.begin(), tri.end(), 0u);
  auto shuffle = [&](std::vector<std::uint32_t>& a, std::uint64_t stream) {
    for (std::size_t i = a.size(); i > 1; --i) std::swap(a[i - 1], a[rng::bits(rng::stream_key(seed, stream), i) % i]);
  };
  shuffle(order, 1);
  shuffle(tri, 2);
  std::vector<std::uint32_t> new_index(v);
  TriangleMesh out;
  out.positions.resize(v);
  for (std::size_t k = 0; k < v; ++k) new_index[order[k]] = std::uint32_t(k), out.positions[k] = in.positions[order[k]];
  for (std::size_t k = 0; k < t; ++k) {
    const std::uint32_t s = tri[k];
    const int r = int(rng::bits(rng::stream_key(seed, 3), k) % 3);
    for (int i = 0; i < 3; ++i) out.indices.push_back(new_index[in.indices[3 * s + (i + r) % 3]]);
  }
  return out;
}

inline std::vector<std::array<std::uint32_t, 3>> sorted_positions(std::span<const glm::vec3> positions) {
  std::vector<std::array<std::uint32_t, 3>> bits;
  for (glm::vec3 p : positions)
    bits.push_back({std::bit_cast<std::uint32_t>(p.x), std::bit_cast<std::uint32_t>(p.y), std::bit_cast<std::uint32_t>(p.z)});
  std::sort(bits.begin(), bits.end());
  return bits;
}

/// Checks the surface from its triangles alone (not trusting the edge table): every edge
/// borders one or two triangles, two walk it in opposite directions, no two vertices share a
/// position, and the edge table agrees. Returns the number of boundary edges.
inline std::size_t expect_valid_surface(const EdgeMesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& c : mesh.triangles)
    for (int i = 0; i < 3; ++i) ++directed[{c[i], c[(i + 1) % 3]}];
  std::size_t boundary = 0, undirected = 0;
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second << " walked twice the same way";
    const bool twin = directed.count({edge.second, edge.first}) > 0;
    if (!twin) ++boundary;
    if (!twin || edge.first < edge.second) ++undirected;
  }
  EXPECT_EQ(undirected, mesh.edge_count());
  std::size_t table_boundary = 0;
  for (std::size_t e = 0; e < mesh.edge_count(); ++e) {
    const Edge& edge = mesh.edges[e];
    table_boundary += edge.on_boundary();
    const auto& t0 = mesh.triangles[edge.t[0]];
    bool found = false;
    for (int i = 0; i < 3; ++i) found |= t0[i] == edge.v[0] && t0[(i + 1) % 3] == edge.v[1] && mesh.triangle_edges[edge.t[0]][i] == e;
    EXPECT_TRUE(found) << "edge " << e << " not walked v0->v1 by its triangle t[0]";
  }
  EXPECT_EQ(table_boundary, boundary);
  const auto sorted = sorted_positions(mesh.positions);
  EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << "two vertices at one position";
  return boundary;
}

}  // namespace sansui::mesh::test
