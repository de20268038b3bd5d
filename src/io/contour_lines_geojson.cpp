// A contour map from GeoJSON: see contour_lines_geojson.hpp.
#include "io/contour_lines_geojson.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "io/json_text.hpp"

namespace sansui::io {
namespace {

using Point = PlanePoint;

Point position(const nlohmann::json& p, std::string_view source, std::size_t feature) {
  if (!p.is_array() || p.size() < 2 || !p[0].is_number() || !p[1].is_number())
    fail("{}: feature {}: position {} must be [x, y] with numbers in metres", source, feature, p.dump());
  const Point at{p[0].get<double>(), p[1].get<double>()};
  if (!std::isfinite(at.x) || !std::isfinite(at.y)) fail("{}: feature {}: position {} is not finite", source, feature, p.dump());
  return at;
}

void add_line(ContourMap& map, const nlohmann::json& positions, bool ring, double z, std::string_view source, std::size_t feature) {
  if (!positions.is_array()) fail("{}: feature {}: coordinates must be an array of [x, y] positions", source, feature);
  ContourLine line;
  line.elevation_m = z;
  for (const auto& p : positions) line.points.push_back(position(p, source, feature));
  if (line.points.size() < 2)
    fail("{}: feature {}: a contour line needs at least 2 positions, it has {}", source, feature, line.points.size());
  line.closed = ring || line.points.front() == line.points.back();
  if (line.closed && line.points.size() > 2 && line.points.front() == line.points.back()) line.points.pop_back();
  map.lines.push_back(std::move(line));
}

double elevation_of(const nlohmann::json& properties, const std::string& attribute, std::string_view source, std::size_t feature) {
  const nlohmann::json* value = nullptr;
  std::string name = attribute;
  if (properties.is_object()) {
    if (!attribute.empty()) {
      if (properties.contains(attribute)) value = &properties[attribute];
    } else {
      for (const char* candidate : default_elevation_attributes)
        if (properties.contains(candidate)) {
          value = &properties[candidate];
          name = candidate;
          break;
        }
    }
  }
  if (value == nullptr) {
    if (attribute.empty())
      fail(
          "{}: feature {} has no elevation attribute (tried elev, ELEV, elevation, elevation_m, ELEVATION): name it with "
          "--elevation-attribute",
          source, feature);
    fail("{}: feature {} has no attribute \"{}\" (--elevation-attribute)", source, feature, attribute);
  }
  double z = NAN;
  if (value->is_number())
    z = value->get<double>();
  else if (value->is_string()) {  // shapefile-to-GeoJSON conversions sometimes quote numbers
    const std::string text = value->get<std::string>();
    char* end = nullptr;
    z = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0') z = NAN;
  }
  if (!std::isfinite(z)) fail("{}: feature {}: elevation {} = {} is not a finite number of metres", source, feature, name, value->dump());
  return z;
}

}  // namespace

ContourMap parse_contour_map(std::string_view text, std::string_view source, const std::string& attribute, bool spot_heights) {
  // The shared parser: one-line messages, numbers out of a double's range, the nesting limit.
  const nlohmann::json root = parse_json(text, source);
  if (!root.is_object() || string_member(root, "type") != "FeatureCollection" || !root.contains("features") || !root["features"].is_array())
    fail("{}: not a GeoJSON FeatureCollection of contour lines", source);
  ContourMap map;
  const auto& features = root["features"];
  for (std::size_t f = 0; f < features.size(); ++f) {
    const auto& feature = features[f];
    if (!feature.is_object() || !feature.contains("geometry") || !feature["geometry"].is_object()) continue;
    const auto& geometry = feature["geometry"];
    const std::string type = string_member(geometry, "type");
    const bool line = type == "LineString" || type == "MultiLineString" || type == "Polygon" || type == "MultiPolygon";
    const bool point = type == "Point" || type == "MultiPoint";
    if (!line && !(point && spot_heights)) continue;
    const double z = elevation_of(feature.value("properties", nlohmann::json()), attribute, source, f);
    if (!geometry.contains("coordinates") || !geometry["coordinates"].is_array())
      fail("{}: feature {}: the {} has no coordinates", source, f, type);
    const auto& c = geometry["coordinates"];
    if (type == "LineString") {
      add_line(map, c, false, z, source, f);
    } else if (type == "MultiLineString") {
      for (const auto& part : c) add_line(map, part, false, z, source, f);
    } else if (type == "Polygon") {
      for (const auto& ring : c) add_line(map, ring, true, z, source, f);
    } else if (type == "MultiPolygon") {
      for (const auto& polygon : c) {
        if (!polygon.is_array()) fail("{}: feature {}: a MultiPolygon's polygons must be arrays of rings", source, f);
        for (const auto& ring : polygon) add_line(map, ring, true, z, source, f);
      }
    } else if (type == "Point") {
      map.spots.push_back({position(c, source, f), z});
    } else {
      for (const auto& p : c) map.spots.push_back({position(p, source, f), z});
    }
  }
  if (map.lines.empty()) fail("{}: no contour lines (LineString, MultiLineString, Polygon or MultiPolygon features)", source);
  return map;
}

}  // namespace sansui::io
