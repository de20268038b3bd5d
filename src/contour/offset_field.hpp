// A smooth fractal field of the contour offset d over the plane (issue 17 item 2): d varies
// along each contour and between levels, so a mountain gets steep and gentle sides instead of one
// slope everywhere. factor(p) = 1 + variation * f(p), f a sum of octaves of smoothly interpolated
// lattice noise (value noise, quintic fade), octave k of wavelength L / 2^k and amplitude 2^(-H k),
// scaled to unit range and clipped to [-1, 1]. Lattice values are pure functions of (seed, octave,
// lattice point) through core/random.hpp: the same seed gives the same field in any order.
#pragma once

#include <cstdint>

#include "contour/geometry.hpp"

namespace sansui::contour {

class OffsetField {
 public:
  /// `wavelength_m`: the largest wavelength (L); octaves down to `finest_m`, at most 10.
  OffsetField(double variation, double hurst, double wavelength_m, double finest_m, std::uint64_t seed);
  /// The offset at p is d * factor(p), factor in [1 - variation, 1 + variation].
  double factor(Point p) const;
  bool constant() const { return variation_ == 0.0; }

 private:
  double variation_, hurst_, wavelength_;
  int octaves_;
  std::uint64_t seed_;
  double scale_;
};

}  // namespace sansui::contour
