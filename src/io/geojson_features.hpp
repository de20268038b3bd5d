// Lines and polygons with their properties as a GeoJSON FeatureCollection (RFC 7946 geometry;
// coordinates in metres, x east, y north, rounded to 1 mm), for GIS tools and engines. Plain
// data: rivers, lakes and other layers are turned into features by their callers.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace sansui::io {

using Position = std::array<double, 2>;  ///< east, north. [Units: m]

struct LineFeature {
  std::vector<Position> line;  ///< two or more positions
  nlohmann::json properties = nlohmann::json::object();
};

/// One polygon: its shell, then its holes; each ring open (the writer closes it).
using PolygonRings = std::vector<std::vector<Position>>;

/// One feature of one or more polygons (a lake whose cells touch only at corners has several).
struct PolygonFeature {
  std::vector<PolygonRings> polygons;
  nlohmann::json properties = nlohmann::json::object();
};

/// One LineString feature per line; `layer` goes into the collection's "sansui" member.
std::string lines_to_geojson(const std::vector<LineFeature>& features, std::string_view layer);

/// One MultiPolygon feature per entry: one geometry type for the whole layer, as GIS tools
/// want it, whether a feature has one polygon or several.
std::string polygons_to_geojson(const std::vector<PolygonFeature>& features, std::string_view layer);

}  // namespace sansui::io
