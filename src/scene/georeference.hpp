// The coordinate reference system of a recipe's outputs (issue 14 item 3), internal to scene/:
// georeference.crs if given, else the CRS of the source's input (a heightmap's GeoTIFF keys or
// sidecar, a seed's or contour map's GeoJSON crs member). GeoJSON inputs in degrees are refused
// here, before any work, unless georeference.force_metres.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "io/crs.hpp"
#include "scene/recipe.hpp"

namespace sansui::scene::detail {

/// The outputs' CRS (nullopt: a local plane in metres); `notes` gets a line for each choice the
/// user should hear of (a given CRS replacing the input's, an input CRS that could not carry).
/// Throws InputError for a bad CRS or an input in degrees.
std::optional<io::Crs> output_crs(const Recipe& recipe, std::vector<std::string>& notes);

/// The CRS a georeferenced output file names: the outputs' CRS; without one, "Sansui local
/// metres" (io::local_metres_crs), in every such file (GeoTIFF, ENVI and .aux.xml headers,
/// GeoJSON) from version 5 on, in GeoJSON only (its datum named) in version 4, and none before.
std::optional<io::Crs> named_crs(const std::optional<io::Crs>& crs, int version, bool geojson);

}  // namespace sansui::scene::detail
