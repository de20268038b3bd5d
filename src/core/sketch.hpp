// A map sketch as plain data: ridge and valley lines (and spot heights) drawn with their
// heights, read from GeoJSON by io and triangulated by mesh (mesh/sketch.hpp).
#pragma once

#include <string>
#include <vector>

namespace sansui {

/// A point of the map. [Units: m]
struct SketchPoint {
  double east_m = 0.0;
  double north_m = 0.0;
  double height_m = 0.0;
};

/// A drawn line (two or more points) or a spot height (one point).
struct SketchFeature {
  std::vector<SketchPoint> points;
  bool locked = false;  ///< its vertices are locked: the line stays exactly as drawn
  std::string label;    ///< for messages, e.g. "feature 3 (ridge)"
};

struct Sketch {
  std::vector<SketchFeature> features;
};

}  // namespace sansui
