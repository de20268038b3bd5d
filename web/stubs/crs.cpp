// The browser build's io/crs.cpp: no PROJ (cmake/SansuiWeb.cmake). A browser world has no
// coordinate reference system: world.crs and --crs are refused in one line, and GeoJSON inputs
// with a crs member too. Plain metres (the local CRS) is all there is.
#include "io/crs.hpp"

#include <fmt/format.h>

#include "web_stub.hpp"

namespace sansui::io {

std::string Crs::label() const {
  return epsg != 0 ? fmt::format("EPSG:{}", epsg) : !id.empty() ? id : name;
}

std::string Crs::described() const {
  return label();
}

Crs parse_crs(std::string_view text, std::string_view what) {
  web::not_in_browser(fmt::format("{} '{}'", what, text.substr(0, 80)), "PROJ");
}

std::string output_crs_problem(std::string_view) {
  return "the browser build has no PROJ: a world there has no CRS";
}

std::optional<std::array<double, 2>> lonlat_of(const Crs&, double, double) {
  return std::nullopt;
}

std::string area_of_use_problem(const Crs&, double, double) {
  return "";
}

Crs crs_from_epsg(int code, std::string_view what) {
  web::not_in_browser(fmt::format("{} EPSG:{}", what, code), "PROJ");
}

nlohmann::json crs_to_sidecar(const Crs& crs) {
  return {{"epsg", crs.epsg != 0 ? nlohmann::json(crs.epsg) : nlohmann::json(nullptr)}, {"name", crs.name}, {"wkt", crs.wkt}};
}

std::string crs_wkt1(const Crs& crs) {
  // A browser world has no CRS but local metres, written as PROJ writes it for the CLI.
  if (is_local_metres(crs)) return R"(LOCAL_CS["Sansui local metres",UNIT["metre",1],AXIS["Easting",EAST],AXIS["Northing",NORTH]])";
  return "";
}

Crs crs_from_sidecar(const nlohmann::json&, std::string_view what) {
  web::not_in_browser(std::string(what), "PROJ");
}

const Crs& local_metres_crs() {
  static const Crs crs{0, "Sansui local metres", "", false, true, "metre", ""};
  return crs;
}

const Crs& version_4_local_metres_crs() {
  return local_metres_crs();  // the same name; the browser writes no WKT
}

bool is_local_metres(const Crs& crs) {
  return crs.epsg == 0 && crs.name == "Sansui local metres";
}

nlohmann::json crs_to_geojson_member(const Crs&) {
  web::not_in_browser("a GeoJSON crs member", "PROJ");
}

std::string with_geojson_crs(std::string, const Crs&) {
  web::not_in_browser("a GeoJSON output with a crs member", "PROJ");
}

}  // namespace sansui::io
