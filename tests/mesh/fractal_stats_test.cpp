#include "mesh/fractal_stats.hpp"

#include <cstdio>

#include <gtest/gtest.h>

#include "mesh/mesh_test_util.hpp"
#include "mesh/pyramid.hpp"
#include "mesh/subdivide.hpp"

namespace sansui::mesh {
namespace {

/// Mean measured H over three seeds of `input` subdivided 7 times.
double mean_measured_h(const TriangleMesh& input, double h, Direction direction) {
  const EdgeMesh coarse = build_edge_mesh(input);
  double sum = 0.0;
  const int seeds = 3;
  for (int seed = 1; seed <= seeds; ++seed) {
    SubdivideParams p;
    p.steps = 7;
    p.h = h;
    p.seed = std::uint64_t(seed);
    p.roughness = 0.1;
    p.direction = direction;
    const SubdivideResult r = subdivide(coarse, p);
    const auto m = measure_fractal(input, to_triangle_mesh(r.mesh, false), r.steps[0].mean_edge_m, 7);
    EXPECT_TRUE(m.has_value());
    if (!m) return 0.0;
    EXPECT_GT(m->r_squared, 0.95);
    std::printf("h %.2f %s seed %d: measured %.3f (r2 %.3f, lags %d..%d, cell %.2f m, rms %.2f m)\n", h,
                direction == Direction::vertical ? "vertical" : "normal", seed, m->measured_h, m->r_squared, m->min_lag, m->max_lag,
                m->cell_size_m, m->detail_rms_m);
    sum += m->measured_h;
  }
  return sum / seeds;
}

class SubdividedRoughness : public ::testing::TestWithParam<double> {};

TEST_P(SubdividedRoughness, MovedVerticallyHeightsHaveTheHAskedFor) {
  EXPECT_NEAR(mean_measured_h(test::flat_square(4, 250), GetParam(), Direction::vertical), GetParam(), 0.1);
}

TEST_P(SubdividedRoughness, MovedAlongNormalsOnSlopesHeightsAreRougherButNotBelowHSquared) {
  // Sideways moves on a slope shift the heights by amounts as rough as themselves.
  const double h = GetParam();
  const TriangleMesh pyramid = make_pyramid(1000, 500);
  const double normal = mean_measured_h(pyramid, h, Direction::normal);
  const double vertical = mean_measured_h(pyramid, h, Direction::vertical);
  EXPECT_LT(normal, vertical + 0.05);
  EXPECT_GT(normal, h * h - 0.1);
}

INSTANTIATE_TEST_SUITE_P(Fractal, SubdividedRoughness, ::testing::Values(0.3, 0.5, 0.8));

TEST(SubdividedRoughness, NeedsEnoughSteps) {
  const TriangleMesh pyramid = make_pyramid(1000, 500);
  SubdivideParams p;
  p.steps = 4;
  const SubdivideResult r = subdivide(build_edge_mesh(pyramid), p);
  EXPECT_FALSE(measure_fractal(pyramid, to_triangle_mesh(r.mesh, false), r.steps[0].mean_edge_m, 4));
}

}  // namespace
}  // namespace sansui::mesh
