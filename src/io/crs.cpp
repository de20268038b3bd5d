// Coordinate reference systems through PROJ's C API: see crs.hpp.
#include "io/crs.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <memory>
#include <optional>
#include <utility>

#include <fmt/format.h>
#include <proj.h>

#include "core/error.hpp"
#include "core/params.hpp"
#include "io/json_text.hpp"

namespace sansui::io {
namespace {

/// One PROJ context per call: contexts are not shared between threads, and one costs little next
/// to the database look-up it makes.
struct ProjContext {
  PJ_CONTEXT* get() const { return context.get(); }
  std::unique_ptr<PJ_CONTEXT, decltype(&proj_context_destroy)> context{proj_context_create(), &proj_context_destroy};
};

struct Object {
  Object(PJ* p = nullptr) : pj(p) {}
  Object(const Object&) = delete;
  Object& operator=(const Object&) = delete;
  Object(Object&& other) noexcept : pj(std::exchange(other.pj, nullptr)) {}
  ~Object() {
    if (pj != nullptr) proj_destroy(pj);
  }
  PJ* pj;
};

std::string short_text(std::string_view text) {
  std::string shown(text.substr(0, 60));
  std::replace_if(
      shown.begin(), shown.end(), [](char c) { return c == '\n' || c == '\r' || c == '\t'; }, ' ');
  return text.size() > 60 ? shown + "..." : shown;
}

const char* allowed = "give EPSG:CODE (e.g. EPSG:2193) or the CRS's WKT, as gdalsrsinfo prints them";

const char* type_name(PJ_TYPE type) {
  switch (type) {
    case PJ_TYPE_VERTICAL_CRS:
      return "vertical CRS";
    case PJ_TYPE_GEOCENTRIC_CRS:
      return "geocentric CRS";
    case PJ_TYPE_ELLIPSOID:
      return "ellipsoid";
    case PJ_TYPE_PRIME_MERIDIAN:
      return "prime meridian";
    case PJ_TYPE_CONVERSION:
    case PJ_TYPE_TRANSFORMATION:
    case PJ_TYPE_CONCATENATED_OPERATION:
    case PJ_TYPE_OTHER_COORDINATE_OPERATION:
      return "coordinate operation";
    case PJ_TYPE_GEODETIC_REFERENCE_FRAME:
    case PJ_TYPE_DYNAMIC_GEODETIC_REFERENCE_FRAME:
    case PJ_TYPE_VERTICAL_REFERENCE_FRAME:
    case PJ_TYPE_DYNAMIC_VERTICAL_REFERENCE_FRAME:
    case PJ_TYPE_DATUM_ENSEMBLE:
      return "datum";
    default:
      return "object of another kind";
  }
}

/// The horizontal part of a CRS: a compound CRS's first component, a bound CRS's source.
Object horizontal_part(PJ_CONTEXT* context, PJ* crs) {
  switch (proj_get_type(crs)) {
    case PJ_TYPE_COMPOUND_CRS:
      return Object(proj_crs_get_sub_crs(context, crs, 0));
    case PJ_TYPE_BOUND_CRS:
      return Object(proj_get_source_crs(context, crs));
    default:
      return Object(proj_clone(context, crs));
  }
}

/// The EPSG code of a CRS: its own identifier, or the one PROJ identifies with full confidence.
int epsg_code_of(PJ_CONTEXT* context, PJ* crs) {
  const char* authority = proj_get_id_auth_name(crs, 0);
  const char* code = proj_get_id_code(crs, 0);
  if (authority != nullptr && code != nullptr && std::string_view(authority) == "EPSG") return std::atoi(code);
  int* confidence = nullptr;
  PJ_OBJ_LIST* candidates = proj_identify(context, crs, "EPSG", nullptr, &confidence);
  int found = 0;
  if (candidates != nullptr) {
    for (int i = 0; i < proj_list_get_count(candidates) && found == 0; ++i) {
      if (confidence[i] < 100) continue;
      Object candidate(proj_list_get(context, candidates, i));
      const char* candidate_code = candidate.pj != nullptr ? proj_get_id_code(candidate.pj, 0) : nullptr;
      if (candidate_code != nullptr) found = std::atoi(candidate_code);
    }
    proj_list_destroy(candidates);
    proj_int_list_destroy(confidence);
  }
  return found;
}

Crs describe(PJ_CONTEXT* context, PJ* object, std::string_view text, std::string_view what) {
  if (!proj_is_crs(object))
    fail("{} '{}' is not a coordinate reference system ({}): {}", what, short_text(text), type_name(proj_get_type(object)), allowed);
  const Object horizontal = horizontal_part(context, object);
  const PJ_TYPE type = horizontal.pj != nullptr ? proj_get_type(horizontal.pj) : PJ_TYPE_UNKNOWN;
  Crs crs;
  switch (type) {
    case PJ_TYPE_GEOGRAPHIC_2D_CRS:
    case PJ_TYPE_GEOGRAPHIC_3D_CRS:
      crs.geographic = true;
      break;
    case PJ_TYPE_PROJECTED_CRS:
    case PJ_TYPE_ENGINEERING_CRS:
      break;
    default:
      fail("{} '{}' is a {}, not a horizontal coordinate reference system: {}", what, short_text(text), type_name(proj_get_type(object)),
           allowed);
  }
  const Object system(proj_crs_get_coordinate_system(context, horizontal.pj));
  double to_base = 1.0;
  const char* unit_name = nullptr;
  if (system.pj != nullptr &&
      proj_cs_get_axis_info(context, system.pj, 0, nullptr, nullptr, nullptr, &to_base, &unit_name, nullptr, nullptr) == 1) {
    crs.unit = unit_name != nullptr ? unit_name : "";
    crs.metric = !crs.geographic && std::abs(to_base - 1.0) < 1e-12;
  }
  // Only the horizontal part is carried (a compound CRS's vertical part is dropped: heights are
  // metres, which the GeoTIFF's VerticalUnits key says).
  PJ* carried = horizontal.pj;
  crs.epsg = epsg_code_of(context, carried);
  const char* authority = proj_get_id_auth_name(carried, 0);
  const char* code = proj_get_id_code(carried, 0);
  if (authority != nullptr && code != nullptr) crs.id = fmt::format("{}:{}", authority, code);
  if (crs.epsg != 0) crs.id = fmt::format("EPSG:{}", crs.epsg);
  if (const char* name = proj_get_name(carried)) crs.name = name;
  if (const char* wkt = proj_as_wkt(context, carried, PJ_WKT2_2019, nullptr)) crs.wkt = wkt;
  return crs;
}

/// "EPSG:2193" → 2193; nullopt for other text.
std::optional<long long> epsg_prefix_code(std::string_view text) {
  std::string lower(text);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (!lower.starts_with("epsg:") || lower.find('+') != std::string::npos) return std::nullopt;  // "EPSG:2193+7839": PROJ's
  const std::string_view digits = std::string_view(text).substr(5);
  long long code = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), code);
  if (error != std::errc() || end != digits.data() + digits.size()) return -1;
  return code;
}

}  // namespace

std::string Crs::label() const {
  return epsg != 0 ? fmt::format("EPSG:{}", epsg) : !id.empty() ? id : name;
}

std::string Crs::described() const {
  return label() == name || name.empty() ? label() : fmt::format("{} ({})", label(), name);
}

Crs parse_crs(std::string_view text, std::string_view what) {
  const std::string trimmed(text.substr(0, std::min(text.size(), std::size_t(1) << 20)));
  if (trimmed.find_first_not_of(" \t\r\n") == std::string::npos) fail("{} is empty: {}", what, allowed);
  if (const auto code = epsg_prefix_code(trimmed); code && (*code <= 0 || *code > 2147483647))
    fail("{} '{}' is not an EPSG code: {}", what, short_text(trimmed), allowed);
  if (trimmed.starts_with("+") || trimmed.find("+proj=") != std::string::npos)
    fail("{} '{}' is a PROJ string, which does not name a datum reliably: {}", what, short_text(trimmed), allowed);
  ProjContext context;
  proj_log_level(context.get(), PJ_LOG_NONE);
  const Object object(proj_create(context.get(), trimmed.c_str()));
  if (object.pj == nullptr) {
    const int error = proj_context_errno(context.get());
    const char* reason = error != 0 ? proj_context_errno_string(context.get(), error) : "unknown";
    fail("{} '{}' is not a coordinate reference system PROJ knows ({}): {}", what, short_text(trimmed), reason, allowed);
  }
  return describe(context.get(), object.pj, trimmed, what);
}

std::optional<std::array<double, 2>> lonlat_of(const Crs& crs, double east_m, double north_m) {
  ProjContext context;
  proj_log_level(context.get(), PJ_LOG_NONE);
  const Object source(proj_create(context.get(), crs.wkt.c_str()));
  const Object target(proj_create(context.get(), "OGC:CRS84"));
  if (source.pj == nullptr || target.pj == nullptr) return std::nullopt;
  const Object operation(proj_create_crs_to_crs_from_pj(context.get(), source.pj, target.pj, nullptr, nullptr));
  if (operation.pj == nullptr) return std::nullopt;
  const Object normalised(proj_normalize_for_visualization(context.get(), operation.pj));
  if (normalised.pj == nullptr) return std::nullopt;
  const PJ_COORD out = proj_trans(normalised.pj, PJ_FWD, proj_coord(east_m, north_m, 0.0, 0.0));
  if (!std::isfinite(out.xy.x) || !std::isfinite(out.xy.y) || std::abs(out.xy.x) > 360.0 || std::abs(out.xy.y) > 90.0) return std::nullopt;
  return std::array<double, 2>{out.xy.x, out.xy.y};
}

std::string area_of_use_problem(const Crs& crs, double east_m, double north_m) {
  ProjContext context;
  proj_log_level(context.get(), PJ_LOG_NONE);
  const Object object(proj_create(context.get(), crs.wkt.c_str()));
  double west = 0, south = 0, east = 0, north = 0;
  const char* area_name = nullptr;
  if (object.pj == nullptr || !proj_get_area_of_use(context.get(), object.pj, &west, &south, &east, &north, &area_name) || west <= -1000.0)
    return "";
  const std::string area = fmt::format("{} ({:g}..{:g} E, {:g}..{:g} N{})", crs.label(), west, east, south, north,
                                       area_name != nullptr ? fmt::format(": {}", area_name) : "");
  const auto lonlat = lonlat_of(crs, east_m, north_m);
  const std::string point = fmt::format("{}, {}", params::format_number(east_m), params::format_number(north_m));
  if (!lonlat) return fmt::format("{} is not a point PROJ can place in {}", point, area);
  constexpr double margin_deg = 0.5;
  const double lon = (*lonlat)[0], lat = (*lonlat)[1];
  const bool wraps = west > east;  // an area across the antimeridian
  const bool lon_inside =
      wraps ? lon >= west - margin_deg || lon <= east + margin_deg : lon >= west - margin_deg && lon <= east + margin_deg;
  if (lon_inside && lat >= south - margin_deg && lat <= north + margin_deg) return "";
  return fmt::format("{} (longitude {:.3f}, latitude {:.3f}) lies outside the area where {} is valid", point, lon, lat, area);
}

std::string output_crs_problem(std::string_view text) {
  try {
    const Crs crs = parse_crs(text, "crs");
    if (crs.geographic) return fmt::format("{} is geographic, in degrees", crs.described());
    if (!crs.metric) return fmt::format("{} is in {}, not metres", crs.described(), crs.unit);
    return "";
  } catch (const InputError& error) {
    // parse_crs's message "... PROJ knows (REASON): ..." → "PROJ: REASON"; others as they are
    const std::string message = error.what();
    const std::string marker = "PROJ knows (";
    const std::size_t open = message.find(marker);
    const std::size_t close = open != std::string::npos ? message.find("): ", open) : std::string::npos;
    if (close != std::string::npos) return "PROJ: " + message.substr(open + marker.size(), close - open - marker.size());
    const std::size_t colon = message.find("': ");
    if (colon != std::string::npos) return message.substr(colon + 3, message.find(": give") - colon - 3);
    return "not a CRS PROJ knows";
  }
}

Crs crs_from_epsg(int code, std::string_view what) {
  return parse_crs(fmt::format("EPSG:{}", code), what);
}

nlohmann::json crs_to_sidecar(const Crs& crs) {
  return {{"epsg", crs.epsg != 0 ? nlohmann::json(crs.epsg) : nlohmann::json(nullptr)}, {"name", crs.name}, {"wkt", crs.wkt}};
}

Crs crs_from_sidecar(const nlohmann::json& value, std::string_view what) {
  if (!value.is_object()) fail("{} is {}, not an object with epsg and wkt", what, value.dump());
  const auto epsg = value.find("epsg");
  if (epsg != value.end() && !epsg->is_null()) {
    if (!epsg->is_number_integer()) fail("{}: epsg is {}, not a whole number", what, epsg->dump());
    return crs_from_epsg(epsg->get<int>(), what);
  }
  const auto wkt = value.find("wkt");
  if (wkt == value.end() || !wkt->is_string()) fail("{}: it has neither an epsg code nor a wkt string", what);
  return parse_crs(wkt->get<std::string>(), what);
}

std::string crs_wkt1(const Crs& crs) {
  PJ_CONTEXT* context = proj_context_create();
  proj_log_level(context, PJ_LOG_NONE);
  std::string text;
  if (PJ* object = proj_create(context, crs.wkt.c_str())) {
    const char* options[] = {"MULTILINE=NO", nullptr};
    if (const char* wkt = proj_as_wkt(context, object, PJ_WKT1_GDAL, options)) text = wkt;
    proj_destroy(object);
  }
  proj_context_destroy(context);
  return text;
}

namespace {
// The datum is unnamed: a GeoTIFF can carry only the CRS's name, and GDAL reads it back with an
// unnamed datum, so every file of one world names the same CRS. Version 4's GeoJSON named it.
constexpr const char* local_wkt =
    "ENGCRS[\"Sansui local metres\",EDATUM[\"\"],CS[Cartesian,2],AXIS[\"easting (X)\",east,ORDER[1],"
    "LENGTHUNIT[\"metre\",1]],AXIS[\"northing (Y)\",north,ORDER[2],LENGTHUNIT[\"metre\",1]]]";
constexpr const char* version_4_local_wkt =
    "ENGCRS[\"Sansui local metres\",EDATUM[\"Sansui world\"],CS[Cartesian,2],AXIS[\"easting (X)\",east,ORDER[1],"
    "LENGTHUNIT[\"metre\",1]],AXIS[\"northing (Y)\",north,ORDER[2],LENGTHUNIT[\"metre\",1]]]";
}  // namespace

const Crs& local_metres_crs() {
  static const Crs crs = parse_crs(local_wkt, "the local metres CRS");
  return crs;
}

const Crs& version_4_local_metres_crs() {
  static const Crs crs = parse_crs(version_4_local_wkt, "version 4's local metres CRS");
  return crs;
}

bool is_local_metres(const Crs& crs) {
  return crs.epsg == 0 && crs.name == "Sansui local metres";
}

nlohmann::json crs_to_geojson_member(const Crs& crs) {
  if (crs.epsg == 0) {
    if (crs.wkt.empty()) return nullptr;
    // The one-line WKT1 OGR reads back (PROJ's multi-line WKT2 would do, but is long).
    std::string name = crs.wkt;
    if (is_local_metres(crs)) name = crs.wkt == version_4_local_metres_crs().wkt ? version_4_local_wkt : local_wkt;
    return {{"type", "name"}, {"properties", {{"name", std::move(name)}}}};
  }
  return {{"type", "name"}, {"properties", {{"name", fmt::format("urn:ogc:def:crs:EPSG::{}", crs.epsg)}}}};
}

std::string with_geojson_crs(std::string geojson, const Crs& crs) {
  const nlohmann::json member = crs_to_geojson_member(crs);
  const std::size_t brace = geojson.find('{');
  if (member.is_null() || brace == std::string::npos) return geojson;
  const bool empty_object = geojson.find_first_not_of(" \t\r\n", brace + 1) == geojson.find('}', brace + 1);
  geojson.insert(brace + 1, "\"crs\":" + dump_json(member) + (empty_object ? "" : ","));
  return geojson;
}

}  // namespace sansui::io
