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

/// Parses `text` (the contents of `source`, named in messages) in one streaming pass (simdjson).
/// `attribute`: the elevation's property name, or empty for the defaults. Throws InputError, one
/// line, for text that is not JSON (as parse_json, io/json_text.hpp) or not a GeoJSON
/// FeatureCollection, no line features, a feature without the attribute, an elevation that is
/// not a finite number, or a position that is not [x, y] in finite numbers.
/// `readable_past_end`: bytes after the text that may be read (not written), such as the spare
/// capacity of the string holding it (read_text_file's `spare_bytes`); with at least
/// contour_map_padding the text is read in place, else from a copy.
ContourMap parse_contour_map(std::string_view text, std::string_view source, const std::string& attribute, bool spot_heights,
                             std::size_t readable_past_end = 0);

/// The bytes past the end of its text that parse_contour_map() needs to read it in place.
inline constexpr std::size_t contour_map_padding = 64;

}  // namespace sansui::io
