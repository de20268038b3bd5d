// Hypsometric reshaping: see elevations.hpp.
#include "contour/elevations.hpp"

#include <algorithm>
#include <charconv>
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

Hypsometry parse_hypsometry(std::string_view text, std::string_view source) {
  Hypsometry curve;
  int line_number = 0;
  bool header_seen = false;
  std::size_t start = 0;
  auto number = [](std::string_view s, double& value) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
    return error == std::errc() && end == s.data() + s.size() && !s.empty();
  };
  while (start < text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++line_number;
    if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    if (line.find_first_not_of(" \t\r") == std::string_view::npos) continue;
    const auto comma = line.find(',');
    double a = 0.0, h = 0.0;
    if (comma == std::string_view::npos || !number(line.substr(0, comma), a) || !number(line.substr(comma + 1), h)) {
      if (curve.points.empty() && !header_seen) {  // a header such as "area,height"
        header_seen = true;
        continue;
      }
      fail("{}:{}: '{}' is not a point of a hypsometric curve: give area,height as fractions", source, line_number, line);
    }
    if (!(a >= 0.0 && a <= 1.0 && h >= 0.0 && h <= 1.0))
      fail("{}:{}: area {} and height {} must both lie in [0, 1]", source, line_number, a, h);
    curve.points.emplace_back(a, h);
  }
  if (curve.points.size() < 2) fail("{}: a hypsometric curve needs at least 2 points, found {}", source, curve.points.size());
  std::sort(curve.points.begin(), curve.points.end(), [](const auto& x, const auto& y) { return x.second < y.second; });
  for (std::size_t i = 1; i < curve.points.size(); ++i)
    if (!(curve.points[i].second > curve.points[i - 1].second && curve.points[i].first < curve.points[i - 1].first))
      fail("{}: the curve must have strictly falling area as height rises (at height {})", source, curve.points[i].second);
  return curve;
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
  int low = 0;
  const std::vector<double> areas = area_per_level(tree, low);
  const double seed_area = areas[static_cast<std::size_t>(-low)];
  const double z0 = tree.nodes[static_cast<std::size_t>(tree.seed)].elevation_m;
  const double h0 = curve.height_at(1.0);
  for (ContourNode& node : tree.nodes) {
    if (node.level < 0) continue;
    const double a = areas[static_cast<std::size_t>(node.level - low)] / seed_area;
    node.elevation_m = z0 + relief_m * (curve.height_at(a) - h0);
  }
  // Keep elevations strictly rising with level even where the curve is flat between points.
  int high = 0;
  for (const ContourNode& node : tree.nodes) high = std::max(high, node.level);
  std::vector<double> z(static_cast<std::size_t>(high + 1), z0);
  for (const ContourNode& node : tree.nodes)
    if (node.level >= 0) z[static_cast<std::size_t>(node.level)] = node.elevation_m;
  for (std::size_t k = 1; k < z.size(); ++k) z[k] = std::max(z[k], std::nextafter(z[k - 1], INFINITY) + 1e-6 * relief_m);
  for (ContourNode& node : tree.nodes)
    if (node.level >= 0) node.elevation_m = z[static_cast<std::size_t>(node.level)];
}

}  // namespace sansui::contour
