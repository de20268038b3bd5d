// Small helpers shared by the contour tests.
#pragma once

#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "contour/geometry.hpp"

namespace sansui::contour::test {

inline std::string describe(const Ring& ring) {
  std::string s;
  for (const Point& p : ring) s += fmt::format("({:.4f}, {:.4f}) ", p.x, p.y);
  return s;
}

/// True if `actual` equals `expected` up to a cyclic shift, vertex by vertex within `tolerance`.
inline ::testing::AssertionResult same_ring(const Ring& actual, const Ring& expected, double tolerance) {
  if (actual.size() != expected.size())
    return ::testing::AssertionFailure() << "sizes " << actual.size() << " vs " << expected.size() << "\nactual:   " << describe(actual)
                                         << "\nexpected: " << describe(expected);
  const std::size_t n = actual.size();
  for (std::size_t shift = 0; shift < n; ++shift) {
    bool all = true;
    for (std::size_t i = 0; i < n && all; ++i) all = distance(actual[(i + shift) % n], expected[i]) <= tolerance;
    if (all) return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "\nactual:   " << describe(actual) << "\nexpected: " << describe(expected);
}

inline Ring square(double side) {
  return {{0, 0}, {side, 0}, {side, side}, {0, side}};
}

inline Ring circle(Point centre, double radius, int vertices) {
  Ring ring;
  for (int k = 0; k < vertices; ++k) {
    const double a = 2.0 * std::numbers::pi * k / vertices;
    ring.push_back({centre.x + radius * std::cos(a), centre.y + radius * std::sin(a)});
  }
  return ring;
}

/// Two discs of radius r joined by a neck of width `neck` (counter-clockwise).
inline Ring dumbbell(double r, double gap, double neck, int per_disc = 64) {
  Ring ring;
  const double half = 0.5 * neck;
  const double cx = r + 0.5 * gap;  // disc centres at -cx and +cx
  const double a0 = std::asin(half / r);
  // Right disc, from the neck's lower side around to its upper side.
  for (int k = 0; k <= per_disc; ++k) {
    const double a = std::numbers::pi + a0 + (2.0 * std::numbers::pi - 2.0 * a0) * k / per_disc;
    ring.push_back({cx + r * std::cos(a), r * std::sin(a)});
  }
  for (int k = 0; k <= per_disc; ++k) {
    const double a = a0 + (2.0 * std::numbers::pi - 2.0 * a0) * k / per_disc;
    ring.push_back({-cx + r * std::cos(a), r * std::sin(a)});
  }
  return ring;
}

}  // namespace sansui::contour::test
