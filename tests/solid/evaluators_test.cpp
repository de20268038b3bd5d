// The four evaluators of the solid field (seeds/002, SPEC 2) agree bit for bit, follow the
// paper's statistics, keep their memory bounds, and reject bad input with clear messages.
#include <algorithm>
#include <bit>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include "core/error.hpp"
#include "core/random.hpp"
#include "solid/evaluator.hpp"
#include "solid/node_rules.hpp"
#include "solid/type1_array.hpp"
#include "solid/type2_memo.hpp"
#include "solid/type3_ancestors.hpp"
#include "tests/test_util.hpp"

namespace sansui::solid {
namespace {

using test::message_of;

std::uint32_t bits_of(float v) {
  return std::bit_cast<std::uint32_t>(v);
}

FieldParams params_with(int levels, std::uint64_t seed = 5, double beta = 0.6) {
  FieldParams params;
  params.levels = levels;
  params.seed = seed;
  params.beta = beta;
  params.corners = {0.5f, -1.0f, 0.25f, 2.0f, -0.75f, 1.5f, 0.0f, -2.5f};
  return params;
}

/// Every evaluator variant worth comparing: Types II-IV, with and without reuse, several R2.
std::vector<std::unique_ptr<FieldEvaluator>> all_lazy_evaluators(const FieldParams& params) {
  std::vector<std::unique_ptr<FieldEvaluator>> list;
  list.push_back(make_evaluator(EvaluatorType::type2, params));
  list.push_back(make_evaluator(EvaluatorType::type3, params, {0, true}));
  list.push_back(make_evaluator(EvaluatorType::type3, params, {0, false}));
  for (int r2 : {1, params.levels / 2, params.levels}) list.push_back(make_evaluator(EvaluatorType::type4, params, {r2, true}));
  return list;
}

TEST(SolidEvaluators, AllTypesAgreeBitForBitOnEveryLatticePointAtR5) {
  const FieldParams params = params_with(5);
  const Volume volume = generate_type1(params);
  auto lazy = all_lazy_evaluators(params);
  const int last = 1 << params.levels;
  // Raster order, then the reverse, so that reuse meets both directions.
  for (int pass = 0; pass < 2; ++pass)
    for (int zz = 0; zz <= last; ++zz)
      for (int yy = 0; yy <= last; ++yy)
        for (int xx = 0; xx <= last; ++xx) {
          const int x = pass == 0 ? xx : last - xx, y = pass == 0 ? yy : last - yy, z = pass == 0 ? zz : last - zz;
          const std::uint32_t expected = bits_of(volume(x, y, z));
          for (auto& evaluator : lazy)
            ASSERT_EQ(bits_of(evaluator->at(x, y, z)), expected)
                << "type " << type_name(evaluator->type()) << " at " << x << "," << y << "," << z;
        }
}

TEST(SolidEvaluators, AllTypesAgreeOnTenThousandRandomPointsAtR9) {
  const FieldParams params = params_with(9, 77);
  auto type1 = make_evaluator(EvaluatorType::type1, params);
  auto lazy = all_lazy_evaluators(params);
  const int side = params.side();
  for (int q = 0; q < 10000; ++q) {
    const int x = static_cast<int>(rng::uniform(3, 1, q, 0) * side);
    const int y = static_cast<int>(rng::uniform(3, 1, q, 1) * side);
    const int z = static_cast<int>(rng::uniform(3, 1, q, 2) * side);
    const std::uint32_t expected = bits_of(type1->at(x, y, z));
    for (auto& evaluator : lazy)
      ASSERT_EQ(bits_of(evaluator->at(x, y, z)), expected)
          << "type " << type_name(evaluator->type()) << " at " << x << "," << y << "," << z;
    // Continuous queries interpolate the same lattice values in the same order.
    const double rx = rng::uniform(3, 2, q, 0) * (side - 1), ry = rng::uniform(3, 2, q, 1) * (side - 1),
                 rz = rng::uniform(3, 2, q, 2) * (side - 1);
    const std::uint32_t expected_sample = bits_of(type1->sample(rx, ry, rz));
    for (auto& evaluator : lazy) ASSERT_EQ(bits_of(evaluator->sample(rx, ry, rz)), expected_sample);
  }
}

TEST(SolidEvaluators, CornersKeepTheirValues) {
  const FieldParams params = params_with(4);
  const Volume volume = generate_type1(params);
  for (int i = 0; i < 8; ++i)
    EXPECT_EQ(volume((i & 1) * 16, ((i >> 1) & 1) * 16, ((i >> 2) & 1) * 16), params.corners[static_cast<std::size_t>(i)]);
}

TEST(SolidEvaluators, FewerLevelsAreTheSameFieldAtEveryOtherPoint) {
  // Node Gaussians are hashed on world coordinates: R is a resolution.
  const Volume coarse = generate_type1(params_with(4));
  const Volume fine = generate_type1(params_with(6));
  for (int z = 0; z <= 16; ++z)
    for (int y = 0; y <= 16; ++y)
      for (int x = 0; x <= 16; ++x) ASSERT_EQ(bits_of(coarse(x, y, z)), bits_of(fine(4 * x, 4 * y, 4 * z)));
}

TEST(SolidEvaluators, OneAndTwoThreadsAndTwoRunsGiveTheSameBytes) {
  const FieldParams params = params_with(7, 11);
  Volume one, two;
  tbb::task_arena(1).execute([&] { one = generate_type1(params); });
  tbb::task_arena(2).execute([&] { two = generate_type1(params); });
  const Volume again = generate_type1(params);
  EXPECT_EQ(test::fnv1a(one.values()), test::fnv1a(two.values()));
  EXPECT_EQ(test::fnv1a(one.values()), test::fnv1a(again.values()));
}

TEST(SolidEvaluators, TypeOneReportsProgressPlaneByPlaneNeverBackwards) {
  // The last level is 7/8 of the work: a report per level only would sit at 12 % and then jump.
  std::vector<double> fractions;
  Context context;
  context.on_progress = [&](std::string_view stage, double fraction) {
    EXPECT_EQ(stage, "solid");
    fractions.push_back(fraction);
  };
  tbb::task_arena(1).execute([&] { (void)generate_type1(params_with(6), context); });  // one thread: reports in order
  ASSERT_FALSE(fractions.empty());
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_EQ(fractions.back(), 1.0);
  const auto in_last_level = std::count_if(fractions.begin(), fractions.end(), [](double f) { return f > 0.13 && f < 1.0; });
  EXPECT_GE(in_last_level, 60);  // the last level's 65 planes, less the one that ends it
}

TEST(SolidEvaluators, GoldenHashOfA33CubedLattice) {
  // Fixed seed: if this changes, textures made by earlier versions cannot be rebuilt.
  FieldParams params;
  params.levels = 5;
  params.seed = 2024;
  EXPECT_EQ(test::fnv1a(generate_type1(params).values()), 16928922953408202361ull);
}

TEST(SolidEvaluators, DifferentSeedsGiveDifferentFields) {
  EXPECT_NE(test::fnv1a(generate_type1(params_with(4, 1)).values()), test::fnv1a(generate_type1(params_with(4, 2)).values()));
}

/// Displacements of the level-n nodes of a Type I lattice: value minus the mean of the parents.
std::vector<double> displacements_at_level(const Volume& v, int levels, int n) {
  std::vector<double> out;
  const int half = 1 << (levels - n), last = 1 << levels;
  for (int z = 0; z <= last; z += half)
    for (int y = 0; y <= last; y += half)
      for (int x = 0; x <= last; x += half) {
        const int lx = rules::axis_level(x, levels), ly = rules::axis_level(y, levels), lz = rules::axis_level(z, levels);
        if (std::max({lx, ly, lz}) != n) continue;
        double sum = 0.0;
        int count = 0;
        if (lx == n) {
          sum += v(x - half, y, z) + v(x + half, y, z);
          count += 2;
        }
        if (ly == n) {
          sum += v(x, y - half, z) + v(x, y + half, z);
          count += 2;
        }
        if (lz == n) {
          sum += v(x, y, z - half) + v(x, y, z + half);
          count += 2;
        }
        out.push_back(v(x, y, z) - sum / count);
      }
  return out;
}

void expect_variance_near(const std::vector<double>& d, double expected, int n) {
  double sum = 0.0, sum2 = 0.0;
  for (double v : d) {
    sum += v;
    sum2 += v * v;
  }
  const double m = static_cast<double>(d.size());
  const double variance = (sum2 - sum * sum / m) / (m - 1.0);
  // The sample variance of m normal values has standard deviation sigma^2 sqrt(2 / (m - 1)).
  const double tolerance = 5.0 * expected * std::sqrt(2.0 / (m - 1.0)) + 1e-4 * expected;
  EXPECT_NEAR(variance, expected, tolerance) << "level " << n << " over " << d.size() << " nodes";
}

TEST(SolidEvaluators, DisplacementVarianceAtLevelNIsLSquared) {
  const double beta = 0.45;
  // Deep levels from one lattice, the first levels (19 and 152 nodes each) from many seeds.
  const FieldParams params = params_with(7, 3, beta);
  const Volume volume = generate_type1(params);
  for (int n = 3; n <= 7; ++n) expect_variance_near(displacements_at_level(volume, 7, n), std::exp(-2.0 * (n - 1) * beta), n);
  std::vector<double> level1, level2;
  for (std::uint64_t seed = 0; seed < 300; ++seed) {
    const Volume small = generate_type1(params_with(2, seed, beta));
    for (double d : displacements_at_level(small, 2, 1)) level1.push_back(d);
    for (double d : displacements_at_level(small, 2, 2)) level2.push_back(d);
  }
  expect_variance_near(level1, 1.0, 1);
  expect_variance_near(level2, std::exp(-2.0 * beta), 2);
}

TEST(SolidEvaluators, TypeThreeMemoStaysWithinItsBound) {
  for (int r2 : {0, 3}) {
    const FieldParams params = params_with(9, 8);
    auto evaluator = make_evaluator(r2 == 0 ? EvaluatorType::type3 : EvaluatorType::type4, params, {r2, true});
    auto& ancestors = dynamic_cast<AncestorEvaluator&>(*evaluator);
    const int bound = AncestorEvaluator::nodes_per_level * (params.levels - r2);
    EXPECT_EQ(ancestors.memo_bytes(), static_cast<std::size_t>(params.levels - r2) * (27 * 4 + 12));
    const std::size_t bytes_before = ancestors.memory_bytes();
    int largest = 0;
    for (int q = 0; q < 20000; ++q) {
      const int side = params.side();
      const bool coherent = q < 10000;
      const int x = coherent ? q % side : static_cast<int>(rng::uniform(9, 0, q, 0) * side);
      const int y = coherent ? (q / side) % side : static_cast<int>(rng::uniform(9, 0, q, 1) * side);
      const int z = coherent ? 100 : static_cast<int>(rng::uniform(9, 0, q, 2) * side);
      (void)ancestors.at(x, y, z);
      largest = std::max(largest, ancestors.memo_nodes());
      ASSERT_LE(ancestors.memo_nodes(), bound);
    }
    EXPECT_GT(largest, params.levels - r2);  // the memo is really used
    EXPECT_EQ(ancestors.memory_bytes(), bytes_before);
  }
}

TEST(SolidEvaluators, TypeTwoRemembersEveryNodeItComputed) {
  const FieldParams params = params_with(5);
  MemoEvaluator memo(params);
  (void)memo.at(1, 1, 1);  // a finest centre: needs ancestors at every level
  const std::size_t after_one = memo.nodes();
  EXPECT_GT(after_one, 5u);
  (void)memo.at(1, 1, 1);
  EXPECT_EQ(memo.nodes(), after_one);
  EXPECT_GT(memo.peak_memory_bytes(), after_one * 12);
}

TEST(SolidEvaluators, ClonesGiveTheSameValues) {
  const FieldParams params = params_with(6);
  for (auto type : {EvaluatorType::type1, EvaluatorType::type2, EvaluatorType::type3, EvaluatorType::type4}) {
    auto evaluator = make_evaluator(type, params, {3, true});
    auto clone = evaluator->clone();
    for (int q = 0; q < 200; ++q) {
      const int x = (q * 7) % 65, y = (q * 13) % 65, z = (q * 29) % 65;
      ASSERT_EQ(bits_of(evaluator->at(x, y, z)), bits_of(clone->at(x, y, z)));
    }
  }
}

// ---- bad input ----

TEST(SolidEvaluators, BadInputIsRejectedWithAClearMessage) {
  FieldParams params;
  params.levels = 0;
  EXPECT_EQ(message_of([&] { make_evaluator(EvaluatorType::type3, params); }),
            "solid_field.levels 0 is not allowed: it must be between 1 and 20");
  params.levels = 21;
  EXPECT_EQ(message_of([&] { make_evaluator(EvaluatorType::type3, params); }),
            "solid_field.levels 21 is not allowed: it must be between 1 and 20");
  params.levels = 4;
  params.beta = 0.0;
  EXPECT_EQ(message_of([&] { make_evaluator(EvaluatorType::type2, params); }),
            "solid_field.beta 0 is not allowed: it must be > 0 and <= 100");
  params.beta = -1.0;
  EXPECT_NE(message_of([&] { make_evaluator(EvaluatorType::type2, params); }).find("beta -1"), std::string::npos);
  params.beta = 0.5;
  params.corners[3] = std::nanf("");
  EXPECT_EQ(message_of([&] { make_evaluator(EvaluatorType::type1, params); }),
            "solid_field.corners 0,0,0,nan,0,0,0,0 is not allowed: it must be 8 numbers, all finite");
  params.corners[3] = 0.0f;
  EXPECT_EQ(message_of([&] { make_evaluator(EvaluatorType::type4, params, {5, true}); }), "R2 = 5 is not allowed: it must be 0..R (R = 4)");
  auto evaluator = make_evaluator(EvaluatorType::type3, params);
  EXPECT_EQ(message_of([&] { evaluator->sample(1.0, 16.5, 2.0); }),
            "point (1, 16.5, 2) is outside the block: coordinates must be in [0, 16]");
  EXPECT_EQ(message_of([&] { evaluator->sample(-0.1, 1.0, 2.0); }),
            "point (-0.1, 1, 2) is outside the block: coordinates must be in [0, 16]");
  EXPECT_NE(message_of([&] { evaluator->sample(std::nan(""), 1.0, 2.0); }), "(no error)");
  EXPECT_EQ(message_of([&] { type_from_name("V"); }), "type 'V' is unknown: allowed are I, II, III, IV");
}

TEST(SolidEvaluators, MemoryChecksSayHowMuchWouldBeNeeded) {
  FieldParams params;
  params.levels = 11;
  EXPECT_EQ(message_of([&] { check_fits(EvaluatorType::type1, params, 0, 0, std::size_t{16} << 30); }),
            "Type I at R = 11 needs 34.4 GB for its 2049^3 lattice, more than the 17.2 GB of memory available: use --type III or IV");
  EXPECT_EQ(message_of([&] { check_fits(EvaluatorType::type3, params, 0, 0, 1000); }), "(no error)");
  params.levels = 20;
  EXPECT_EQ(message_of([&] { check_fits(EvaluatorType::type4, params, 11, 0, std::size_t{16} << 30); }),
            "Type IV with R2 = 11 needs 34.4 GB for its 2049^3 array, more than the 17.2 GB of memory available: use a smaller --r2");
  params.levels = 10;
  EXPECT_NE(message_of([&] {
              check_fits(EvaluatorType::type2, params, 0, 1e9, std::size_t{16} << 30);
            }).find("Type II at R = 10 needs about 40.0 GB"),
            std::string::npos);
}

}  // namespace
}  // namespace sansui::solid
