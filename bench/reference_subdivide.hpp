// A plain reference for fractal mesh subdivision, the way one writes it first: one thread, a
// hash map from each edge's two vertices to its midpoint, rebuilt every step. Same random
// numbers and arithmetic as mesh::subdivide_step (normal direction, free boundary), so the
// sorted vertex positions agree exactly; used by the benchmark and the tests.
#pragma once

#include <cstdint>
#include <vector>

#include "core/triangle_mesh.hpp"
#include "mesh/edge_mesh.hpp"

namespace sansui::reference {

struct KeyedMesh {
  TriangleMesh mesh;
  std::vector<std::uint64_t> keys;
};

/// The canonical input as a plain mesh with its vertex keys.
KeyedMesh keyed(const mesh::EdgeMesh& mesh);

/// `steps` steps with S(n) = s0 * 0.5^(h n).
KeyedMesh subdivide(KeyedMesh mesh, std::uint64_t seed, double s0_m, double h, int steps);

}  // namespace sansui::reference
