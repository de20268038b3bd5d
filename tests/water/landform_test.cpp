// The landform measures (water/landform.hpp) on surfaces whose answer is known.
#include "water/landform.hpp"

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "core/random.hpp"
#include "terrain/midpoint.hpp"
#include "water/water_test_util.hpp"

namespace sansui::water {
namespace {

/// A random surface whose power spectrum falls as f^-beta (random phases, inverse FFT), of
/// n x n samples cut from a periodic 2n x 2n one so that it does not wrap.
Heightfield power_law_surface(int n, double beta, std::uint64_t seed) {
  const int m = 2 * n;
  std::vector<std::complex<double>> field(static_cast<std::size_t>(m) * m);
  for (int ky = 0; ky < m; ++ky)
    for (int kx = 0; kx < m; ++kx) {
      const int fx = kx < m / 2 ? kx : kx - m, fy = ky < m / 2 ? ky : ky - m;
      const double f = std::hypot(fx, fy) / m;
      const double phase = 2.0 * std::numbers::pi * rng::uniform(seed, 1, kx, ky);
      field[static_cast<std::size_t>(ky) * m + kx] = f > 0 ? std::polar(std::pow(f, -beta / 2.0), phase) : 0.0;
    }
  fft_2d(field, m, true);
  Heightfield h(n + 1, n + 1, 0.0f, 10.0);
  double variance = 0.0;
  for (const auto& v : field) variance += v.real() * v.real();
  const double scale = 100.0 / std::sqrt(variance / static_cast<double>(field.size()));
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) h(x, y) = static_cast<float>(scale * field[static_cast<std::size_t>(y) * m + x].real());
  return h;
}

TEST(Landform, SpectralExponentOfKnownSurfaces) {
  for (const double beta : {2.0, 2.8, 3.6})
    for (std::uint64_t seed : {1u, 2u}) {
      const double measured = spectral_exponent(power_law_surface(256, beta, seed));
      EXPECT_NEAR(measured, beta, 0.1) << "beta " << beta << ", seed " << seed;
    }
}

TEST(Landform, MidpointTerrainHasAboutTwoHPlusTwo) {
  // A fractional Brownian surface of Hurst exponent H: P(f) ~ f^-(2H + 2). Midpoint displacement
  // is only roughly one (its spectrum bends), hence the wide margin.
  for (const double hurst : {0.5, 0.7, 0.9}) {
    terrain::MidpointParams params;
    params.hurst = hurst;
    params.seed = 11;
    const double measured = spectral_exponent(terrain::generate_midpoint(params, 513));
    EXPECT_NEAR(measured, 2.0 * hurst + 2.0, 0.35) << "H " << hurst;
  }
}

TEST(Landform, ChannelsOfAValleyAreGentlerThanItsSides) {
  // A valley: sides of slope 0.5 falling to a channel of slope 0.01 draining north.
  Heightfield h(65, 65, 0.0f, 10.0);
  for (int y = 0; y < 65; ++y)
    for (int x = 0; x < 65; ++x) h(x, y) = static_cast<float>(0.5 * 10.0 * std::abs(x - 32) + 0.01 * 10.0 * y);
  const LandformMeasures m = measure_landform(h, std::nullopt);
  EXPECT_NEAR(m.hillslope_slope, 0.5, 0.01);
  EXPECT_NEAR(m.channel_slope, 0.01, 0.005);
  EXPECT_LT(m.channel_ratio, 0.05);
  EXPECT_DOUBLE_EQ(m.land_fraction, 1.0);
  EXPECT_EQ(m.pits, 0);
}

TEST(Landform, SeaIsNotLand) {
  Heightfield h = test::midpoint_terrain(129, 10.0, 4);
  const LandformMeasures all = measure_landform(h, std::nullopt);
  const LandformMeasures land = measure_landform(h, 0.0);
  std::size_t above = 0;
  for (float v : h.values()) above += v > 0.0f ? 1 : 0;
  EXPECT_DOUBLE_EQ(land.land_fraction, static_cast<double>(above) / static_cast<double>(h.size()));
  EXPECT_DOUBLE_EQ(all.land_fraction, 1.0);
  const auto [low, high] = std::minmax_element(h.values().begin(), h.values().end());
  EXPECT_DOUBLE_EQ(all.relief_m, static_cast<double>(*high) - *low);
  EXPECT_DOUBLE_EQ(land.relief_m, static_cast<double>(*high) - std::max(0.0, static_cast<double>(*low)));
}

TEST(Landform, TooSmallIsRefused) {
  EXPECT_NE(sansui::test::message_of([] { measure_landform(Heightfield(9, 9, 0.0f), std::nullopt); }).find("at least 17 x 17"),
            std::string::npos);
}

}  // namespace
}  // namespace sansui::water
