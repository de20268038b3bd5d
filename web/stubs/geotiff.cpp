// The browser build's io/geotiff.cpp: no libtiff or libgeotiff (cmake/SansuiWeb.cmake).
#include "io/heightmap_formats.hpp"
#include "web_stub.hpp"

namespace sansui::io::detail {

void write_geotiff(const std::filesystem::path&, const std::filesystem::path& target, const Heightfield&, Compression,
                   const std::optional<Crs>&) {
  web::not_in_browser("writing the GeoTIFF " + target.filename().string(), "libtiff");
}

Heightfield read_geotiff(const std::filesystem::path& path, GeoReference&, std::optional<double>) {
  web::not_in_browser("reading the GeoTIFF " + path.filename().string(), "libtiff");
}

GeoReference read_geotiff_georeference(const std::filesystem::path& path) {
  web::not_in_browser("reading the GeoTIFF " + path.filename().string(), "libtiff");
}

}  // namespace sansui::io::detail
