// A given contour map as plain data: lines with their elevations and spot heights, as digitised
// maps or gdal_contour give them. io reads them (io/contour_lines_geojson.hpp); contour turns them
// into a DEM (contour/contours_to_dem.hpp).
#pragma once

#include <vector>

#include "core/plane_point.hpp"

namespace sansui {

/// A contour line: an open polyline or a closed ring (the last point joins the first).
struct ContourLine {
  std::vector<PlanePoint> points;
  bool closed = false;
  double elevation_m = 0.0;
};

struct SpotHeight {
  PlanePoint at;
  double elevation_m = 0.0;
};

struct ContourMap {
  std::vector<ContourLine> lines;
  std::vector<SpotHeight> spots;
};

}  // namespace sansui
