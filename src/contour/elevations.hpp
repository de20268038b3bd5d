// Reshaping a mountain by its elevations (Misawa, Chiba, Saito 1987, seeds/000, Sec. 5: "the
// slope is not constant"; SPEC 1.3). By default contour k stands at z0 + k dz. A hypsometric
// (altitude-area) curve reassigns the inward elevations: with A_k the area enclosed by level k as
// a fraction of the seed's area, z_k = z0 + relief * h(A_k), h the curve's relative height at
// relative area A_k (Strahler's hypsometric curve: a = area above, h = relative height). The
// other handle, a per-level offset d, is GenerationParams::offset_schedule_m.
#pragma once

#include <string_view>
#include <utility>
#include <vector>

#include "contour/contour_tree.hpp"

namespace sansui::contour {

struct Hypsometry {
  /// (area fraction a, height fraction h) pairs, h increasing and a decreasing strictly,
  /// a and h in [0, 1].
  std::vector<std::pair<double, double>> points;

  /// Relative height at relative area a (linear between points, clamped at the ends).
  double height_at(double area_fraction) const;
};

/// Reassigns the elevations of the seed's inward levels (level >= 0) by the curve. `relief_m` is
/// the height of the curve's top above z0; outward levels keep z0 - k dz. [Units: m] [Range: > 0]
void apply_hypsometry(ContourTree& tree, const Hypsometry& curve, double relief_m);

/// Enclosed area per level (sum over the level's contours), index = level - lowest level.
std::vector<double> area_per_level(const ContourTree& tree, int& lowest_level);

}  // namespace sansui::contour
