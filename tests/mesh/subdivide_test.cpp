#include "mesh/subdivide.hpp"

#include <atomic>
#include <cmath>
#include <cstring>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include "bench/reference_subdivide.hpp"
#include "core/error.hpp"
#include "mesh/mesh_test_util.hpp"
#include "mesh/pyramid.hpp"
#include "test_util.hpp"

namespace sansui::mesh {
namespace {

using test::expect_valid_surface;
using ::testing::HasSubstr;

SubdivideParams steps(int k, std::uint64_t seed = 1) {
  SubdivideParams p;
  p.seed = seed;
  p.steps = k;
  return p;
}

std::uint64_t hash_of(const EdgeMesh& m) {
  std::uint64_t h = sansui::test::fnv1a(m.positions.data(), m.positions.size() * sizeof(glm::vec3));
  return sansui::test::fnv1a(m.triangles.data(), m.triangles.size() * sizeof(m.triangles[0]), h);
}

std::string error_of(const TriangleMesh& mesh, const SubdivideParams& params) {
  try {
    subdivide(build_edge_mesh(mesh), params);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

/// Vertices at either end of a boundary edge.
std::vector<std::uint32_t> boundary_vertices(const EdgeMesh& m) {
  std::vector<std::uint32_t> out;
  for (const Edge& e : m.edges)
    if (e.on_boundary()) out.push_back(e.v[0]), out.push_back(e.v[1]);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

TEST(Subdivide, StaysCrackFreeManifoldWithTheSameEulerCharacteristic) {
  for (const TriangleMesh& input : {make_pyramid(1000, 600), test::octahedron(), test::flat_square(3, 100)}) {
    const EdgeMesh coarse = build_edge_mesh(input);
    const std::size_t boundary = expect_valid_surface(coarse);
    const SubdivideResult r = subdivide(coarse, steps(4));
    EXPECT_EQ(r.mesh.triangle_count(), coarse.triangle_count() * 256);
    EXPECT_EQ(expect_valid_surface(r.mesh), boundary * 16);
    EXPECT_EQ(euler_characteristic(r.mesh), euler_characteristic(coarse));
    ASSERT_EQ(r.steps.size(), 5u);
    for (int n = 0; n <= 4; ++n) EXPECT_EQ(r.steps[n].triangles, coarse.triangle_count() << (2 * n));
  }
}

TEST(Subdivide, ShuffledAndRenumberedInputGivesTheSameSurface) {
  for (const TriangleMesh& input : {make_pyramid(1000, 600), test::octahedron(), test::flat_square(4, 50)}) {
    const EdgeMesh a = subdivide(build_edge_mesh(input), steps(4, 7)).mesh;
    for (std::uint64_t shuffle = 1; shuffle <= 3; ++shuffle) {
      const EdgeMesh b = subdivide(build_edge_mesh(test::shuffled(input, shuffle)), steps(4, 7)).mesh;
      EXPECT_EQ(test::sorted_positions(a.positions), test::sorted_positions(b.positions));
      EXPECT_EQ(hash_of(a), hash_of(b));  // canonical order: even the arrays are the same
    }
  }
}

TEST(Subdivide, SameBytesForOneOrManyThreadsAndAcrossRuns) {
  SubdivideParams p = steps(5, 42);
  const EdgeMesh coarse = build_edge_mesh(test::octahedron());
  std::uint64_t one = 0, two = 0, all = 0;
  tbb::task_arena(1).execute([&] { one = hash_of(subdivide(coarse, p).mesh); });
  tbb::task_arena(2).execute([&] { two = hash_of(subdivide(coarse, p).mesh); });
  all = hash_of(subdivide(coarse, p).mesh);
  EXPECT_EQ(one, two);
  EXPECT_EQ(one, all);
  // Golden value: changes only if the algorithm or its random numbers change.
  EXPECT_EQ(hash_of(subdivide(build_edge_mesh(make_pyramid(1000, 600)), steps(3, 1)).mesh), 0xec9d88ce55ace733ull);
}

TEST(Subdivide, DifferentSeedsGiveDifferentSurfaces) {
  const EdgeMesh coarse = build_edge_mesh(make_pyramid(1000, 600));
  EXPECT_NE(hash_of(subdivide(coarse, steps(3, 1)).mesh), hash_of(subdivide(coarse, steps(3, 2)).mesh));
}

TEST(Subdivide, ScheduleIsSOfNEqualsSOfNMinusOneTimesHalfToTheH) {
  const double h = 0.7;
  for (int n = 1; n <= 8; ++n) EXPECT_NEAR(displacement_scale(3.0, h, n) / displacement_scale(3.0, h, n - 1), std::pow(0.5, h), 1e-12);
  SubdivideParams p = steps(4);
  p.h = h;
  p.roughness = 0.25;
  const EdgeMesh coarse = build_edge_mesh(make_pyramid(1000, 600));
  const SubdivideResult r = subdivide(coarse, p);
  EXPECT_DOUBLE_EQ(r.steps[0].scale_m, 0.25 * mean_edge_length(coarse));
  for (int n = 1; n <= 4; ++n) EXPECT_DOUBLE_EQ(r.steps[n].scale_m, displacement_scale(r.steps[0].scale_m, h, n));
}

TEST(Subdivide, MidpointsMoveByExactlySTimesTheirEdgesGaussian) {
  // A flat square moved vertically: each new vertex is its edge's middle plus S(1) * g(key).
  const EdgeMesh coarse = build_edge_mesh(test::flat_square(4, 100));
  const EdgeMesh fine = subdivide_step(coarse, {9, 12.5, BoundaryMode::free, Direction::vertical});
  for (std::size_t e = 0; e < coarse.edge_count(); ++e) {
    const auto [a, b] = coarse.edges[e].v;
    const std::uint32_t m = std::uint32_t(coarse.vertex_count() + e);
    EXPECT_EQ(fine.keys[m], midpoint_key(coarse.keys[a], coarse.keys[b]));
    EXPECT_EQ(fine.positions[m].y, 12.5f * midpoint_gaussian(9, fine.keys[m]));
    EXPECT_EQ(fine.positions[m].x, 0.5f * (coarse.positions[a].x + coarse.positions[b].x));
  }
}

TEST(Subdivide, DisplacementsHaveStandardDeviationS) {
  // On a large flat square moved vertically the displacement of step n, measured against the
  // middle of its edge, has mean 0 and standard deviation S(n).
  EdgeMesh mesh = build_edge_mesh(test::flat_square(16, 100));
  const double s0 = 40.0, h = 0.6;
  for (int n = 1; n <= 4; ++n) {
    const double s = displacement_scale(s0, h, n);
    const EdgeMesh next = subdivide_step(mesh, {3, s, BoundaryMode::free, Direction::vertical});
    double sum = 0, sum2 = 0;
    for (std::size_t e = 0; e < mesh.edge_count(); ++e) {
      const auto [a, b] = mesh.edges[e].v;
      const double d = next.positions[mesh.vertex_count() + e].y - 0.5 * (mesh.positions[a].y + mesh.positions[b].y);
      sum += d, sum2 += d * d;
    }
    const double count = double(mesh.edge_count());
    EXPECT_NEAR(sum / count / s, 0.0, 4.0 / std::sqrt(count));
    EXPECT_NEAR(std::sqrt(sum2 / count) / s, 1.0, 0.05) << "step " << n;
    mesh = next;
  }
}

TEST(Subdivide, StopsWhenEveryEdgeIsShorterThanMinEdge) {
  const EdgeMesh coarse = build_edge_mesh(make_pyramid(1000, 600));
  for (double min_edge : {300.0, 100.0, 40.0}) {
    SubdivideParams p;
    p.min_edge_m = min_edge;
    const SubdivideResult r = subdivide(coarse, p);
    EXPECT_EQ(r.stopped_by, "min-edge");
    EXPECT_LT(max_edge_length(r.mesh), min_edge);
    ASSERT_GE(r.steps.size(), 2u);
    EXPECT_GE(r.steps[r.steps.size() - 2].max_edge_m, min_edge);  // one step fewer was not enough
  }
  SubdivideParams p = steps(2);
  p.min_edge_m = 1.0;  // whichever comes first
  const SubdivideResult r = subdivide(coarse, p);
  EXPECT_EQ(r.stopped_by, "steps");
  EXPECT_EQ(r.steps.size(), 3u);
  EXPECT_EQ(subdivide(coarse, steps(0)).mesh.triangle_count(), 4u);
}

TEST(Subdivide, FixedBoundaryStaysOnTheOutlineVerticalOnlyMovesUpOrDown) {
  const float side = 400;
  const EdgeMesh coarse = build_edge_mesh(test::flat_square(2, side / 2));
  auto on_outline = [&](glm::vec3 p) { return p.x == 0 || p.x == side || p.z == 0 || p.z == side; };
  for (BoundaryMode mode : {BoundaryMode::fixed, BoundaryMode::vertical, BoundaryMode::free}) {
    SubdivideParams p = steps(4);
    p.boundary = mode;
    p.roughness = 0.3;
    const EdgeMesh m = subdivide(coarse, p).mesh;
    int off_outline = 0, moved = 0;
    for (std::uint32_t v : boundary_vertices(m)) {
      off_outline += !on_outline(m.positions[v]);
      moved += m.positions[v].y != 0.0f;
    }
    if (mode == BoundaryMode::fixed) {
      EXPECT_EQ(off_outline + moved, 0);
    } else if (mode == BoundaryMode::vertical) {
      EXPECT_EQ(off_outline, 0);
      EXPECT_GT(moved, 50);
    } else {
      EXPECT_GT(off_outline + moved, 50);
    }
  }
}

TEST(Subdivide, LockedVerticesKeepTheLineBetweenThemAsDrawn) {
  // Lock the diagonal of a flat square: it stays straight and flat at every level.
  const int n = 4;
  const float size = 100;
  const TriangleMesh square = test::flat_square(n, size);
  std::vector<std::uint8_t> locks(square.positions.size(), 0);
  for (int i = 0; i <= n; ++i) locks[std::size_t(i * (n + 1) + i)] = 1;
  SubdivideParams p = steps(4);
  p.roughness = 0.5;
  const EdgeMesh m = subdivide(build_edge_mesh(square, locks), p).mesh;
  int locked = 0, on_diagonal = 0;
  for (std::uint32_t v = 0; v < m.vertex_count(); ++v) {
    if (!m.locked(v)) continue;
    ++locked;
    EXPECT_EQ(m.positions[v].y, 0.0f);
    on_diagonal += m.positions[v].x == m.positions[v].z;
  }
  EXPECT_EQ(locked, n * 16 + 1);
  EXPECT_EQ(on_diagonal, locked);
  int moved = 0;  // the rest does move
  for (glm::vec3 q : m.positions) moved += q.y != 0.0f;
  EXPECT_GT(moved, int(m.vertex_count()) / 2);
}

TEST(Subdivide, RefusesTooManyTrianglesUnlessForced) {
  const TriangleMesh pyramid = make_pyramid(1000, 600);
  SubdivideParams p = steps(6);
  p.max_triangles = 10000;
  EXPECT_THAT(error_of(pyramid, p),
              HasSubstr("6 steps would make 16384 triangles (about 2 MB), over the limit of 10000: give fewer steps, or force it"));
  p.force = true;
  EXPECT_EQ(subdivide(build_edge_mesh(pyramid), p).mesh.triangle_count(), 16384u);

  SubdivideParams tiny;
  tiny.min_edge_m = 0.001;
  EXPECT_THAT(error_of(pyramid, tiny), HasSubstr("min-edge 0.001 m would need at least 20 steps and"));
  EXPECT_THAT(error_of(pyramid, tiny), HasSubstr("over the limit of 50000000: give a larger min-edge, or force it"));

  // Foreseen as 3 steps, but rough surfaces have longer edges: refused when it gets there.
  SubdivideParams rough;
  rough.min_edge_m = 130;
  rough.roughness = 2.0;
  rough.h = 0.2;
  rough.max_triangles = 256;
  EXPECT_THAT(error_of(pyramid, rough), HasSubstr("after 3 steps the longest edge is still"));
}

TEST(Subdivide, BadParametersAreRefusedWithAMessage) {
  const TriangleMesh pyramid = make_pyramid(10, 5);
  auto with = [](auto change) {
    SubdivideParams p = steps(1);
    change(p);
    return p;
  };
  EXPECT_THAT(error_of(pyramid, with([](auto& p) { p.h = 0.0; })), HasSubstr("subdivide.h 0 is not allowed: it must be > 0 and <= 1"));
  EXPECT_THAT(error_of(pyramid, with([](auto& p) { p.h = 1.5; })), HasSubstr("subdivide.h 1.5 is not allowed"));
  EXPECT_THAT(error_of(pyramid, with([](auto& p) { p.h = NAN; })), HasSubstr("subdivide.h nan is not allowed"));
  EXPECT_THAT(error_of(pyramid, with([](auto& p) { p.roughness = -1; })), HasSubstr("roughness -1 is not allowed"));
  EXPECT_THAT(error_of(pyramid, with([](auto& p) { p.min_edge_m = 0.0; })),
              HasSubstr("subdivide.min_edge 0 is not allowed: it must be > 0 and <= 10000000 m"));
  EXPECT_THAT(error_of(pyramid, with([](auto& p) { p.min_edge_m = -2.0; })), HasSubstr("subdivide.min_edge -2 is not allowed"));
  EXPECT_THAT(error_of(pyramid, with([](auto& p) { p.steps = -1; })), HasSubstr("steps -1 is not allowed"));
  EXPECT_THAT(error_of(pyramid, with([](auto& p) { p.steps.reset(); })), HasSubstr("no stop rule"));
  EXPECT_THAT(error_of(pyramid, with([](auto& p) { p.max_triangles = 0; })),
              HasSubstr("subdivide.max_triangles 0 is not allowed: it must be between 1 and 10000000000"));
}

TEST(Subdivide, CanBeCancelled) {
  std::atomic<bool> cancel{true};
  Context context;
  context.cancel = &cancel;
  EXPECT_THROW(subdivide(build_edge_mesh(make_pyramid(10, 5)), steps(3), context), Cancelled);
}

TEST(Subdivide, PlainMeshHasUnitNormalsAndTheSameTriangles) {
  const EdgeMesh m = subdivide(build_edge_mesh(make_pyramid(1000, 600)), steps(3)).mesh;
  const TriangleMesh plain = to_triangle_mesh(m);
  ASSERT_EQ(plain.normals.size(), plain.positions.size());
  for (glm::vec3 n : plain.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
  EXPECT_EQ(plain.triangle_count(), m.triangle_count());
  std::uint64_t one = 0;
  tbb::task_arena(1).execute([&] {
    const TriangleMesh t = to_triangle_mesh(m);
    one = sansui::test::fnv1a(t.normals.data(), t.normals.size() * sizeof(glm::vec3));
  });
  EXPECT_EQ(one, sansui::test::fnv1a(plain.normals.data(), plain.normals.size() * sizeof(glm::vec3)));
}

void expect_same_bytes(const TriangleMesh& a, const TriangleMesh& b) {
  ASSERT_EQ(a.positions.size(), b.positions.size());
  ASSERT_EQ(a.indices.size(), b.indices.size());
  ASSERT_EQ(a.normals.size(), b.normals.size());
  // memcmp of empty arrays only where there are any: their data() may be null (UBSan).
  if (!a.positions.empty()) {
    EXPECT_EQ(std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(glm::vec3)), 0);
  }
  EXPECT_EQ(a.indices, b.indices);
  if (!a.normals.empty()) {
    EXPECT_EQ(std::memcmp(a.normals.data(), b.normals.data(), a.normals.size() * sizeof(glm::vec3)), 0);
  }
}

TEST(Subdivide, ToMeshGivesThePlainMeshOfSubdivideByteForByte) {
  // The last step made straight into the plain mesh (positions, corners, normals, the step's
  // edge lengths) against subdivide() then to_triangle_mesh(), over closed and open surfaces,
  // every boundary rule and direction, locked vertices, and 1 and 2 threads.
  const TriangleMesh square = test::flat_square(3, 100);
  std::vector<std::uint8_t> locks(square.positions.size(), 0);
  locks[0] = locks[5] = locks[10] = 1;
  struct Case {
    TriangleMesh mesh;
    std::vector<std::uint8_t> locks;
  };
  const Case cases[] = {{make_pyramid(1000, 600), {}}, {test::octahedron(), {}}, {square, locks}};
  for (const Case& c : cases)
    for (BoundaryMode boundary : {BoundaryMode::free, BoundaryMode::vertical, BoundaryMode::fixed})
      for (Direction direction : {Direction::normal, Direction::vertical})
        for (int k : {0, 1, 4})
          for (bool with_normals : {true, false}) {
            SubdivideParams p = steps(k, 7);
            p.boundary = boundary;
            p.direction = direction;
            const EdgeMesh coarse = build_edge_mesh(c.mesh, c.locks);
            const SubdivideResult full = subdivide(coarse, p);
            for (int threads : {1, 2}) {
              SubdividedMesh direct;
              tbb::task_arena(threads).execute([&] { direct = subdivide_to_mesh(coarse, p, with_normals); });
              expect_same_bytes(direct.mesh, to_triangle_mesh(full.mesh, with_normals));
              EXPECT_EQ(direct.stopped_by, full.stopped_by);
              ASSERT_EQ(direct.steps.size(), full.steps.size());
              for (std::size_t n = 0; n < full.steps.size(); ++n) {
                EXPECT_EQ(direct.steps[n].step, full.steps[n].step);
                EXPECT_EQ(direct.steps[n].scale_m, full.steps[n].scale_m);
                EXPECT_EQ(direct.steps[n].triangles, full.steps[n].triangles);
                EXPECT_EQ(direct.steps[n].vertices, full.steps[n].vertices);
                EXPECT_EQ(direct.steps[n].edges, full.steps[n].edges);
                EXPECT_EQ(direct.steps[n].max_edge_m, full.steps[n].max_edge_m);
                EXPECT_EQ(direct.steps[n].mean_edge_m, full.steps[n].mean_edge_m);
              }
            }
          }
}

TEST(Subdivide, ToMeshStoppedByMinEdgeGivesThePlainMeshOfSubdivide) {
  // The last step is not known before it is made: the edge form, then the plain mesh.
  SubdivideParams p;
  p.min_edge_m = 60.0;
  const EdgeMesh coarse = build_edge_mesh(make_pyramid(1000, 600));
  const SubdivideResult full = subdivide(coarse, p);
  const SubdividedMesh direct = subdivide_to_mesh(coarse, p, true);
  EXPECT_EQ(direct.stopped_by, "min-edge");
  EXPECT_EQ(direct.steps.size(), full.steps.size());
  expect_same_bytes(direct.mesh, to_triangle_mesh(full.mesh, true));
}

}  // namespace
}  // namespace sansui::mesh

namespace sansui::mesh {
namespace {

TEST(Subdivide, AgreesWithThePlainHashMapReference) {
  // Same random numbers and arithmetic, another way of finding each edge's midpoint.
  for (const TriangleMesh& input : {make_pyramid(1000, 600), test::octahedron(), test::flat_square(3, 100)}) {
    const EdgeMesh coarse = build_edge_mesh(input);
    SubdivideParams p = steps(4, 11);
    const SubdivideResult fast = subdivide(coarse, p);
    const reference::KeyedMesh slow = reference::subdivide(reference::keyed(coarse), 11, fast.steps[0].scale_m, p.h, 4);
    EXPECT_EQ(test::sorted_positions(fast.mesh.positions), test::sorted_positions(slow.mesh.positions));
  }
}

}  // namespace
}  // namespace sansui::mesh
