// Coordinate reference systems (issue 14 item 3): what an input says its coordinates are, checked
// and described by PROJ (its C API and its EPSG database, proj.db, installed with libproj; no
// network), so that outputs carry the same CRS: GeoTIFF GeoKeys, the GeoJSON `crs` member, the
// sidecar's "crs". Sansui grids are planar metres, so a CRS is usable only when it is projected
// (or engineering) with metre axes; geographic (degree) CRSs are recognised so that callers can
// refuse them instead of reading degrees as metres.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace sansui::io {

struct Crs {
  int epsg = 0;             ///< the EPSG code; 0 when the CRS has none (then `wkt` says it)
  std::string name;         ///< PROJ's name: "NZGD2000 / New Zealand Transverse Mercator 2000"
  std::string wkt;          ///< WKT2:2019 as PROJ writes it
  bool geographic = false;  ///< axes in degrees (latitude, longitude), not metres
  bool metric = true;       ///< horizontal axes in metres (false: feet, degrees...)
  std::string unit;         ///< the horizontal axes' unit: "metre", "degree", "US survey foot"
  std::string id;           ///< AUTHORITY:CODE if it has one ("EPSG:2193", "OGC:CRS84"), else ""

  /// "EPSG:2193", another authority's id, or the name when there is none.
  std::string label() const;
  /// "EPSG:2193 (NZGD2000 / New Zealand Transverse Mercator 2000)", for messages.
  std::string described() const;
  bool operator==(const Crs& other) const { return epsg == other.epsg && (epsg != 0 || wkt == other.wkt); }
};

/// A CRS from text: "EPSG:2193" (any case), "urn:ogc:def:crs:EPSG::2193", "OGC:CRS84", or WKT.
/// `what` names where the text came from ("--crs", "seed.geojson's crs member"). Throws
/// InputError "WHAT 'TEXT' is not a coordinate reference system PROJ knows: ..." for an unknown
/// code, a malformed text, or an object that is not a horizontal CRS (a vertical CRS, a
/// transformation).
Crs parse_crs(std::string_view text, std::string_view what);

/// "" when `text` names a CRS the outputs can carry (one PROJ knows, projected or engineering, in
/// metres), else why not in a few words ("PROJ: crs not found", "EPSG:4326 is geographic, in
/// degrees"): for parameter rules.
std::string output_crs_problem(std::string_view text);

/// Longitude and latitude (degrees, WGS 84 axis order lon, lat) of the point `east_m`, `north_m`
/// of the projected `crs`, through PROJ; nullopt when PROJ cannot transform it.
std::optional<std::array<double, 2>> lonlat_of(const Crs& crs, double east_m, double north_m);

/// "" when the point `east_m`, `north_m` lies within the area where `crs` is valid (PROJ's area
/// of use, widened by half a degree), else the problem in words, naming the point's longitude and
/// latitude and the area. "" too when the CRS has no area of use.
std::string area_of_use_problem(const Crs& crs, double east_m, double north_m);

/// The CRS of EPSG code `code` (a GeoTIFF key). Throws InputError naming `what`.
Crs crs_from_epsg(int code, std::string_view what);

/// The sidecar's "crs" object: {"epsg": 2193 or null, "name": ..., "wkt": ...}.
nlohmann::json crs_to_sidecar(const Crs& crs);

/// The CRS as one line of WKT1 (GDAL's dialect: what its ENVI driver and .aux.xml files read);
/// empty when PROJ cannot write it so.
std::string crs_wkt1(const Crs& crs);
/// Reads a sidecar's "crs" object back (through PROJ, from the code or else the WKT).
Crs crs_from_sidecar(const nlohmann::json& value, std::string_view what);

/// Plane metres with no place on Earth: an engineering CRS ("Sansui local metres"), which outputs
/// without a CRS name (GeoTIFF, ENVI and .aux.xml headers, GeoJSON crs members) so that GIS tools
/// neither read their metres as longitude/latitude degrees nor take the files of one world for
/// different places. Read back, it means "no CRS". Version 4's GeoJSON named its datum, which a
/// GeoTIFF cannot carry; the rest is the same.
const Crs& local_metres_crs();
const Crs& version_4_local_metres_crs();
bool is_local_metres(const Crs& crs);

/// The GeoJSON `crs` member (GeoJSON 2008, which GDAL/OGR and QGIS read):
/// {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::2193"}}; for a CRS without an
/// EPSG code the name is its WKT, which OGR reads too.
nlohmann::json crs_to_geojson_member(const Crs& crs);

/// `geojson` (a text beginning with a JSON object) with the `crs` member of `crs` added as its
/// first member; unchanged when the CRS has no EPSG code.
std::string with_geojson_crs(std::string geojson, const Crs& crs);

}  // namespace sansui::io
