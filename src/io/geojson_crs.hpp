// The coordinate system of an input GeoJSON (a seed contour, a contour map): its `crs` member
// (GeoJSON 2008: {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::2193"}}, or
// {"type": "EPSG", "properties": {"code": 2193}}), or, without one, a look at the coordinates:
// RFC 7946 GeoJSON is longitude/latitude, so a file whose coordinates all lie within
// [-180, 180] x [-90, 90] over a footprint of a few degrees is taken for degrees. Degrees are
// refused (never read as metres) unless the caller forces metres.
#pragma once

#include <optional>
#include <string_view>

#include "io/crs.hpp"

namespace sansui::io {

/// Coordinates within longitude/latitude bounds spanning less than this are taken for degrees
/// when a GeoJSON has no crs member: no real seed or contour map in metres is under 5 m wide.
/// [Units: deg]
inline constexpr double lonlat_footprint_limit_deg = 5.0;

/// The bounding box of every position in a GeoJSON document.
struct CoordinateBounds {
  double min_x = 0.0, max_x = 0.0, min_y = 0.0, max_y = 0.0;
  bool any = false;
};
CoordinateBounds coordinate_bounds(const nlohmann::json& root);

/// True when `bounds` look like longitude/latitude degrees (see above).
bool looks_like_degrees(const CoordinateBounds& bounds);

/// For inputs with no way to say their CRS (a CSV seed): throws InputError naming `source` when
/// `bounds` look like degrees, unless `force_metres`.
void refuse_degrees(const CoordinateBounds& bounds, std::string_view source, bool force_metres);

/// The CRS of the GeoJSON `text` (the contents of `source`, named in messages): its crs member,
/// or nullopt (plane metres, no CRS known). Throws InputError for a malformed or unknown crs
/// member, and, unless `force_metres`, for a geographic or non-metre crs member or a file without
/// one that looks like degrees. With `force_metres` such a file is read as metres without a CRS.
/// Read in one streaming pass (simdjson), as parse_contour_map(): `readable_past_end` as there.
std::optional<Crs> geojson_input_crs(std::string_view text, std::string_view source, bool force_metres, std::size_t readable_past_end = 0);
/// The same for a parsed document.
std::optional<Crs> geojson_document_crs(const nlohmann::json& root, std::string_view source, bool force_metres);

}  // namespace sansui::io
