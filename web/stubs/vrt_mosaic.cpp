// The browser build's io/vrt_mosaic.cpp: no GDAL (cmake/SansuiWeb.cmake).
#include "io/vrt_mosaic.hpp"

#include "web_stub.hpp"

namespace sansui::io {

void write_vrt_mosaic(const std::filesystem::path& path, const std::vector<std::filesystem::path>&, const std::optional<nlohmann::json>&,
                      std::string_view) {
  web::not_in_browser("writing the tile mosaic " + path.filename().string(), "GDAL");
}

}  // namespace sansui::io
