// Hypsometric reshaping: see elevations.hpp.
#include "contour/elevations.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace sansui::contour {

double Hypsometry::height_at(double a) const {
  // points are sorted by height ascending, so area descending.
  if (points.empty()) return 1.0 - a;
  if (a >= points.front().first) return points.front().second;
  if (a <= points.back().first) return points.back().second;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const auto [a0, h0] = points[i - 1];
    const auto [a1, h1] = points[i];
    if (a <= a0 && a >= a1) return h0 + (h1 - h0) * (a0 - a) / (a0 - a1);
  }
  return points.back().second;
}

std::vector<double> area_per_level(const ContourTree& tree, int& lowest_level) {
  int low = 0, high = 0;
  for (const ContourNode& node : tree.nodes) low = std::min(low, node.level), high = std::max(high, node.level);
  std::vector<double> areas(static_cast<std::size_t>(high - low + 1), 0.0);
  for (const ContourNode& node : tree.nodes) areas[static_cast<std::size_t>(node.level - low)] += signed_area(node.ring);
  lowest_level = low;
  return areas;
}

void apply_hypsometry(ContourTree& tree, const Hypsometry& curve, double relief_m) {
  if (!(relief_m > 0.0) || !std::isfinite(relief_m)) fail("relief {} m is not allowed: it must be > 0", relief_m);
  // A crater's levels (descending inside their rim) keep their depth below the rim; the curve
  // reshapes the others by their own enclosed areas.
  std::vector<double> drop(tree.nodes.size(), -1.0);
  for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
    const int parent = tree.nodes[i].parent;
    if (parent >= 0 && (tree.descends(static_cast<int>(i)) || drop[static_cast<std::size_t>(parent)] >= 0.0))
      drop[i] = tree.nodes[static_cast<std::size_t>(parent)].elevation_m - tree.nodes[i].elevation_m;
  }
  ContourTree outside_craters;
  for (std::size_t i = 0; i < tree.nodes.size(); ++i)
    if (drop[i] < 0.0)
      outside_craters.nodes.push_back({{}, tree.nodes[i].level, 0.0, -1, {}}), outside_craters.nodes.back().ring = tree.nodes[i].ring;
  int low = 0;
  const std::vector<double> areas = area_per_level(outside_craters, low);
  const double seed_area = areas[static_cast<std::size_t>(-low)];
  const double z0 = tree.nodes[static_cast<std::size_t>(tree.seed)].elevation_m;
  const double h0 = curve.height_at(1.0);
  for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
    ContourNode& node = tree.nodes[i];
    if (node.level < 0 || drop[i] >= 0.0) continue;
    const double a = areas[static_cast<std::size_t>(node.level - low)] / seed_area;
    node.elevation_m = z0 + relief_m * (curve.height_at(a) - h0);
  }
  // Keep elevations strictly rising with level even where the curve is flat between points.
  int high = 0;
  for (const ContourNode& node : tree.nodes) high = std::max(high, node.level);
  std::vector<double> z(static_cast<std::size_t>(high + 1), z0);
  for (std::size_t i = 0; i < tree.nodes.size(); ++i)
    if (tree.nodes[i].level >= 0 && drop[i] < 0.0) z[static_cast<std::size_t>(tree.nodes[i].level)] = tree.nodes[i].elevation_m;
  for (std::size_t k = 1; k < z.size(); ++k) z[k] = std::max(z[k], std::nextafter(z[k - 1], INFINITY) + 1e-6 * relief_m);
  for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
    ContourNode& node = tree.nodes[i];
    if (node.level < 0) continue;
    // Parents come before their children, so a crater level follows its rim's new elevation.
    node.elevation_m =
        drop[i] >= 0.0 ? tree.nodes[static_cast<std::size_t>(node.parent)].elevation_m - drop[i] : z[static_cast<std::size_t>(node.level)];
  }
}

}  // namespace sansui::contour
