// Midpoint displacement of contour segments (Misawa, Chiba, Saito 1987, seeds/000, Sec. 4.1,
// Fig. 12): every segment longer than 2*d0 is split at its midpoint, recursively, until no
// segment exceeds 2*d0; the midpoint moves perpendicular to the segment, to a random side, by
// min(d'', |l tan(theta)|), 2l the segment's length, theta uniform in [theta_min, theta_max].
// (Not fractal midpoint displacement: "simply moving midpoints at random", as the paper says.)
// Both lengths may be scaled locally (`scale`), e.g. by the local contour offset.
#pragma once

#include <cstdint>
#include <functional>

#include "contour/geometry.hpp"

namespace sansui::contour {

struct MidpointDisplacementParams {
  /// Segments longer than this are split: 2*d0, d0 the mean segment length of the seed. [Units: m] [Range: > 0]
  double max_segment_m = 20.0;
  /// d'': the largest displacement. [Units: m] [Range: >= 0]
  double max_displacement_m = 3.0;
  /// Range of theta. [Units: degrees] [Range: 0 <= min <= max < 90] [Default: 0, 20]
  double theta_min_deg = 0.0;
  double theta_max_deg = 20.0;
  /// Local scale: both lengths above are multiplied by scale(m), m the midpoint of the ring's
  /// segment being split (so every split of one segment uses the same scale). Empty: 1. Where the
  /// contour offset d varies over the plane, this is its factor there, so that steep flanks
  /// (small d) get finer and smaller displacements, gentle ones coarser and larger.
  std::function<double(Point)> scale;
};

/// The displaced ring. `sign_key` and `angle_key` are the contour's random streams
/// (random_keys.hpp); a midpoint's numbers are keyed by its segment index and its position in the
/// binary tree of splits, so they do not depend on how other segments were split.
Ring displace_midpoints(const Ring& ring, const MidpointDisplacementParams& params, std::uint64_t sign_key, std::uint64_t angle_key);

}  // namespace sansui::contour
