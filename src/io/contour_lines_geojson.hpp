// A contour map from GeoJSON (issue 17 item 6): every LineString, MultiLineString, Polygon and
// MultiPolygon feature is a contour line (each polygon ring a closed one) at the elevation named
// by its attribute; Point and MultiPoint features are spot heights, read when asked for.
// Coordinates are metres in a plane (x east, y north), as gdal_contour writes them in a
// projected CRS. Parsers take the file's text; reading the file is the caller's business.
#pragma once

#include <string>
#include <string_view>

#include "core/contour_lines.hpp"

namespace sansui::io {

/// The attribute names tried when none is given, in order.
inline constexpr const char* default_elevation_attributes[] = {"elev", "ELEV", "elevation", "elevation_m", "ELEVATION"};

/// Parses `text` (the contents of `source`, named in messages). `attribute`: the elevation's
/// property name, or empty for the defaults. Throws InputError for text that is not a GeoJSON
/// FeatureCollection, no line features, a feature without the attribute, or an elevation that is
/// not a finite number.
ContourMap parse_contour_map(std::string_view text, std::string_view source, const std::string& attribute, bool spot_heights);

}  // namespace sansui::io
