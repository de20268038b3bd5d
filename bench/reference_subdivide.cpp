#include "bench/reference_subdivide.hpp"

#include <unordered_map>

#include <glm/geometric.hpp>

#include "mesh/subdivide.hpp"

namespace sansui::reference {
namespace {

std::uint64_t pair_key(std::uint32_t a, std::uint32_t b) {
  return a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
}

KeyedMesh step(const KeyedMesh& in, std::uint64_t seed, double scale_m) {
  const auto& p = in.mesh.positions;
  const auto& idx = in.mesh.indices;
  const std::size_t triangles = in.mesh.triangle_count();
  std::vector<glm::vec3> normal(triangles);
  std::unordered_map<std::uint64_t, std::pair<std::uint32_t, std::uint32_t>> sides;  // edge -> its triangles
  for (std::uint32_t t = 0; t < triangles; ++t) {
    const glm::vec3 a = p[idx[3 * t]];
    const glm::vec3 n = glm::cross(p[idx[3 * t + 1]] - a, p[idx[3 * t + 2]] - a);
    const float length = glm::length(n);
    normal[t] = length > 0.0f ? n / length : glm::vec3(0.0f);
    for (int i = 0; i < 3; ++i) {
      auto [it, fresh] = sides.try_emplace(pair_key(idx[3 * t + i], idx[3 * t + (i + 1) % 3]), t, mesh::no_triangle);
      if (!fresh) it->second.second = t;
    }
  }
  KeyedMesh out;
  out.mesh.positions = p;
  out.keys = in.keys;
  std::unordered_map<std::uint64_t, std::uint32_t> midpoint;
  auto mid = [&](std::uint32_t a, std::uint32_t b) {
    const auto [it, fresh] = midpoint.try_emplace(pair_key(a, b), 0u);
    if (!fresh) return it->second;
    const auto [t0, t1] = sides.at(pair_key(a, b));
    glm::vec3 direction = normal[t0];
    if (t1 != mesh::no_triangle) {
      const glm::vec3 sum = normal[t0] + normal[t1];
      const float length = glm::length(sum);
      direction = length > 1e-6f ? sum / length : glm::vec3(0.0f);
    }
    const std::uint64_t key = mesh::midpoint_key(in.keys[a], in.keys[b]);
    const float g = mesh::midpoint_gaussian(seed, key);
    it->second = std::uint32_t(out.mesh.positions.size());
    out.mesh.positions.push_back((p[a] + p[b]) * 0.5f + direction * (float(scale_m) * g));
    out.keys.push_back(key);
    return it->second;
  };
  for (std::size_t t = 0; t < triangles; ++t) {
    const std::uint32_t a = idx[3 * t], b = idx[3 * t + 1], c = idx[3 * t + 2];
    const std::uint32_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
    out.mesh.indices.insert(out.mesh.indices.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
  }
  return out;
}

}  // namespace

KeyedMesh keyed(const mesh::EdgeMesh& mesh) {
  return {mesh::to_triangle_mesh(mesh, false), {mesh.keys.begin(), mesh.keys.end()}};
}

KeyedMesh subdivide(KeyedMesh mesh, std::uint64_t seed, double s0_m, double h, int steps) {
  for (int n = 1; n <= steps; ++n) mesh = step(mesh, seed, mesh::displacement_scale(s0_m, h, n));
  return mesh;
}

}  // namespace sansui::reference
