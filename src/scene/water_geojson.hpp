// Rivers and lakes as GeoJSON features (io/geojson_features.hpp): rivers as one LineString per
// reach (upstream to downstream) with its Strahler order, drainage area and discharge; lakes as
// one Polygon per lake (its outline traced between flooded and dry samples, islands as holes)
// with its water level, area and volume. Coordinates in metres of the heightfield's plane.
#pragma once

#include <string>

#include "core/grid.hpp"
#include "water/priority_flood.hpp"
#include "water/rivers.hpp"

namespace sansui::scene {

/// The reaches of `rivers`, positioned by `grid` (the heightfield they were traced on).
std::string rivers_to_geojson(const water::RiverNetwork& rivers, const Heightfield& grid);

/// The lakes of `lakes`; `ground` gives the plane (cell size, origin).
std::string lakes_to_geojson(const water::LakeFill& lakes, const Heightfield& ground);

}  // namespace sansui::scene
