// The browser build's io/gdal_raster.cpp: no GDAL (cmake/SansuiWeb.cmake).
#include "io/heightmap_formats.hpp"
#include "web_stub.hpp"

namespace sansui::io::detail {

Heightfield read_gdal_raster(const std::filesystem::path& path, GeoReference&, std::optional<double>) {
  web::not_in_browser("reading " + path.filename().string(), "GDAL");
}

std::string read_gdal_raster_crs(const std::filesystem::path&) {
  return "";
}

}  // namespace sansui::io::detail
