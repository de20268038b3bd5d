// Contours as GeoJSON (RFC 7946 geometry; coordinates in metres of the seed's plane, x east,
// y north, rounded to 1 mm): a FeatureCollection with one Polygon feature per contour whose
// properties are id, level, elevation_m, parent (null for a root), index (an index contour of
// the map) and summit (no contour inside). A top-level "sansui" member, which GeoJSON readers
// ignore, names the seed contour; the run's provenance is in the sidecar (FILE.geojson.json).
#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "contour/contour_tree.hpp"

namespace sansui::scene {

/// The tree as GeoJSON text; `index_every` marks index contours as on the map.
std::string contours_to_geojson(const contour::ContourTree& tree, int index_every = 5);

/// Reads a tree written by contours_to_geojson back. Throws InputError naming `source`.
contour::ContourTree contours_from_geojson(std::string_view text, std::string_view source);

}  // namespace sansui::scene
