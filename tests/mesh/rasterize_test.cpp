#include "mesh/rasterize.hpp"

#include <cmath>
#include <limits>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include "core/error.hpp"
#include "mesh/mesh_test_util.hpp"
#include "mesh/pyramid.hpp"
#include "mesh/subdivide.hpp"
#include "test_util.hpp"

namespace sansui::mesh {
namespace {

using ::testing::HasSubstr;

TriangleMesh rough_pyramid(Direction direction, int steps, std::uint64_t seed = 1) {
  SubdivideParams p;
  p.steps = steps;
  p.seed = seed;
  p.direction = direction;
  p.boundary = BoundaryMode::vertical;
  p.roughness = 0.3;
  return to_triangle_mesh(subdivide(build_edge_mesh(make_pyramid(1024, 600)), p).mesh, false);
}

std::uint64_t hash_of(const Heightfield& h) {
  return sansui::test::fnv1a(h.values());
}

/// The highest triangle over (x, z) by brute force, or nullopt.
std::optional<double> highest_at(const TriangleMesh& m, double x, double z) {
  std::optional<double> best;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]], c = m.positions[m.indices[3 * t + 2]];
    const double area = (double(b.x) - a.x) * (double(c.z) - a.z) - (double(b.z) - a.z) * (double(c.x) - a.x);
    if (area == 0) continue;
    const double wb = ((x - a.x) * (double(c.z) - a.z) - (z - a.z) * (double(c.x) - a.x)) / area;
    const double wc = ((double(b.x) - a.x) * (z - a.z) - (double(b.z) - a.z) * (x - a.x)) / area;
    if (wb < -1e-9 || wc < -1e-9 || wb + wc > 1 + 1e-9) continue;
    const double y = a.y + wb * (double(b.y) - a.y) + wc * (double(c.y) - a.y);
    best = best ? std::max(*best, y) : y;
  }
  return best;
}

TEST(Rasterize, SamplesAtVerticesHoldTheVertexHeights) {
  // Moved vertically, the vertices of step 4 stand on a 32 m grid (the pyramid's faces are
  // half squares from the corners to the apex): one sample each.
  const TriangleMesh m = rough_pyramid(Direction::vertical, 4);
  const Heightfield dem = rasterize(m, frame_with_cell(m, 32.0));
  ASSERT_EQ(dem.width(), 33);
  ASSERT_EQ(dem.height(), 33);
  for (glm::vec3 p : m.positions) {
    const int i = int(std::lround((p.x - dem.origin_x_m) / 32.0)), j = int(std::lround((p.z - dem.origin_y_m) / 32.0));
    EXPECT_NEAR(dem(i, j), p.y, 1e-4 * (1.0 + std::abs(p.y)));
  }
}

TEST(Rasterize, EverySampleIsTheHighestSurfaceAboveIt) {
  // Moved along normals the surface overhangs in places: compare with brute force.
  const TriangleMesh m = rough_pyramid(Direction::normal, 3, 5);
  const RasterFrame frame = frame_with_cell(m, 23.0);
  const Heightfield dem = rasterize(m, frame, -1000.0f);
  int covered = 0;
  for (int j = 0; j < dem.height(); ++j)
    for (int i = 0; i < dem.width(); ++i) {
      const auto expected = highest_at(m, frame.origin_x_m + i * frame.cell_size_m, frame.origin_y_m + j * frame.cell_size_m);
      if (!expected) continue;
      ++covered;
      EXPECT_NEAR(dem(i, j), *expected, 1e-3) << i << "," << j;
    }
  EXPECT_GT(covered, dem.width() * dem.height() / 2);
}

TEST(Rasterize, HighestOfTwoOverlappingTrianglesWinsElsewhereFill) {
  TriangleMesh m;
  m.positions = {{0, 1, 0}, {0, 1, 10}, {10, 1, 0}, {0, 5, 0}, {0, 5, 10}, {10, 5, 10}, {20, 0, 20}};
  m.indices = {0, 1, 2, 3, 4, 5};
  RasterFrame frame{0, 0, 1, 21, 21};
  const Heightfield dem = rasterize(m, frame, -7.0f);
  EXPECT_EQ(dem(0, 0), 5.0f);                    // both: the higher
  EXPECT_EQ(dem(8, 1), 1.0f);                    // only the low one
  EXPECT_EQ(dem(1, 8), 5.0f);                    // only the high one
  EXPECT_EQ(dem(15, 15), -7.0f);                 // neither
  EXPECT_EQ(rasterize(m, frame)(15, 15), 1.0f);  // default fill: lowest used vertex
  EXPECT_EQ(dem.origin_x_m, 0.0);
}

TEST(Rasterize, TrianglesFarOutsideTheFrameAreClipped) {
  TriangleMesh m;
  m.positions = {{-1e30f, 3, -1e30f}, {1e30f, 3, -1e30f}, {0, 3, 1e30f}, {5, 9, 5}, {6, 9, 5}, {5, 9, 6}};
  m.indices = {0, 2, 1, 3, 5, 4};
  const Heightfield dem = rasterize(m, RasterFrame{0, 0, 1, 11, 11});
  EXPECT_EQ(dem(0, 0), 3.0f);
  EXPECT_EQ(dem(5, 5), 9.0f);
  m.positions[4].y = NAN;
  EXPECT_THROW(rasterize(m, RasterFrame{0, 0, 1, 11, 11}), InputError);
}

TEST(Rasterize, SharedEdgesLeaveNoHoles) {
  const TriangleMesh m = test::flat_square(7, 3.0f);
  const Heightfield dem = rasterize(m, frame_with_cell(m, 0.75), -1.0f);
  for (float v : dem.values()) ASSERT_EQ(v, 0.0f);
}

TEST(Rasterize, SameBytesForOneOrManyThreads) {
  const TriangleMesh m = rough_pyramid(Direction::normal, 5, 3);
  const RasterFrame frame = square_frame(m, 513);
  std::uint64_t one = 0;
  tbb::task_arena(1).execute([&] {
    const Heightfield d = rasterize(m, frame);
    one = sansui::test::fnv1a(d.values());
  });
  const Heightfield d = rasterize(m, frame);  // const: values() is a span of const float
  EXPECT_EQ(one, sansui::test::fnv1a(d.values()));
  // A coarse mesh on a fine grid is split by rows: still the same.
  const TriangleMesh coarse = make_pyramid(1000, 500);
  const RasterFrame fine = square_frame(coarse, 1025);
  std::uint64_t coarse_one = 0;
  tbb::task_arena(1).execute([&] { coarse_one = hash_of(rasterize(coarse, fine)); });
  EXPECT_EQ(coarse_one, hash_of(rasterize(coarse, fine)));
}

TEST(Rasterize, FramesCoverTheFootprint) {
  const TriangleMesh m = make_pyramid(1000, 500);
  const RasterFrame f = frame_with_cell(m, 10.0);
  EXPECT_EQ(f.width, 101);
  EXPECT_EQ(f.height, 101);
  TriangleMesh wide = m;
  for (glm::vec3& p : wide.positions) p.x *= 2;
  const RasterFrame s = square_frame(wide, 201);
  EXPECT_EQ(s.width, 201);
  EXPECT_DOUBLE_EQ(s.cell_size_m, 10.0);
  EXPECT_DOUBLE_EQ(s.origin_y_m, -500.0);  // the shorter side centred
}

TEST(Rasterize, BadFramesAreRefusedWithAMessage) {
  const TriangleMesh m = make_pyramid(1000, 500);
  auto error = [](auto f) {
    try {
      f();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(error([&] { frame_with_cell(m, 0.0); }), HasSubstr("cell size 0 m is not allowed: it must be > 0"));
  EXPECT_THAT(error([&] { frame_with_cell(m, -1.0); }), HasSubstr("cell size -1 m is not allowed"));
  EXPECT_THAT(error([&] { frame_with_cell(m, 0.001); }), HasSubstr("more than 65537 per side: give a larger cell size"));
  EXPECT_THAT(error([&] { square_frame(m, 1); }), HasSubstr("a DEM of 1 samples per side is not allowed"));
  EXPECT_THAT(error([&] { rasterize(TriangleMesh{}, RasterFrame{0, 0, 1, 2, 2}); }), HasSubstr("the mesh is empty"));
  EXPECT_THAT(error([&] { rasterize(m, RasterFrame{0, 0, 1, 0, 2}); }), HasSubstr("a DEM of 0 x 2 samples is not allowed"));
}

}  // namespace
}  // namespace sansui::mesh
