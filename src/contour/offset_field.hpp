// A smooth fractal field of the contour offset d over the plane (issue 17 item 2): d varies
// along each contour and between levels, so a mountain gets steep and gentle sides instead of one
// slope everywhere. factor(p) = 1 + variation * f(p), f a sum of octaves of smoothly interpolated
// lattice noise (value noise, quintic fade), octave k of wavelength L / 2^k and amplitude 2^(-H k),
// scaled to unit range and clipped to [-1, 1]. Lattice values are pure functions of (seed, octave,
// lattice point) through core/random.hpp: the same seed gives the same field in any order.
#pragma once

#include <cstdint>
#include <vector>

#include "contour/geometry.hpp"

namespace sansui::contour {

class OffsetField {
 public:
  /// `wavelength_m`: the largest wavelength (L); octaves down to `finest_m`, at most 10.
  OffsetField(double variation, double hurst, double wavelength_m, double finest_m, std::uint64_t seed);
  /// The offset at p is d * factor(p), factor in [m (1 - variation), m (1 + variation)], m = 1
  /// unless normalised.
  double factor(Point p) const;
  bool constant() const { return variation_ == 0.0; }
  /// Scales the factor (m above) so that the mean of 1 / factor over the inside of `rings` is 1.
  /// A mountain's relief is dz times the levels on the way up, the path's length over d, so the
  /// field's largest waves, which may lie mostly above or below 0 over a seed, would otherwise
  /// make one seed's mountain half as high as another's; normalised, the relief the derived d
  /// aims at (scale.hpp) holds for any field, and only the slopes vary.
  void normalise_inside(const std::vector<Ring>& rings);

 private:
  double variation_, hurst_, wavelength_;
  int octaves_;
  std::uint64_t seed_;
  double scale_;
  double mean_ = 1.0;  // m
};

}  // namespace sansui::contour
