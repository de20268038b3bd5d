#include "contour/fourier.hpp"

#include <cmath>
#include <complex>
#include <numbers>

#include <gtest/gtest.h>

#include "contour/random_keys.hpp"
#include "tests/contour/contour_test_util.hpp"

namespace sansui::contour {
namespace {

/// A wiggly closed curve some hundreds of metres across, far from the origin.
Ring wiggly(int vertices) {
  Ring ring;
  for (int i = 0; i < vertices; ++i) {
    const double a = 2.0 * std::numbers::pi * i / vertices;
    const double r = 300.0 * (1.0 + 0.2 * std::cos(3 * a) + 0.07 * std::sin(11 * a + 0.3));
    ring.push_back({5000.0 + r * std::cos(a), -2000.0 + 0.7 * r * std::sin(a)});
  }
  return ring;
}

Steps steps(const Ring& z) {
  const double h = perimeter(z) / static_cast<double>(z.size());
  Steps w;
  for (std::size_t j = 0; j < z.size(); ++j) {
    const Point d = z[(j + 1) % z.size()] - z[j];
    w.emplace_back(d.x / h, d.y / h);
  }
  return w;
}

TEST(Fourier, ResamplingGivesEqualStepsAlongTheCurve) {
  const Ring ring = test::square(10.0);
  const Ring z = resample_closed(ring, 8);
  ASSERT_EQ(z.size(), 8u);
  const Ring expected{{0, 0}, {5, 0}, {10, 0}, {10, 5}, {10, 10}, {5, 10}, {0, 10}, {0, 5}};
  for (std::size_t i = 0; i < 8; ++i) EXPECT_NEAR(distance(z[i], expected[i]), 0.0, 1e-12) << i;
}

TEST(Fourier, DescriptorsAreThePapersDefinition) {
  // c(k) = (1/n) sum_j w(j) exp(-2 pi i jk/n), checked against the sum written out.
  const Ring z = resample_closed(wiggly(37), 16);
  const Steps w = steps(z);
  const Steps c = descriptors_of_steps(w);
  for (int k = 0; k < 16; ++k) {
    std::complex<double> sum = 0.0;
    for (int j = 0; j < 16; ++j) sum += w[static_cast<std::size_t>(j)] * std::polar(1.0, -2.0 * std::numbers::pi * j * k / 16.0);
    EXPECT_NEAR(std::abs(c[static_cast<std::size_t>(k)] - sum / 16.0), 0.0, 1e-12) << k;
  }
  // A closed curve's steps sum to zero: c(0) = 0.
  EXPECT_NEAR(std::abs(c[0]), 0.0, 1e-12);
}

TEST(Fourier, F0AtHalfNReturnsTheResampledCurveUnchanged) {
  for (int n : {8, 64, 1024, 4096}) {
    const Ring ring = wiggly(200);
    const Ring z = resample_closed(ring, n);
    const Ring out = randomise_phases(ring, {n, n / 2}, 12345);
    ASSERT_EQ(out.size(), z.size());
    for (std::size_t i = 0; i < z.size(); ++i) ASSERT_NEAR(distance(out[i], z[i]), 0.0, 1e-9) << "n " << n << " i " << i;
  }
}

TEST(Fourier, C0AndMagnitudesStayForAnyF0) {
  const Ring z = resample_closed(wiggly(300), 256);
  const Steps w = steps(z);
  const Steps before = descriptors_of_steps(w);
  for (int f0 : {0, 1, 2, 17, 64, 127, 128}) {
    const Steps after = descriptors_of_steps(randomise_step_phases(w, f0, contour_key(9, Stream::fourier_phase, 1, 0)));
    EXPECT_NEAR(std::abs(after[0] - before[0]), 0.0, 1e-12) << "f0 " << f0;
    int changed = 0;
    for (int index = 1; index < 256; ++index) {
      const int k = index < 128 ? index : index - 256;
      const auto i = static_cast<std::size_t>(index);
      EXPECT_NEAR(std::abs(after[i]), std::abs(before[i]), 1e-12) << "f0 " << f0 << " k " << k;
      if (std::abs(k) < f0 || f0 >= 128) {
        EXPECT_NEAR(std::abs(after[i] - before[i]), 0.0, 1e-12) << "f0 " << f0 << " k " << k << " must stay";
      } else {
        changed += std::abs(after[i] - before[i]) > 1e-9 * (std::abs(before[i]) + 1e-30) ? 1 : 0;
      }
    }
    if (f0 < 128) {
      EXPECT_GT(changed, 0) << "f0 " << f0;
    }
  }
}

TEST(Fourier, RandomisedCurveStaysClosedAndDeterministic) {
  const Ring ring = wiggly(300);
  const Ring a = randomise_phases(ring, {1024, 256}, 77);
  const Ring b = randomise_phases(ring, {1024, 256}, 77);
  const Ring c = randomise_phases(ring, {1024, 256}, 78);
  ASSERT_EQ(a.size(), 1024u);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  // Starts where the resampled curve starts, and the last step leads back to it (c(0) = 0):
  // the closing step is no longer than the others.
  EXPECT_EQ(a[0], resample_closed(ring, 1024)[0]);
  double longest = 0.0;
  for (std::size_t i = 0; i + 1 < a.size(); ++i) longest = std::max(longest, distance(a[i], a[i + 1]));
  EXPECT_LE(distance(a.back(), a.front()), 1.5 * longest);
  // High-frequency phases change the curve only a little: its area stays within 2 %.
  EXPECT_NEAR(signed_area(a), signed_area(ring), 0.02 * signed_area(ring));
}

}  // namespace
}  // namespace sansui::contour
