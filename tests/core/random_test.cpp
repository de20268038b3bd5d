#include "core/random.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "tests/test_util.hpp"

namespace sansui::rng {
namespace {

struct Moments {
  double mean = 0, variance = 0, skewness = 0, kurtosis = 0;
};

template <class F>
Moments moments_of(int count, F sample) {
  std::vector<double> values(static_cast<std::size_t>(count));
  double sum = 0;
  for (int i = 0; i < count; ++i) sum += values[static_cast<std::size_t>(i)] = sample(i);
  Moments m;
  m.mean = sum / count;
  double m2 = 0, m3 = 0, m4 = 0;
  for (double v : values) {
    const double d = v - m.mean;
    m2 += d * d;
    m3 += d * d * d;
    m4 += d * d * d * d;
  }
  m.variance = m2 / count;
  m.skewness = (m3 / count) / std::pow(m.variance, 1.5);
  m.kurtosis = (m4 / count) / (m.variance * m.variance);
  return m;
}

constexpr int samples = 1 << 20;

TEST(Random, UniformHasTheMomentsOfUniform01) {
  const Moments m = moments_of(samples, [](int i) { return uniform(42, 3, i % 1024, i / 1024); });
  EXPECT_NEAR(m.mean, 0.5, 0.002);  // sd of the mean: 0.29 / 1024
  EXPECT_NEAR(m.variance, 1.0 / 12, 0.001);
  EXPECT_NEAR(m.skewness, 0.0, 0.01);
  EXPECT_NEAR(m.kurtosis, 1.8, 0.01);
}

TEST(Random, GaussianHasTheMomentsOfAStandardNormal) {
  const Moments m = moments_of(samples, [](int i) { return gaussian(7, 1, i % 1024, i / 1024); });
  EXPECT_NEAR(m.mean, 0.0, 0.005);  // sd of the mean: 1 / 1024
  EXPECT_NEAR(m.variance, 1.0, 0.005);
  EXPECT_NEAR(m.skewness, 0.0, 0.01);
  EXPECT_NEAR(m.kurtosis, 3.0, 0.03);
}

TEST(Random, GaussianTailsHaveNormalProbabilities) {
  int beyond2 = 0, beyond3 = 0;
  for (int i = 0; i < samples; ++i) {
    const float g = std::abs(gaussian(11, 0, i, 5));
    beyond2 += g > 2.0f;
    beyond3 += g > 3.0f;
  }
  EXPECT_NEAR(beyond2 / double(samples), 0.0455, 0.001);
  EXPECT_NEAR(beyond3 / double(samples), 0.0027, 0.0003);
}

/// Pearson correlation of two samplers over the same index range.
template <class F, class G>
double correlation(F f, G g) {
  double sf = 0, sg = 0, sff = 0, sgg = 0, sfg = 0;
  const int n = 1 << 18;
  for (int i = 0; i < n; ++i) {
    const double a = f(i), b = g(i);
    sf += a, sg += b, sff += a * a, sgg += b * b, sfg += a * b;
  }
  const double cov = sfg / n - (sf / n) * (sg / n);
  return cov / std::sqrt((sff / n - (sf / n) * (sf / n)) * (sgg / n - (sg / n) * (sg / n)));
}

TEST(Random, NeighbouringCoordinatesAreUncorrelated) {
  const double bound = 4.0 / std::sqrt(double(1 << 18));  // four standard errors
  auto at = [](int dx, int dy) { return [=](int i) { return double(gaussian(5, 2, i % 512 + dx, i / 512 + dy)); }; };
  EXPECT_LT(std::abs(correlation(at(0, 0), at(1, 0))), bound);
  EXPECT_LT(std::abs(correlation(at(0, 0), at(0, 1))), bound);
  EXPECT_LT(std::abs(correlation(at(0, 0), at(1, 1))), bound);
  auto at3 = [](int dz) { return [=](int i) { return uniform(5, 2, i % 64, (i / 64) % 64, i / 4096 + dz); }; };
  EXPECT_LT(std::abs(correlation(at3(0), at3(1))), bound);
}

TEST(Random, StreamsAndSeedsAreIndependent) {
  const double bound = 4.0 / std::sqrt(double(1 << 18));
  auto stream = [](std::uint64_t seed, std::uint64_t s) { return [=](int i) { return double(gaussian(seed, s, i % 512, i / 512)); }; };
  EXPECT_LT(std::abs(correlation(stream(1, 0), stream(1, 1))), bound);
  EXPECT_LT(std::abs(correlation(stream(1, 4), stream(1, 5))), bound);
  EXPECT_LT(std::abs(correlation(stream(1, 0), stream(2, 0))), bound);
}

TEST(Random, GoldenValuesStayTheSame) {
  // A change here changes every terrain and texture ever generated: bump the version if meant.
  std::vector<float> values;
  std::vector<double> uniforms;
  for (int i = 0; i < 1000; ++i) {
    values.push_back(gaussian(1, i % 7, i, -i));
    uniforms.push_back(uniform(2, 3, i, i % 13, i / 13));
  }
  EXPECT_EQ(test::fnv1a(std::span<const float>(values)), 7437946937418320475ull);
  EXPECT_EQ(test::fnv1a(std::span<const double>(uniforms)), 3727338836190999039ull);
}

TEST(Random, GaussianIsTheInverseNormalCdfOfItsUniform) {
  // The mapping is monotone in the top bits and symmetric.
  float previous = -10.0f;
  for (std::uint64_t k = 0; k < (1u << 23); k += 4099) {
    const float g = to_gaussian(k << 41);
    EXPECT_GT(g, previous);
    previous = g;
  }
  EXPECT_EQ(to_gaussian(0), -to_gaussian(~0ull));
  EXPECT_NEAR(to_gaussian(0), -5.2947, 1e-3);
}

}  // namespace
}  // namespace sansui::rng
