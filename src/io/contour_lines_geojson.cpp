// A contour map from GeoJSON: see contour_lines_geojson.hpp.
//
// One streaming pass with simdjson's On-Demand parser, straight into the lines: no document tree
// and no strtod (a 7.6 MB gdal_contour file of 1,745 lines took about 0.4 s through an nlohmann
// tree, most of a `sansui contour-dem` run). Every value is still visited and checked (numbers
// parsed, strings unescaped, the root's end reached), so text that is not JSON is refused as
// before; an error found in a feature waits until the whole text is checked, so a syntax error
// anywhere still wins, as when the text was parsed first. A feature's members may come in any
// order: its elevation is settled when the feature ends, and a geometry whose coordinates come
// before its type has them read again (a second parser over their text) once the type is known.
#include "io/contour_lines_geojson.hpp"

#include <cmath>
#include <cstdlib>
#include <memory>
#include <optional>

#include <simdjson.h>

#include "core/error.hpp"
#include "io/json_ondemand.hpp"
#include "io/json_text.hpp"

namespace sansui::io {
namespace {

namespace od = simdjson::ondemand;
static_assert(contour_map_padding >= simdjson::SIMDJSON_PADDING);

using ondemand::number_of;
using ondemand::skip;
using Point = PlanePoint;

/// The text of the JSON value starting at `start` (inside `text`), for messages and for reading a
/// value again: an array or object to its matching bracket, a string to its closing quote, any
/// other scalar to the next delimiter. Only called on text simdjson has indexed.
std::string_view value_text(std::string_view text, const char* start) {
  const std::size_t begin = static_cast<std::size_t>(start - text.data());
  std::size_t i = begin;
  int depth = 0;
  bool in_string = false;
  for (; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') {
        ++i;
      } else if (c == '"') {
        in_string = false;
        if (depth == 0) return text.substr(begin, i + 1 - begin);
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      ++depth;
    } else if (c == ']' || c == '}') {
      if (depth == 0) break;  // the end of a scalar inside its parent
      if (--depth == 0) return text.substr(begin, i + 1 - begin);
    } else if (depth == 0 && (c == ',' || c == ' ' || c == '\t' || c == '\n' || c == '\r')) {
      break;
    }
  }
  return text.substr(begin, std::min(i, text.size()) - begin);
}

/// What a feature's properties say about its elevation, settled when the feature ends.
struct Elevation {
  double z = NAN;
  std::string name;   ///< the attribute found, or empty: none
  std::string value;  ///< its JSON text, for the message
};

enum class Geometry { none, line_string, multi_line_string, polygon, multi_polygon, point, multi_point };

Geometry geometry_of(std::string_view type) {
  if (type == "LineString") return Geometry::line_string;
  if (type == "MultiLineString") return Geometry::multi_line_string;
  if (type == "Polygon") return Geometry::polygon;
  if (type == "MultiPolygon") return Geometry::multi_polygon;
  if (type == "Point") return Geometry::point;
  if (type == "MultiPoint") return Geometry::multi_point;
  return Geometry::none;
}

class Reader {
 public:
  Reader(std::string_view text, std::string_view source, const std::string& attribute, bool spot_heights)
      : text_(text), source_(source), attribute_(attribute), spot_heights_(spot_heights) {}

  ContourMap read(od::document& document) {
    document_ = &document;
    bool collection = false, has_features = false;
    if (document.type() == od::json_type::object) {
      for (auto field : document.get_object()) {
        const std::string_view key = field.unescaped_key();
        od::value value = field.value();
        if (key == "type") {
          collection = string_of(value) == "FeatureCollection";
        } else if (key == "features") {
          // The last "features" counts (as in a parsed tree).
          map_.lines.clear(), map_.spots.clear(), pending_.reset();
          has_features = value.type() == od::json_type::array;
          if (has_features)
            read_features(value.get_array());
          else
            skip(value, 1);
        } else {
          skip(value, 1);
        }
      }
    } else {
      ondemand::skip_document(document);
    }
    if (!document.current_location().error()) throw simdjson::simdjson_error(simdjson::TRAILING_CONTENT);  // not at its end
    if (!collection || !has_features) fail("{}: not a GeoJSON FeatureCollection of contour lines", source_);
    if (pending_) throw InputError(*pending_);
    if (map_.lines.empty()) fail("{}: no contour lines (LineString, MultiLineString, Polygon or MultiPolygon features)", source_);
    return std::move(map_);
  }

  // ---- checking what is not read ------------------------------------------------------------

  /// The string `value` holds, or "" for any other value (checked all through).
  std::string_view string_of(od::value value) {
    if (value.type() == od::json_type::string) return value.get_string();
    skip(value, 1);
    return {};
  }

  std::string text_of(od::value& value) { return std::string(value_text(text_, value.raw_json_token().data())); }

  /// Keeps the first error of the features; it is thrown once the whole text is checked.
  void defer(std::string message) {
    if (!pending_) pending_ = std::move(message);
  }

  // ---- features -----------------------------------------------------------------------------

  void read_features(od::array features) {
    std::size_t f = 0;
    for (auto element : features) {
      od::value feature = element.value();
      if (pending_ || feature.type() != od::json_type::object)
        skip(feature, 2);
      else
        read_feature(feature.get_object(), f);
      ++f;
    }
  }

  void read_feature(od::object feature, std::size_t f) {
    const std::size_t first_line = map_.lines.size(), first_spot = map_.spots.size();
    std::optional<Elevation> elevation;  // unset: no properties member
    Geometry kind = Geometry::none;
    bool has_geometry = false;
    std::string type_name, error;
    for (auto field : feature) {
      const std::string_view key = field.unescaped_key();
      od::value value = field.value();
      if (key == "properties") {
        elevation = elevation_of(value);
      } else if (key == "geometry") {
        // The last geometry counts: drop what an earlier one read.
        map_.lines.resize(first_line), map_.spots.resize(first_spot), error.clear();
        has_geometry = value.type() == od::json_type::object;
        kind = Geometry::none;
        type_name.clear();
        if (has_geometry)
          read_geometry(value.get_object(), f, kind, type_name, error);
        else
          skip(value, 2);
      } else {
        skip(value, 2);
      }
    }
    const bool line = kind == Geometry::line_string || kind == Geometry::multi_line_string || kind == Geometry::polygon ||
                      kind == Geometry::multi_polygon;
    const bool point = kind == Geometry::point || kind == Geometry::multi_point;
    if (!has_geometry || (!line && !(point && spot_heights_))) {
      map_.lines.resize(first_line), map_.spots.resize(first_spot);
      return;
    }
    // As before the reading was streamed: the elevation is checked first, then the coordinates.
    const Elevation found = elevation.value_or(Elevation{});
    if (found.name.empty()) {
      if (attribute_.empty())
        return defer(
            fmt::format("{}: feature {} has no elevation attribute (tried elev, ELEV, elevation, elevation_m, ELEVATION): name it with "
                        "--elevation-attribute",
                        source_, f));
      return defer(fmt::format("{}: feature {} has no attribute \"{}\" (--elevation-attribute)", source_, f, attribute_));
    }
    if (!std::isfinite(found.z))
      return defer(fmt::format("{}: feature {}: elevation {} = {} is not a finite number of metres", source_, f, found.name, found.value));
    if (!error.empty()) return defer(std::move(error));
    for (std::size_t i = first_line; i < map_.lines.size(); ++i) map_.lines[i].elevation_m = found.z;
    for (std::size_t i = first_spot; i < map_.spots.size(); ++i) map_.spots[i].elevation_m = found.z;
  }

  /// The elevation attribute among `properties` (the given name, else the first default name in
  /// their order that is there; a name given twice: its last value).
  Elevation elevation_of(od::value properties) {
    Elevation found;
    if (properties.type() != od::json_type::object) {
      skip(properties, 2);
      return found;
    }
    constexpr std::size_t not_found = std::size(default_elevation_attributes);
    std::size_t rank = not_found;  // of the default name found
    for (auto field : properties.get_object()) {
      const std::string_view key = field.unescaped_key();
      od::value value = field.value();
      std::size_t candidate = not_found;
      if (!attribute_.empty()) {
        candidate = key == attribute_ ? 0 : not_found;
      } else {
        for (std::size_t k = 0; k < not_found; ++k)
          if (key == default_elevation_attributes[k]) candidate = k;
      }
      if (candidate > rank || candidate == not_found) {
        skip(value, 3);
        continue;
      }
      rank = candidate;
      found.name = std::string(key);
      found.value = text_of(value);
      found.z = NAN;
      if (value.type() == od::json_type::number) {
        found.z = number_of(value);
      } else if (value.type() == od::json_type::string) {  // shapefile-to-GeoJSON conversions sometimes quote numbers
        const std::string text(value.get_string().value());
        char* end = nullptr;
        found.z = std::strtod(text.c_str(), &end);
        if (end == text.c_str() || *end != '\0') found.z = NAN;
      } else {
        skip(value, 3);
      }
    }
    return found;
  }

  // ---- geometry -----------------------------------------------------------------------------

  /// Whether features of this geometry are read.
  bool wanted(Geometry kind) const {
    return kind == Geometry::line_string || kind == Geometry::multi_line_string || kind == Geometry::polygon ||
           kind == Geometry::multi_polygon || ((kind == Geometry::point || kind == Geometry::multi_point) && spot_heights_);
  }

  /// Reads a geometry's lines (or spot heights) into the map, with elevation 0 until the feature
  /// ends; the first problem with them goes to `error`. The last "type" and "coordinates" count.
  void read_geometry(od::object geometry, std::size_t f, Geometry& kind, std::string& type_name, std::string& error) {
    const std::size_t first_line = map_.lines.size(), first_spot = map_.spots.size();
    std::string_view coordinates;  // the text of the last coordinates member, if an array
    bool has_coordinates = false;
    Geometry read_as = Geometry::none;  // the type they were read under
    for (auto field : geometry) {
      const std::string_view key = field.unescaped_key();
      od::value value = field.value();
      if (key == "type") {
        type_name = std::string(string_of(value));
        kind = geometry_of(type_name);
      } else if (key == "coordinates") {
        map_.lines.resize(first_line), map_.spots.resize(first_spot), error.clear();
        read_as = Geometry::none;
        const char* start = value.raw_json_token().data();
        has_coordinates = value.type() == od::json_type::array;
        if (has_coordinates && wanted(kind)) {
          read_coordinates(value, kind, f, error);
          read_as = kind;
        } else {
          skip(value, 3);
        }
        if (has_coordinates) coordinates = text_up_to_here(start);
      } else {
        skip(value, 3);
      }
    }
    if (!wanted(kind)) return;
    if (!has_coordinates) {
      error = fmt::format("{}: feature {}: the {} has no coordinates", source_, f, type_name);
      return;
    }
    if (read_as != kind) {
      // The type came after the coordinates: read them again, now that it is known, with a second
      // parser over their text (inside the first one's, so its padding follows too).
      map_.lines.resize(first_line), map_.spots.resize(first_spot), error.clear();
      if (!again_) again_ = std::make_unique<od::parser>();
      const auto readable = static_cast<std::size_t>(text_.data() + text_.size() - coordinates.data()) + simdjson::SIMDJSON_PADDING;
      od::document document = again_->iterate(simdjson::padded_string_view(coordinates.data(), coordinates.size(), readable));
      read_coordinates(document.get_value(), kind, f, error);
    }
  }

  /// The text from `start` to where the parser stands now (just past a value), without the
  /// white space before it.
  std::string_view text_up_to_here(const char* start) {
    const char* end = document_->current_location().value();
    while (end > start && (end[-1] == ' ' || end[-1] == '\t' || end[-1] == '\n' || end[-1] == '\r')) --end;
    return {start, static_cast<std::size_t>(end - start)};
  }

  void read_coordinates(od::value coordinates, Geometry kind, std::size_t f, std::string& error) {
    const char* start = coordinates.raw_json_token().data();
    od::array c = coordinates.get_array();
    switch (kind) {
      case Geometry::line_string:
        add_line(c, false, f, error);
        break;
      case Geometry::multi_line_string:
      case Geometry::polygon:
        for (auto part : c) {
          od::value line = part.value();
          if (!error.empty()) {
            skip(line, 4);
          } else if (line.type() != od::json_type::array) {
            skip(line, 4);
            error = fmt::format("{}: feature {}: coordinates must be an array of [x, y] positions", source_, f);
          } else {
            add_line(line.get_array(), kind == Geometry::polygon, f, error);
          }
        }
        break;
      case Geometry::multi_polygon:
        for (auto element : c) {
          od::value polygon = element.value();
          if (!error.empty() || polygon.type() != od::json_type::array) {
            if (error.empty()) error = fmt::format("{}: feature {}: a MultiPolygon's polygons must be arrays of rings", source_, f);
            skip(polygon, 4);
            continue;
          }
          for (auto ring_element : polygon.get_array()) {
            od::value ring = ring_element.value();
            if (!error.empty()) {
              skip(ring, 5);
            } else if (ring.type() != od::json_type::array) {
              skip(ring, 5);
              error = fmt::format("{}: feature {}: coordinates must be an array of [x, y] positions", source_, f);
            } else {
              add_line(ring.get_array(), true, f, error);
            }
          }
        }
        break;
      case Geometry::point:  // the coordinates are the position
        if (const std::optional<Point> at = position_of(c, start, f, error)) map_.spots.push_back({*at, 0.0});
        break;
      case Geometry::multi_point:
        for (auto element : c) {
          od::value p = element.value();
          if (!error.empty()) {
            skip(p, 4);
          } else if (const std::optional<Point> at = position(p, f, error)) {
            map_.spots.push_back({*at, 0.0});
          }
        }
        break;
      case Geometry::none:
        break;
    }
  }

  /// Appends the line of `positions`; on an error, sets `error` and checks the rest.
  void add_line(od::array positions, bool ring, std::size_t f, std::string& error) {
    ContourLine line;
    for (auto element : positions) {
      od::value p = element.value();
      if (!error.empty())
        skip(p, 6);
      else if (const std::optional<Point> at = position(p, f, error))
        line.points.push_back(*at);
    }
    if (!error.empty()) return;
    if (line.points.size() < 2) {
      error = fmt::format("{}: feature {}: a contour line needs at least 2 positions, it has {}", source_, f, line.points.size());
      return;
    }
    line.closed = ring || line.points.front() == line.points.back();
    if (line.closed && line.points.size() > 2 && line.points.front() == line.points.back()) line.points.pop_back();
    map_.lines.push_back(std::move(line));
  }

  /// A position [x, y, ...]: numbers in metres, finite; on an error, sets `error`.
  std::optional<Point> position(od::value p, std::size_t f, std::string& error) {
    const char* start = p.raw_json_token().data();
    if (p.type() != od::json_type::array) {
      skip(p, 6);
      error = fmt::format("{}: feature {}: position {} must be [x, y] with numbers in metres", source_, f, value_text(text_, start));
      return std::nullopt;
    }
    return position_of(p.get_array(), start, f, error);
  }

  /// The position of the array starting at `start`; more than two members are checked, not read.
  std::optional<Point> position_of(od::array a, const char* start, std::size_t f, std::string& error) {
    double xy[2] = {0.0, 0.0};
    std::size_t count = 0;
    bool numbers = true;
    for (auto element : a) {
      od::value v = element.value();
      if (count < 2 && v.type() == od::json_type::number) {
        xy[count] = number_of(v);
      } else {
        numbers = numbers && count >= 2;
        skip(v, 7);
      }
      ++count;
    }
    if (count < 2 || !numbers) {
      error = fmt::format("{}: feature {}: position {} must be [x, y] with numbers in metres", source_, f, value_text(text_, start));
      return std::nullopt;
    }
    const Point at{xy[0], xy[1]};
    if (!std::isfinite(at.x) || !std::isfinite(at.y)) {
      error = fmt::format("{}: feature {}: position {} is not finite", source_, f, value_text(text_, start));
      return std::nullopt;
    }
    return at;
  }

  std::string_view text_;
  std::string_view source_;
  const std::string& attribute_;
  bool spot_heights_;
  ContourMap map_;
  std::optional<std::string> pending_;
  std::unique_ptr<od::parser> again_;  ///< for coordinates read again
  od::document* document_ = nullptr;
};

/// "at line L, column C" of `at` in `text`.
std::string line_and_column(std::string_view text, const char* at) {
  if (at < text.data() || at > text.data() + text.size()) return {};
  std::size_t line = 1, column = 1;
  for (const char* c = text.data(); c < at; ++c) c[0] == '\n' ? (++line, column = 1) : ++column;
  return fmt::format(" at line {}, column {}", line, column);
}

}  // namespace

ContourMap parse_contour_map(std::string_view text, std::string_view source, const std::string& attribute, bool spot_heights,
                             std::size_t readable_past_end) {
  // As the shared parser: the nesting limit first, then one-line messages.
  check_json_nesting(text, source);
  // simdjson reads up to SIMDJSON_PADDING bytes past the end: in place when the caller's buffer
  // has them (read_text_file's spare capacity), else from a padded copy.
  std::optional<simdjson::padded_string> copy;
  simdjson::padded_string_view input;
  if (readable_past_end >= contour_map_padding) {
    input = simdjson::padded_string_view(text.data(), text.size(), text.size() + readable_past_end);
  } else {
    copy.emplace(text);
    input = simdjson::padded_string_view(copy->data(), copy->size(), copy->size() + simdjson::SIMDJSON_PADDING);
    text = std::string_view(copy->data(), copy->size());
  }
  od::parser parser;
  od::document document;
  Reader reader(text, source, attribute, spot_heights);
  bool iterated = false;  // a document not made has no location
  try {
    document = parser.iterate(input);
    iterated = true;
    return reader.read(document);
  } catch (const simdjson::simdjson_error& e) {
    const char* at = nullptr;
    if (iterated)
      if (auto location = document.current_location(); !location.error()) at = location.value_unsafe();
    fail("{}: not valid JSON: {}{}", source, simdjson::error_message(e.error()), at ? line_and_column(text, at) : std::string());
  }
}

}  // namespace sansui::io
