// Midpoint displacement of contour segments (Misawa, Chiba, Saito 1987, Sec. 4.1): see midpoint.hpp.
#include "contour/midpoint.hpp"

#include <cmath>
#include <numbers>

#include "contour/random_keys.hpp"

namespace sansui::contour {
namespace {

struct Splitter {
  double max_segment, max_displacement;  // of the segment being split, scaled
  std::uint64_t sign_key, angle_key;
  double theta_min, theta_span;
  Ring& out;

  /// Appends the points strictly between a and b. `node` is the split's index in a binary heap
  /// (root 1). With theta >= 60 degrees a split can lengthen its halves, so depth is capped a few
  /// levels beyond what halving needs (and at 30, so node < 2^31).
  void split(Point a, Point b, std::int32_t segment, std::int64_t node, int depth, int max_depth) {
    const double segment_length = distance(a, b);
    if (segment_length <= max_segment || depth >= max_depth) return;
    const auto sub = static_cast<std::int32_t>(node);
    const double theta = theta_min + theta_span * uniform_at(angle_key, segment, sub);
    const double half = 0.5 * segment_length;
    const double shift = std::fmin(max_displacement, std::fabs(half * std::tan(theta)));
    const double side = uniform_at(sign_key, segment, sub) < 0.5 ? -1.0 : 1.0;
    const Point normal = (1.0 / segment_length) * left_normal(b - a);
    const Point middle = 0.5 * (a + b) + (side * shift) * normal;
    split(a, middle, segment, 2 * node, depth + 1, max_depth);
    out.push_back(middle);
    split(middle, b, segment, 2 * node + 1, depth + 1, max_depth);
  }
};

}  // namespace

Ring displace_midpoints(const Ring& ring, const MidpointDisplacementParams& params, std::uint64_t sign_key, std::uint64_t angle_key) {
  constexpr double degrees = std::numbers::pi / 180.0;
  Ring out;
  out.reserve(2 * ring.size());
  Splitter splitter{params.max_segment_m,
                    params.max_displacement_m,
                    sign_key,
                    angle_key,
                    params.theta_min_deg * degrees,
                    (params.theta_max_deg - params.theta_min_deg) * degrees,
                    out};
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    out.push_back(ring[i]);
    const Point a = ring[i], b = ring[(i + 1) % n];
    if (params.scale) {
      const double factor = params.scale(0.5 * (a + b));
      splitter.max_segment = params.max_segment_m * factor, splitter.max_displacement = params.max_displacement_m * factor;
    }
    const double halvings = std::ceil(std::log2(std::fmax(1.0, distance(a, b) / splitter.max_segment)));
    const int max_depth = static_cast<int>(std::fmin(30.0, halvings + 3.0));
    splitter.split(a, b, static_cast<std::int32_t>(i), 1, 0, max_depth);
  }
  return out;
}

}  // namespace sansui::contour
