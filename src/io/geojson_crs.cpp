// The coordinate system of an input GeoJSON: see geojson_crs.hpp.
#include "io/geojson_crs.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"
#include "io/json_text.hpp"

namespace sansui::io {
namespace {

constexpr const char* reproject =
    "reproject it to a projected CRS in metres (e.g. ogr2ogr -t_srs EPSG:32633 out.geojson IN.geojson, the UTM zone of the place) or pass "
    "--force-metres (georeference.force_metres) if the numbers are metres";

void add_positions(const nlohmann::json& node, CoordinateBounds& bounds) {
  if (!node.is_array()) return;
  if (node.size() >= 2 && node[0].is_number() && node[1].is_number()) {
    const double x = node[0].get<double>(), y = node[1].get<double>();
    if (!std::isfinite(x) || !std::isfinite(y)) return;
    if (!bounds.any) {
      bounds = {x, x, y, y, true};
    } else {
      bounds.min_x = std::min(bounds.min_x, x), bounds.max_x = std::max(bounds.max_x, x);
      bounds.min_y = std::min(bounds.min_y, y), bounds.max_y = std::max(bounds.max_y, y);
    }
    return;
  }
  for (const auto& child : node) add_positions(child, bounds);
}

void walk(const nlohmann::json& node, CoordinateBounds& bounds, int depth) {
  if (depth > 64) return;  // parse_json limits nesting already; this bounds the recursion on its own
  if (node.is_object()) {
    for (auto it = node.begin(); it != node.end(); ++it) {
      if (it.key() == "coordinates")
        add_positions(it.value(), bounds);
      else if (it.key() != "properties" && it.key() != "crs")
        walk(it.value(), bounds, depth + 1);
    }
  } else if (node.is_array()) {
    for (const auto& child : node) walk(child, bounds, depth + 1);
  }
}

/// The text of a crs member that PROJ can read.
std::string crs_member_text(const nlohmann::json& member, std::string_view source) {
  const std::string type =
      member.is_object() && member.contains("type") && member["type"].is_string() ? member["type"].get<std::string>() : "";
  const nlohmann::json properties = member.is_object() ? member.value("properties", nlohmann::json::object()) : nlohmann::json();
  if (type == "name" && properties.is_object() && properties.contains("name") && properties["name"].is_string())
    return properties["name"].get<std::string>();
  if (type == "EPSG" && properties.is_object() && properties.contains("code") && properties["code"].is_number_integer())
    return fmt::format("EPSG:{}", properties["code"].get<long long>());
  fail(
      "{}: its crs member {} is not one Sansui reads: use {{\"type\": \"name\", \"properties\": {{\"name\": "
      "\"urn:ogc:def:crs:EPSG::CODE\"}}}}",
      source, member.dump().substr(0, 120));
}

}  // namespace

CoordinateBounds coordinate_bounds(const nlohmann::json& root) {
  CoordinateBounds bounds;
  walk(root, bounds, 0);
  return bounds;
}

bool looks_like_degrees(const CoordinateBounds& b) {
  return b.any && b.min_x >= -180.0 && b.max_x <= 180.0 && b.min_y >= -90.0 && b.max_y <= 90.0 &&
         std::max(b.max_x - b.min_x, b.max_y - b.min_y) < lonlat_footprint_limit_deg;
}

void refuse_degrees(const CoordinateBounds& bounds, std::string_view source, bool force_metres) {
  if (!force_metres && looks_like_degrees(bounds))
    fail(
        "{}: every coordinate lies within longitude/latitude bounds (x {:.6g}..{:.6g}, y {:.6g}..{:.6g}, under {:g} degrees across), so "
        "it looks like degrees, not metres: {}",
        source, bounds.min_x, bounds.max_x, bounds.min_y, bounds.max_y, lonlat_footprint_limit_deg, reproject);
}

std::optional<Crs> geojson_input_crs(std::string_view text, std::string_view source, bool force_metres) {
  return geojson_document_crs(parse_json(text, source), source, force_metres);
}

std::optional<Crs> geojson_document_crs(const nlohmann::json& root, std::string_view source, bool force_metres) {
  if (root.is_object() && root.contains("crs") && !root["crs"].is_null()) {
    const Crs crs = parse_crs(crs_member_text(root["crs"], source), fmt::format("{}: its crs member", source));
    if (is_local_metres(crs)) return std::nullopt;  // plane metres with no place on Earth, as Sansui writes them
    if (crs.metric) return crs;
    if (force_metres) return std::nullopt;
    if (crs.geographic)
      fail("{}: its crs member says {}, a geographic CRS in degrees; Sansui works in metres: {}", source, crs.described(), reproject);
    fail("{}: its crs member says {}, whose unit is {}, not metres: {}", source, crs.described(), crs.unit, reproject);
  }
  const CoordinateBounds bounds = coordinate_bounds(root);
  if (!force_metres && looks_like_degrees(bounds))
    fail(
        "{}: it has no crs member and every coordinate lies within longitude/latitude bounds (x {:.6g}..{:.6g}, y {:.6g}..{:.6g}, under "
        "{:g} degrees across), so it looks like WGS84 degrees, GeoJSON's default: {}",
        source, bounds.min_x, bounds.max_x, bounds.min_y, bounds.max_y, lonlat_footprint_limit_deg, reproject);
  return std::nullopt;
}

}  // namespace sansui::io
