#include "contour/generate.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "contour/clipping.hpp"
#include "contour/crossings.hpp"
#include "contour/extract.hpp"
#include "contour/seed_input.hpp"
#include "contour/to_dem.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"
#include "core/random.hpp"
#include "io/heightmap_io.hpp"
#include "tests/contour/contour_test_util.hpp"
#include "tests/test_paths.hpp"
#include "tests/test_util.hpp"

namespace sansui::contour {
namespace {

/// A random star-shaped seed: radius 150 m modulated by a few random harmonics. Its vertices
/// crowd toward angle 0, so that many segments are longer than twice the mean and the midpoint
/// displacement has work from the first level on.
Ring random_seed(std::uint64_t seed, int vertices = 60) {
  Ring ring;
  const std::uint64_t key = rng::stream_key(seed, 99);
  double amplitude[6], phase[6];
  for (int k = 0; k < 6; ++k) {
    amplitude[k] = 0.25 * rng::to_uniform(rng::bits(key, rng::pack(k, 0))) / (1.0 + 0.5 * k);
    phase[k] = 2.0 * std::numbers::pi * rng::to_uniform(rng::bits(key, rng::pack(k, 1)));
  }
  for (int i = 0; i < vertices; ++i) {
    const double t = static_cast<double>(i) / vertices;
    const double a = 2.0 * std::numbers::pi * t * t;
    double r = 1.0;
    for (int k = 0; k < 6; ++k) r += amplitude[k] * std::cos((k + 2) * a + phase[k]);
    ring.push_back({150.0 * r * std::cos(a), 100.0 * r * std::sin(a)});
  }
  return ring;
}

GenerationParams small_params(Method method, std::uint64_t seed) {
  GenerationParams p;
  p.method = method;
  p.offset_m = 12.0;
  p.interval_m = 10.0;
  p.seed = seed;
  p.samples = 256;  // keeps the 200-mountain property test fast; n = 1024 is tested elsewhere
  p.f0 = 64;
  return p;
}

std::uint64_t hash_of(const ContourTree& tree) {
  std::uint64_t h = 0xCBF29CE484222325ull;
  for (const ContourNode& node : tree.nodes) {
    h = sansui::test::fnv1a(node.ring.data(), node.ring.size() * sizeof(Point), h);
    h = sansui::test::fnv1a(&node.parent, sizeof node.parent, h);
    h = sansui::test::fnv1a(&node.level, sizeof node.level, h);
  }
  return h;
}

/// Every invariant the tree promises, checked with the clipping library and the crossing finder.
void expect_valid_tree(const ContourTree& tree, const std::string& what) {
  for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
    const ContourNode& node = tree.nodes[i];
    ASSERT_GE(node.ring.size(), 3u) << what << " node " << i;
    EXPECT_GT(signed_area(node.ring), 0.0) << what << " node " << i << " is not counter-clockwise";
    EXPECT_TRUE(self_crossings(node.ring).empty()) << what << " node " << i << " crosses itself";
    if (node.parent >= 0) {
      const ContourNode& parent = tree.nodes[static_cast<std::size_t>(node.parent)];
      EXPECT_EQ(node.level, parent.level + 1) << what;
      EXPECT_TRUE(crossings_between(node.ring, parent.ring).empty()) << what << " node " << i << " crosses its parent";
      const double area = signed_area(node.ring);
      EXPECT_NEAR(intersection_area(node.ring, parent.ring), area, 1e-6 * area + 1e-3)
          << what << " node " << i << " is not inside its parent";
      for (int sibling : parent.children) {
        if (sibling <= static_cast<int>(i)) continue;
        const Ring& other = tree.nodes[static_cast<std::size_t>(sibling)].ring;
        EXPECT_TRUE(crossings_between(node.ring, other).empty()) << what << " siblings " << i << ", " << sibling << " cross";
        EXPECT_LT(intersection_area(node.ring, other), 1e-3) << what << " siblings " << i << ", " << sibling << " overlap";
      }
    }
  }
}

class EveryMethod : public ::testing::TestWithParam<Method> {};

TEST_P(EveryMethod, FiftyRandomSeedsGiveValidNestedContours) {
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    const ContourTree tree = generate_contours(random_seed(seed), small_params(GetParam(), seed));
    EXPECT_GT(tree.nodes.size(), 3u);
    expect_valid_tree(tree, fmt::format("{} seed {}", name_of(GetParam()), seed));
    if (HasFailure()) return;
  }
}

TEST_P(EveryMethod, OutwardContoursEncloseTheSeed) {
  GenerationParams p = small_params(GetParam(), 7);
  p.outward_levels = 3;
  const ContourTree tree = generate_contours(random_seed(7), p);
  expect_valid_tree(tree, "outward");
  const auto roots = tree.roots();
  ASSERT_EQ(roots.size(), 1u);
  EXPECT_EQ(tree.nodes[static_cast<std::size_t>(roots[0])].level, -3);
  EXPECT_DOUBLE_EQ(tree.nodes[static_cast<std::size_t>(roots[0])].elevation_m, p.resolved_z0_m() - 3 * p.interval_m);
}

TEST_P(EveryMethod, SameSeedSameContoursAnyThreadCount) {
  const GenerationParams p = small_params(GetParam(), 3);
  const Ring seed = random_seed(3);
  const std::uint64_t all = hash_of(generate_contours(seed, p));
  std::uint64_t one = 0;
  {
    ThreadLimit single(1);
    one = hash_of(generate_contours(seed, p));
  }
  EXPECT_EQ(all, one);
  GenerationParams other = p;
  other.seed = 4;
  if (GetParam() != Method::simple) {
    EXPECT_NE(hash_of(generate_contours(seed, other)), all);
  }
}

TEST_P(EveryMethod, FiftyRandomSeedsWithAVariedOffsetGiveValidNestedContours) {
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    GenerationParams p = small_params(GetParam(), seed);
    p.offset_variation = 0.7;
    const ContourTree tree = generate_contours(random_seed(seed), p);
    EXPECT_GT(tree.nodes.size(), 3u);
    expect_valid_tree(tree, fmt::format("{} varied seed {}", name_of(GetParam()), seed));
    if (HasFailure()) return;
  }
}

TEST_P(EveryMethod, FiftyRandomSeedsWithACraterGiveValidNestedContours) {
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    GenerationParams p = small_params(GetParam(), seed);
    p.crater_depth_m = 15.0;  // one whole interval and a half: the floor 15 m below the rim
    const ContourTree tree = generate_contours(random_seed(seed), p);
    expect_valid_tree(tree, fmt::format("{} crater seed {}", name_of(GetParam()), seed));
    if (HasFailure()) return;
  }
}

TEST_P(EveryMethod, FiftyRandomSeedsWithColsGiveValidNestedContours) {
  int cut = 0;
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    GenerationParams p = small_params(GetParam(), seed);
    const std::size_t plain = generate_contours(random_seed(seed), p).nodes.size();
    p.col_depth_m = 20.0;  // two intervals
    const ContourTree tree = generate_contours(random_seed(seed), p);
    cut += tree.nodes.size() != plain ? 1 : 0;
    expect_valid_tree(tree, fmt::format("{} col seed {}", name_of(GetParam()), seed));
    if (HasFailure()) return;
  }
  EXPECT_GT(cut, 5) << "too few of the seeds split: the check checks little";
}

INSTANTIATE_TEST_SUITE_P(Methods, EveryMethod, ::testing::Values(Method::simple, Method::midpoint, Method::fourier, Method::revised),
                         [](const auto& param_info) { return std::string(name_of(param_info.param)); });

TEST(Generate, DumbbellSplitsIntoExactlyTwoPeaks) {
  GenerationParams p;
  p.method = Method::simple;
  p.offset_m = 5.0;
  const ContourTree tree = generate_contours(test::dumbbell(50.0, 20.0, 12.0), p);
  EXPECT_EQ(tree.summits().size(), 2u);
  // The split happens where the neck closes: one contour with two children.
  int splits = 0;
  for (const ContourNode& node : tree.nodes) splits += node.children.size() == 2 ? 1 : 0;
  EXPECT_EQ(splits, 1);
}

/// The saddle between the highest cells west and east of x = 0 of `dem`: the lowest point of
/// the highest path between them (cells joined from the top down until the two meet).
double saddle_height(const Heightfield& dem) {
  const int w = dem.width(), h = dem.height();
  std::vector<int> order(static_cast<std::size_t>(w) * h), root(order.size(), -1);
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return dem.data()[a] > dem.data()[b]; });
  const auto find = [&](int k) {
    while (root[static_cast<std::size_t>(k)] != k)
      k = root[static_cast<std::size_t>(k)] = root[static_cast<std::size_t>(root[static_cast<std::size_t>(k)])];
    return k;
  };
  int west = -1, east = -1;
  for (int k : order) {
    if (k % w < w / 2 && west < 0) west = k;
    if (k % w > w / 2 && east < 0) east = k;
  }
  for (int k : order) {
    root[static_cast<std::size_t>(k)] = k;
    const int i = k % w, j = k / w;
    const int neighbours[4][2] = {{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}};
    for (const auto& [ni, nj] : neighbours) {
      if (ni < 0 || nj < 0 || ni >= w || nj >= h || root[static_cast<std::size_t>(nj * w + ni)] < 0) continue;
      root[static_cast<std::size_t>(find(nj * w + ni))] = find(k);
    }
    if (root[static_cast<std::size_t>(west)] >= 0 && root[static_cast<std::size_t>(east)] >= 0 && find(west) == find(east))
      return dem.data()[k];
  }
  return NAN;
}

// Issue 17 item 3: --col-depth lowers the saddle between two summits below the level where
// their common contour split, by about the depth asked (within an interval), and the contours
// stay nested.
TEST(Generate, ColDepthLowersTheSaddleBelowTheSplitLevel) {
  GenerationParams p;
  p.method = Method::simple;
  p.offset_variation = 0.0;
  p.offset_m = 10.0;
  p.interval_m = 10.0;
  const Ring seed = test::dumbbell(150.0, 40.0, 80.0);
  const ContourTree plain = generate_contours(seed, p);
  double split = NAN;
  for (const ContourNode& node : plain.nodes)
    if (node.children.size() == 2) split = node.elevation_m;
  ASSERT_TRUE(std::isfinite(split));
  ASSERT_GE(split, 20.0);  // room below the split for two levels
  DemParams frame = dem_frame_for(plain, 257);
  frame.surround = Surround::flat;
  frame.offset_m = 10.0;
  const double before = saddle_height(contours_to_dem(plain, frame));
  EXPECT_GE(before, split - 0.5);  // the method alone: the saddle at the split level or above
  for (double depth : {10.0, 20.0}) {
    p.col_depth_m = depth;
    const ContourTree tree = generate_contours(seed, p);
    expect_valid_tree(tree, fmt::format("col depth {}", depth));
    const double saddle = saddle_height(contours_to_dem(tree, frame));
    EXPECT_LT(saddle, split - depth + p.interval_m) << "depth " << depth << ", split at " << split << ", saddle " << saddle;
    EXPECT_GT(saddle, split - depth - p.interval_m) << "depth " << depth << ", split at " << split << ", saddle " << saddle;
    EXPECT_EQ(tree.summits().size(), 2u);
  }
}

/// The 800 m contour of the real DEM in examples/dem (a branching ridge), resampled every 4 m:
/// a real contour as densely traced as a digitised map's.
Ring dense_real_seed() {
  const Heightfield dem = io::read_heightmap(std::string(sansui::test::source_dir) + "/examples/dem/jacksboro_ridge.tif");
  const Ring ring = normalise_seed(pick_contour(dem, 800.0, std::nullopt), true, "jacksboro").ring;
  Ring dense;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const Point a = ring[i], b = ring[(i + 1) % n];
    const int steps = std::max(1, static_cast<int>(std::ceil(distance(a, b) / 4.0)));
    for (int k = 0; k < steps; ++k) dense.push_back(a + (static_cast<double>(k) / steps) * (b - a));
  }
  return dense;
}

/// The 90th percentile of the distance from the vertices of `tree`'s level-`level` contours to
/// `other`'s contours of that level. [Units: m]
double p90_distance_at_level(const ContourTree& tree, const ContourTree& other, int level) {
  std::vector<double> distances;
  for (const ContourNode& node : tree.nodes) {
    if (node.level != level) continue;
    for (std::size_t i = 0; i < node.ring.size(); i += 4) {
      double nearest = INFINITY;
      for (const ContourNode& o : other.nodes)
        if (o.level == level) nearest = std::min(nearest, distance_to_ring(o.ring, node.ring[i]));
      distances.push_back(nearest);
    }
  }
  if (distances.empty()) return 0.0;
  std::sort(distances.begin(), distances.end());
  return distances[distances.size() * 9 / 10];
}

// Issue 17 item 2: the midpoint displacement works at a spacing of at least d, so a densely
// sampled real seed (4 m segments, d = 30 m) gets displacements of d'' from its first levels on:
// its second contour lies visibly off the simple method's (with the seed's own 4 m spacing a
// split moved by at most 4 tan 20 deg = 1.5 m: 90 % of the contour stayed within 0.7 m of it).
TEST(Generate, MidpointDisplacesADenselySampledRealSeedToo) {
  const Ring seed = dense_real_seed();
  ASSERT_LT(mean_segment_length(seed), 4.5);
  GenerationParams p;
  p.offset_m = 30.0;
  p.offset_variation = 0.0;
  p.max_levels = 2;
  p.method = Method::simple;
  const ContourTree simple = generate_contours(seed, p);
  p.method = Method::midpoint;
  const ContourTree midpoint = generate_contours(seed, p);
  expect_valid_tree(midpoint, "dense real seed, midpoint");
  const double off = p90_distance_at_level(midpoint, simple, 2);
  EXPECT_GT(off, 0.15 * *p.offset_m) << "the midpoint method's level-2 contour is " << off << " m from the simple one's (p90)";
}

TEST(Generate, ConvexSeedShrinksToOneSummit) {
  for (Join join : {Join::extended, Join::straight, Join::arc, Join::clipped}) {
    GenerationParams p;
    p.method = Method::simple;
    p.join = join;
    p.offset_m = 5.0;
    p.offset_variation = 0.0;  // one d: about 100 / 5 levels
    const ContourTree tree = generate_contours(test::circle({0, 0}, 100.0, 90), p);
    EXPECT_EQ(tree.summits().size(), 1u) << name_of(join);
    // About 100 / 5 levels, each one ring.
    EXPECT_GE(tree.nodes.size(), 18u);
    EXPECT_LE(tree.nodes.size(), 21u);
  }
}

TEST(Generate, ElevationsAreZ0PlusLevelTimesInterval) {
  GenerationParams p = small_params(Method::revised, 5);
  p.z0_m = 300.0;
  p.interval_m = 25.0;
  const ContourTree tree = generate_contours(random_seed(5), p);
  for (const ContourNode& node : tree.nodes) EXPECT_DOUBLE_EQ(node.elevation_m, 300.0 + 25.0 * node.level);
}

TEST(Generate, RevisedWithPaperDefaultsOnTheFullSamples) {
  GenerationParams p;
  p.offset_m = 12.0;
  const ContourTree tree = generate_contours(random_seed(11), p);
  expect_valid_tree(tree, "revised n=1024");
  EXPECT_GT(tree.nodes.size(), 5u);
}

TEST(Generate, BaseElevationLimitsOutwardLevels) {
  GenerationParams p = small_params(Method::simple, 1);
  p.z0_m = 100.0;
  p.interval_m = 10.0;
  p.base_m = 65.0;
  // Three whole levels, then a last one at exactly the base (issue 17 item 4).
  EXPECT_EQ(p.resolved_outward_levels(), 4);
  EXPECT_DOUBLE_EQ(p.last_outward_fraction(), 0.5);
  const ContourTree tree = generate_contours(random_seed(1), p);
  EXPECT_EQ(tree.nodes[static_cast<std::size_t>(tree.roots()[0])].elevation_m, 65.0);
  p.outward_levels = 2;  // the stricter limit wins: the base is not reached
  EXPECT_EQ(p.resolved_outward_levels(), 2);
  EXPECT_DOUBLE_EQ(p.last_outward_fraction(), 1.0);
}

TEST(Generate, PerMethodDefaultsAreThePapers) {
  GenerationParams p;
  EXPECT_EQ(p.method, Method::revised);
  EXPECT_EQ(p.resolved_clip_factor(), 3.0);
  EXPECT_EQ(p.resolved_displacement_fraction(), 0.5);
  EXPECT_EQ(p.resolved_theta_min_deg(), 20.0);
  EXPECT_EQ(p.resolved_theta_max_deg(), 40.0);
  EXPECT_EQ(p.samples, 1024);
  EXPECT_EQ(p.f0, 256);
  EXPECT_EQ(p.long_fraction, 0.2);
  p.method = Method::midpoint;
  EXPECT_EQ(p.resolved_clip_factor(), 1.4);
  EXPECT_EQ(p.resolved_displacement_fraction(), 0.3);
  EXPECT_EQ(p.resolved_theta_min_deg(), 0.0);
  EXPECT_EQ(p.resolved_theta_max_deg(), 20.0);
  EXPECT_EQ(p.resolved_join(), Join::clipped);
}

void expect_error(const GenerationParams& p, const std::string& fragment) {
  try {
    p.validate();
    ADD_FAILURE() << "no error; expected one mentioning " << fragment;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(Generate, BadParametersAreRejectedWithTheirValue) {
  GenerationParams p;
  p.offset_m = 0.0;
  expect_error(p, "contour.offset 0 is not allowed: it must be > 0 and <= 10000000 m");
  p = {};
  p.offset_m = -2.0;
  expect_error(p, "contour.offset -2 is not allowed");
  p = {};
  p.interval_m = 0.0;
  expect_error(p, "contour.interval 0 is not allowed");
  p = {};
  p.theta_max_deg = 90.0;
  expect_error(p, "contour.theta 20,90 is not allowed: it must be 2 numbers, each >= 0 and < 90 deg");
  p = {};
  p.theta_min_deg = -1.0;
  expect_error(p, "contour.theta -1,40 is not allowed");
  p = {};
  p.f0 = 513;
  expect_error(p, "contour.f0 513 is not allowed: it must lie in 0..n/2 = 512");
  p = {};
  p.samples = 1000;
  expect_error(p, "contour.n 1000 is not allowed: it must be a power of two from 8 to 65536");
  p = {};
  p.offset_m = NAN;
  expect_error(p, "contour.offset nan is not allowed");
  p = {};
  p.loops.method = 3;
  expect_error(p, "contour.loop_removal 3 is not allowed: it must be between 1 and 2");
  p = {};
  p.clip_factor = 0.5;
  expect_error(p, "contour.c 0.5 is not allowed: it must be between 1 and 100");
}

TEST(Generate, CancellationStopsTheWork) {
  std::atomic<bool> stop{true};
  Context context;
  context.cancel = &stop;
  EXPECT_THROW(generate_contours(random_seed(1), small_params(Method::revised, 1), context), Cancelled);
}

}  // namespace
}  // namespace sansui::contour
