// The fractal field of the contour offset: see offset_field.hpp.
#include "contour/offset_field.hpp"

#include <algorithm>
#include <cmath>

#include "core/random.hpp"

namespace sansui::contour {
namespace {

constexpr std::uint64_t offset_field_stream = 0x6F66667365744Bull;

double fade(double t) {
  return t * t * t * (t * (6.0 * t - 15.0) + 10.0);
}

/// Value noise of unit wavelength at (x, y): lattice values uniform in [-1, 1], interpolated.
double value_noise(std::uint64_t seed, int octave, double x, double y) {
  const double fx = std::floor(x), fy = std::floor(y);
  const auto ix = static_cast<std::int32_t>(fx), iy = static_cast<std::int32_t>(fy);
  const double tx = fade(x - fx), ty = fade(y - fy);
  auto at = [&](std::int32_t i, std::int32_t j) {
    return 2.0 * rng::uniform(seed, offset_field_stream + static_cast<std::uint64_t>(octave), i, j) - 1.0;
  };
  const double a = at(ix, iy) + tx * (at(ix + 1, iy) - at(ix, iy));
  const double b = at(ix, iy + 1) + tx * (at(ix + 1, iy + 1) - at(ix, iy + 1));
  return a + ty * (b - a);
}

}  // namespace

OffsetField::OffsetField(double variation, double hurst, double wavelength_m, double finest_m, std::uint64_t seed)
    : variation_(variation), hurst_(hurst), wavelength_(std::max(wavelength_m, 1e-6)), octaves_(1), seed_(seed) {
  while (octaves_ < 10 && wavelength_ / std::pow(2.0, octaves_) >= finest_m) ++octaves_;
  // Value noise has a standard deviation of about 0.33; the octaves add in quadrature. Scaled so
  // that one standard deviation of the sum is 0.5 (clipped at two).
  double power = 0.0;
  for (int k = 0; k < octaves_; ++k) power += std::pow(2.0, -2.0 * hurst_ * k);
  scale_ = 0.5 / (0.33 * std::sqrt(power));
}

double OffsetField::factor(Point p) const {
  if (variation_ == 0.0) return 1.0;
  double sum = 0.0, wavelength = wavelength_, amplitude = 1.0;
  const double shrink = std::pow(2.0, -hurst_);
  for (int k = 0; k < octaves_; ++k) {
    sum += amplitude * value_noise(seed_, k, p.x / wavelength, p.y / wavelength);
    wavelength *= 0.5, amplitude *= shrink;
  }
  return mean_ * (1.0 + variation_ * std::clamp(scale_ * sum, -1.0, 1.0));
}

void OffsetField::normalise_inside(const std::vector<Ring>& rings) {
  mean_ = 1.0;
  if (constant() || rings.empty()) return;
  // The mean over a 64 x 64 lattice of points across the rings' bounds that lie inside them.
  const Box box = bounds(rings);
  constexpr int lattice = 64;
  double sum = 0.0;
  int count = 0;
  for (int j = 0; j < lattice; ++j)
    for (int i = 0; i < lattice; ++i) {
      const Point p{box.min_x + (i + 0.5) * box.width() / lattice, box.min_y + (j + 0.5) * box.height() / lattice};
      if (std::none_of(rings.begin(), rings.end(), [&](const Ring& r) { return contains(r, p); })) continue;
      sum += 1.0 / factor(p), ++count;
    }
  if (count > 0) mean_ = sum / count;
}

}  // namespace sansui::contour
