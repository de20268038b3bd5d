// Dropping nearly collinear points after the Fourier step of the revised method (Misawa, Chiba,
// Saito 1987, seeds/000, Sec. 4.3, Step 1.3): points are removed, the flattest first
// (Visvalingam-Whyatt: smallest triangle with its neighbours), until about `long_fraction` of the
// segments are longer than 2*d0, so that the next midpoint displacement has segments to work on.
#pragma once

#include <functional>

#include "contour/geometry.hpp"

namespace sansui::contour {

struct DecimateParams {
  /// 2*d0: a segment longer than this counts as long. [Units: m] [Range: > 0]
  double long_segment_m = 20.0;
  /// Stop when this fraction of the segments is long. [Range: 0 < f < 1] [Default: 0.2]
  double long_fraction = 0.2;
  /// Never keep fewer vertices than this. [Range: >= 3] [Default: 8]
  int min_vertices = 8;
  /// Local scale of long_segment_m, taken at a segment's first vertex (midpoint.hpp's `scale`).
  /// Empty: 1.
  std::function<double(Point)> scale;
};

Ring drop_collinear_points(const Ring& ring, const DecimateParams& params);

}  // namespace sansui::contour
