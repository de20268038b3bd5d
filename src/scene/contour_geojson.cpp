#include "scene/contour_geojson.hpp"

#include <climits>
#include <cmath>
#include <cstdint>

#include "contour/map_drawing.hpp"
#include "core/error.hpp"
#include "io/json_text.hpp"

namespace sansui::scene {
namespace {

using io::dump_json;
using io::json_error_text;
using io::parse_json;
using io::string_member;
using io::whole_number_in;

using contour::ContourNode;
using contour::ContourTree;
using contour::Point;

double millimetres(double v) {
  return std::round(v * 1000.0) / 1000.0;
}

}  // namespace

std::string contours_to_geojson(const ContourTree& tree, int index_every) {
  const double z0 = tree.seed_elevation(), interval = tree.interval();
  nlohmann::json features = nlohmann::json::array();
  for (std::size_t id = 0; id < tree.nodes.size(); ++id) {
    const ContourNode& node = tree.nodes[id];
    nlohmann::json ring = nlohmann::json::array();
    for (const Point& p : node.ring) ring.push_back({millimetres(p.x), millimetres(p.y)});
    if (!node.ring.empty()) ring.push_back(ring.front());
    features.push_back({{"type", "Feature"},
                        {"id", id},
                        {"geometry", {{"type", "Polygon"}, {"coordinates", nlohmann::json::array({ring})}}},
                        {"properties",
                         {{"id", id},
                          {"level", node.level},
                          {"elevation_m", node.elevation_m},
                          {"parent", node.parent < 0 ? nlohmann::json(nullptr) : nlohmann::json(node.parent)},
                          {"index", contour::is_index_level(tree.descends(static_cast<int>(id))
                                                                ? static_cast<int>(std::lround((node.elevation_m - z0) / interval))
                                                                : node.level,
                                                            z0, interval, std::max(1, index_every))},
                          {"summit", node.children.empty() && !tree.descends(static_cast<int>(id))}}}});
  }
  nlohmann::json root{{"type", "FeatureCollection"}, {"features", features}};
  root["sansui"] = {{"seed_contour", tree.seed}};
  return dump_json(root) + "\n";
}

namespace {

/// A whole number that fits an int, or an InputError naming it: nlohmann's get<int>() of a
/// fractional or huge number is undefined behaviour, and of a string an exception.
int int_member(const nlohmann::json& object, const char* key, std::string_view source, std::string_view where) {
  const nlohmann::json& value = object[key];
  const auto whole = whole_number_in(value, INT_MIN, INT_MAX);
  if (!whole) fail("{}: {} has {} {}: it must be a whole number", source, where, key, value.dump());
  return static_cast<int>(*whole);
}

}  // namespace

ContourTree contours_from_geojson(std::string_view text, std::string_view source) {
  const nlohmann::json root = parse_json(text, source);
  if (!root.is_object() || string_member(root, "type") != "FeatureCollection" || !root.contains("features"))
    fail("{}: not a FeatureCollection of contours", source);
  ContourTree tree;
  try {
    for (const auto& feature : root["features"]) {
      const auto& properties = feature.value("properties", nlohmann::json::object());
      const auto& geometry = feature.value("geometry", nlohmann::json::object());
      if (!properties.contains("level") || !properties.contains("elevation_m") || string_member(geometry, "type") != "Polygon")
        fail("{}: feature {} is not a sansui contour (Polygon with level and elevation_m)", source, tree.nodes.size());
      ContourNode node;
      const std::string where = fmt::format("feature {}", tree.nodes.size());
      node.level = int_member(properties, "level", source, where);
      node.elevation_m = properties["elevation_m"].get<double>();
      node.parent = properties.value("parent", nlohmann::json(nullptr)).is_null() ? -1 : int_member(properties, "parent", source, where);
      const auto& ring = geometry.at("coordinates").at(0);
      // at(): a missing member or a point with fewer than two numbers is an error, not a read past the end
      for (std::size_t i = 0; i + 1 < ring.size(); ++i)
        node.ring.push_back({ring.at(i).at(0).get<double>(), ring.at(i).at(1).get<double>()});
      tree.nodes.push_back(std::move(node));
    }
  } catch (const nlohmann::json::exception& e) {
    fail("{}: feature {} is not a sansui contour ({})", source, tree.nodes.size(), json_error_text(e));
  }
  for (std::size_t id = 0; id < tree.nodes.size(); ++id) {
    const int parent = tree.nodes[id].parent;
    if (parent >= static_cast<int>(tree.nodes.size())) fail("{}: contour {} names a missing parent {}", source, id, parent);
    if (parent >= 0) tree.nodes[static_cast<std::size_t>(parent)].children.push_back(static_cast<int>(id));
    if (tree.nodes[id].level == 0) tree.seed = static_cast<int>(id);
  }
  if (root.contains("sansui") && root["sansui"].is_object() && root["sansui"].contains("seed_contour"))
    tree.seed = int_member(root["sansui"], "seed_contour", source, "its sansui member");
  if (!tree.nodes.empty() && (tree.seed < 0 || tree.seed >= static_cast<int>(tree.nodes.size())))
    fail("{}: its seed contour {} is not one of its {} contours (no level 0, or a sansui seed_contour out of range)", source, tree.seed,
         tree.nodes.size());
  return tree;
}

}  // namespace sansui::scene
