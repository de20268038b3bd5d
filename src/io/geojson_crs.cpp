// The coordinate system of an input GeoJSON: see geojson_crs.hpp.
#include "io/geojson_crs.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <simdjson.h>

#include "core/error.hpp"
#include "io/json_ondemand.hpp"
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

namespace {

namespace od = simdjson::ondemand;

using ondemand::check_scalar;
using ondemand::skip;

/// The decision of geojson_document_crs(), from the root's crs member (null: none) and the
/// bounds of its coordinates (made only when asked for).
template <class Bounds>
std::optional<Crs> crs_of(const nlohmann::json& member, Bounds&& bounds_of, std::string_view source, bool force_metres) {
  if (!member.is_null()) {
    const Crs crs = parse_crs(crs_member_text(member, source), fmt::format("{}: its crs member", source));
    if (is_local_metres(crs)) return std::nullopt;  // plane metres with no place on Earth, as Sansui writes them
    if (crs.metric) return crs;
    if (force_metres) return std::nullopt;
    if (crs.geographic)
      fail("{}: its crs member says {}, a geographic CRS in degrees; Sansui works in metres: {}", source, crs.described(), reproject);
    fail("{}: its crs member says {}, whose unit is {}, not metres: {}", source, crs.described(), crs.unit, reproject);
  }
  const CoordinateBounds bounds = bounds_of();
  if (!force_metres && looks_like_degrees(bounds))
    fail(
        "{}: it has no crs member and every coordinate lies within longitude/latitude bounds (x {:.6g}..{:.6g}, y {:.6g}..{:.6g}, under "
        "{:g} degrees across), so it looks like WGS84 degrees, GeoJSON's default: {}",
        source, bounds.min_x, bounds.max_x, bounds.min_y, bounds.max_y, lonlat_footprint_limit_deg, reproject);
  return std::nullopt;
}

/// coordinate_bounds() and the root's crs member in one streaming pass (simdjson On-Demand):
/// no document tree of a file of many megabytes for one small member. Every token is checked, so
/// text that is not JSON is refused as parse_json refuses it.
class StreamedCrs {
 public:
  /// Reads the document: the crs member's text (if the root is an object holding one) and the
  /// bounds of every position.
  void read(od::document& document) {
    document_ = &document;
    if (document.type() == od::json_type::object) {
      for (auto field : document.get_object()) {
        const std::string_view key = field.unescaped_key();
        od::value value = field.value();
        if (key == "crs") {
          crs_text_ = std::string(member_text(value));
        } else if (key == "coordinates") {
          positions(value, 1);
        } else if (key == "properties") {
          skip(value, 1);
        } else {
          walk(value, 1);
        }
      }
    } else if (document.type() == od::json_type::array) {
      for (auto element : document.get_array()) walk(element.value(), 1);
    } else {
      check_scalar(document);
    }
    if (!document.current_location().error()) throw simdjson::simdjson_error(simdjson::TRAILING_CONTENT);  // not at its end
  }

  const std::optional<std::string>& crs_text() const { return crs_text_; }
  const CoordinateBounds& bounds() const { return bounds_; }

 private:
  static void check_depth(int depth) {
    if (depth > max_json_depth) throw simdjson::simdjson_error(simdjson::DEPTH_ERROR);
  }

  /// The text of a member's value (checked all through).
  std::string_view member_text(od::value value) {
    const char* start = value.raw_json_token().data();
    skip(value, 1);
    const char* end = start;
    if (auto location = document_->current_location(); !location.error()) end = location.value_unsafe();
    while (end > start && (end[-1] == ' ' || end[-1] == '\t' || end[-1] == '\n' || end[-1] == '\r')) --end;
    return {start, static_cast<std::size_t>(end - start)};
  }

  /// walk(): objects and arrays, positions under "coordinates", nothing under "properties" or "crs".
  void walk(od::value node, int depth) {
    check_depth(depth);
    if (node.type() == od::json_type::object) {
      for (auto field : node.get_object()) {
        const std::string_view key = field.unescaped_key();
        od::value value = field.value();
        if (key == "coordinates")
          positions(value, depth + 1);
        else if (key == "properties" || key == "crs")
          skip(value, depth + 1);
        else
          walk(value, depth + 1);
      }
    } else if (node.type() == od::json_type::array) {
      for (auto element : node.get_array()) walk(element.value(), depth + 1);
    } else {
      check_scalar(node);
    }
  }

  /// add_positions(): an array whose first two members are numbers is a position; any other
  /// array holds positions further down.
  void positions(od::value node, int depth) {
    check_depth(depth);
    if (node.type() != od::json_type::array) return skip(node, depth);
    double xy[2] = {0.0, 0.0};
    std::size_t count = 0;
    bool position = true;
    for (auto element : node.get_array()) {
      od::value value = element.value();
      if (position && count < 2 && value.type() == od::json_type::number) {
        xy[count] = ondemand::number_of(value);
      } else {
        if (count < 2) position = false;
        if (position)
          skip(value, depth + 1);
        else
          positions(value, depth + 1);
      }
      ++count;
    }
    if (!position || count < 2 || !std::isfinite(xy[0]) || !std::isfinite(xy[1])) return;
    const double x = xy[0], y = xy[1];
    if (!bounds_.any) {
      bounds_ = {x, x, y, y, true};
    } else {
      bounds_.min_x = std::min(bounds_.min_x, x), bounds_.max_x = std::max(bounds_.max_x, x);
      bounds_.min_y = std::min(bounds_.min_y, y), bounds_.max_y = std::max(bounds_.max_y, y);
    }
  }

 private:
  od::document* document_ = nullptr;
  std::optional<std::string> crs_text_;
  CoordinateBounds bounds_;
};

}  // namespace

std::optional<Crs> geojson_input_crs(std::string_view text, std::string_view source, bool force_metres, std::size_t readable_past_end) {
  std::optional<simdjson::padded_string> copy;
  simdjson::padded_string_view input;
  if (readable_past_end >= simdjson::SIMDJSON_PADDING) {
    input = simdjson::padded_string_view(text.data(), text.size(), text.size() + readable_past_end);
  } else {
    copy.emplace(text);
    input = simdjson::padded_string_view(copy->data(), copy->size(), copy->size() + simdjson::SIMDJSON_PADDING);
  }
  od::parser parser;
  od::document document;
  StreamedCrs streamed;
  try {
    document = parser.iterate(input);
    streamed.read(document);
  } catch (const simdjson::simdjson_error& e) {
    if (e.error() == simdjson::DEPTH_ERROR) fail("{}: not valid JSON: arrays and objects nested more than {} deep", source, max_json_depth);
    fail("{}: not valid JSON: {}", source, simdjson::error_message(e.error()));
  }
  const nlohmann::json member = streamed.crs_text() ? parse_json(*streamed.crs_text(), source) : nlohmann::json();
  return crs_of(
      member, [&] { return streamed.bounds(); }, source, force_metres);
}

std::optional<Crs> geojson_document_crs(const nlohmann::json& root, std::string_view source, bool force_metres) {
  const nlohmann::json member = root.is_object() && root.contains("crs") ? root["crs"] : nlohmann::json();
  return crs_of(
      member, [&] { return coordinate_bounds(root); }, source, force_metres);
}

}  // namespace sansui::io
