// GeoJSON map sketches (see sketch_geojson.hpp), parsed with nlohmann::json.
#include "io/sketch_geojson.hpp"

#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "io/json_text.hpp"
#include "io/text_file.hpp"

namespace sansui::io {
namespace {

using nlohmann::json;

struct Reader {
  const std::string& name;
  Sketch sketch;

  std::string describe(std::size_t number, const json& properties) const {
    std::string label = fmt::format("feature {}", number);
    std::vector<std::string> words;
    for (const char* key : {"name", "kind"})
      if (properties.is_object() && properties.contains(key) && properties[key].is_string())
        words.push_back(properties[key].get<std::string>());
    if (!words.empty()) label += fmt::format(" ({})", fmt::join(words, ", "));
    return label;
  }

  SketchPoint point(const json& position, const json& properties, std::size_t k, const std::string& label) const {
    if (!position.is_array() || position.size() < 2 || !position[0].is_number() || !position[1].is_number())
      fail("{}: {} has a position that is not [east, north] or [east, north, height] numbers: {}", name, label, position.dump());
    SketchPoint p{position[0].get<double>(), position[1].get<double>(), 0.0};
    if (position.size() >= 3 && position[2].is_number()) {
      p.height_m = position[2].get<double>();
    } else if (properties.is_object() && properties.contains("heights")) {
      const json& heights = properties["heights"];
      if (!heights.is_array() || k >= heights.size() || !heights[k].is_number())
        fail("{}: {} has a \"heights\" property without a number for point {}", name, label, k + 1);
      p.height_m = heights[k].get<double>();
    } else if (properties.is_object() && properties.contains("height")) {
      if (!properties["height"].is_number()) fail("{}: {} has a \"height\" that is not a number", name, label);
      p.height_m = properties["height"].get<double>();
    } else {
      fail("{}: {} has no height: give each position a third number, or the feature a \"height\" property (metres)", name, label);
    }
    return p;
  }

  void add_line(const json& positions, const json& properties, bool locked, const std::string& label, std::size_t min_points) {
    if (!positions.is_array() || positions.size() < min_points) fail("{}: {} needs at least {} positions", name, label, min_points);
    SketchFeature feature{{}, locked, label};
    for (std::size_t k = 0; k < positions.size(); ++k) feature.points.push_back(point(positions[k], properties, k, label));
    sketch.features.push_back(std::move(feature));
  }

  void add_feature(const json& geometry, const json& properties, std::size_t number) {
    if (geometry.is_null()) return;  // allowed by GeoJSON: a feature without a place
    const std::string label = describe(number, properties);
    if (!geometry.is_object() || !geometry.contains("type") || !geometry["type"].is_string())
      fail("{}: {} has no geometry \"type\"", name, label);
    if (!properties.is_null() && !properties.is_object()) fail("{}: {} has \"properties\" that are not an object", name, label);
    bool locked = false;
    if (properties.is_object() && properties.contains("lock")) {
      const json& lock = properties["lock"];
      if (!lock.is_boolean() && !lock.is_number()) fail("{}: {} has a \"lock\" that is not true or false", name, label);
      locked = lock.is_boolean() ? lock.get<bool>() : lock.get<double>() != 0.0;
    }
    const std::string type = geometry["type"].get<std::string>();
    const json& c = geometry.contains("coordinates") ? geometry["coordinates"] : json();
    auto parts = [&](const json& list) {
      if (!list.is_array()) fail("{}: {} ({}) has no coordinates array", name, label, type);
      return list;
    };
    if (type == "LineString") {
      add_line(c, properties, locked, label, 2);
    } else if (type == "MultiLineString") {
      std::size_t part = 0;
      for (const json& line : parts(c)) add_line(line, properties, locked, fmt::format("{}, line {}", label, ++part), 2);
    } else if (type == "Point") {
      add_line(json::array({c}), properties, locked, label, 1);
    } else if (type == "MultiPoint") {
      std::size_t part = 0;
      for (const json& p : parts(c)) add_line(json::array({p}), properties, locked, fmt::format("{}, point {}", label, ++part), 1);
    } else if (type == "Polygon" || type == "MultiPolygon") {
      const json polygons = type == "Polygon" ? json::array({c}) : c;
      std::size_t part = 0;
      for (const json& polygon : parts(polygons))
        for (const json& ring : parts(polygon)) add_line(ring, properties, locked, fmt::format("{}, ring {}", label, ++part), 4);
    } else {
      fail(
          "{}: {} has geometry type \"{}\": allowed are LineString, MultiLineString, Point, MultiPoint, Polygon, "
          "MultiPolygon",
          name, label, type);
    }
  }
};

}  // namespace

Sketch parse_sketch_geojson(std::string_view text, const std::string& name) {
  const json document = parse_json(text, name);
  Reader reader{name, {}};
  const std::string type = document.is_object() && document.contains("type") && document["type"].is_string()
                               ? document["type"].get<std::string>()
                               : std::string();
  if (type == "FeatureCollection") {
    if (!document.contains("features") || !document["features"].is_array())
      fail("{}: the FeatureCollection has no \"features\" array", name);
    std::size_t number = 0;
    for (const json& feature : document["features"]) {
      ++number;
      if (!feature.is_object() || !feature.contains("geometry"))
        fail("{}: feature {} is not a GeoJSON Feature with a \"geometry\"", name, number);
      reader.add_feature(feature["geometry"], feature.value("properties", json()), number);
    }
  } else if (type == "Feature") {
    reader.add_feature(document.value("geometry", json()), document.value("properties", json()), 1);
  } else if (!type.empty()) {
    reader.add_feature(document, json(), 1);
  } else {
    fail("{} is not GeoJSON: expected an object with \"type\": \"FeatureCollection\"", name);
  }
  if (reader.sketch.features.empty()) fail("{} has no lines or points", name);
  return std::move(reader.sketch);
}

Sketch read_sketch_geojson(const std::filesystem::path& path) {
  return parse_sketch_geojson(read_text_file(path, std::size_t{64} << 20), path.string());
}

}  // namespace sansui::io
