#include "io/geojson_features.hpp"

#include <cmath>

#include "io/json_text.hpp"

namespace sansui::io {
namespace {

double millimetres(double metres) {
  return std::round(metres * 1000.0) / 1000.0;
}

nlohmann::json position(const Position& p) {
  return nlohmann::json::array({millimetres(p[0]), millimetres(p[1])});
}

std::string collection(nlohmann::json features, std::string_view layer) {
  const nlohmann::json json = {{"type", "FeatureCollection"}, {"features", std::move(features)}, {"sansui", {{"layer", layer}}}};
  return dump_json(json, 1) + "\n";
}

}  // namespace

std::string lines_to_geojson(const std::vector<LineFeature>& features, std::string_view layer) {
  nlohmann::json out = nlohmann::json::array();
  for (const LineFeature& feature : features) {
    nlohmann::json line = nlohmann::json::array();
    for (const Position& p : feature.line) line.push_back(position(p));
    out.push_back({{"type", "Feature"},
                   {"geometry", {{"type", "LineString"}, {"coordinates", std::move(line)}}},
                   {"properties", feature.properties}});
  }
  return collection(std::move(out), layer);
}

std::string polygons_to_geojson(const std::vector<PolygonFeature>& features, std::string_view layer) {
  nlohmann::json out = nlohmann::json::array();
  for (const PolygonFeature& feature : features) {
    nlohmann::json polygons = nlohmann::json::array();
    for (const PolygonRings& rings : feature.polygons) {
      nlohmann::json polygon = nlohmann::json::array();
      for (const std::vector<Position>& ring : rings) {
        nlohmann::json positions = nlohmann::json::array();
        for (const Position& p : ring) positions.push_back(position(p));
        positions.push_back(position(ring.front()));  // closed
        polygon.push_back(std::move(positions));
      }
      polygons.push_back(std::move(polygon));
    }
    out.push_back({{"type", "Feature"},
                   {"geometry", {{"type", "MultiPolygon"}, {"coordinates", std::move(polygons)}}},
                   {"properties", feature.properties}});
  }
  return collection(std::move(out), layer);
}

}  // namespace sansui::io
