// Rivers and lakes as GeoJSON (RFC 7946 geometry; coordinates in metres of the heightfield's
// plane, x east, y north, as the contours' GeoJSON; rounded to 1 mm), for GIS tools and engines:
// rivers as one LineString feature per reach (upstream to downstream) with its Strahler order,
// drainage area and discharge; lakes as one Polygon per lake (its outline traced between flooded
// and dry samples) with its water level, area and volume. Provenance goes in the sidecar.
#pragma once

#include <string>

#include "core/grid.hpp"
#include "water/priority_flood.hpp"
#include "water/rivers.hpp"

namespace sansui::io {

/// The reaches of `rivers`, positioned by `grid` (the heightfield they were traced on).
std::string rivers_to_geojson(const water::RiverNetwork& rivers, const Heightfield& grid);

/// The lakes of `lakes`; `ground` gives the plane (cell size, origin).
std::string lakes_to_geojson(const water::LakeFill& lakes, const Heightfield& ground);

}  // namespace sansui::io
