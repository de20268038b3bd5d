// A VRT mosaic through GDAL's C API (see vrt_mosaic.hpp).
#include "io/vrt_mosaic.hpp"

#include <string>
#include <system_error>

#include <cpl_conv.h>
#include <cpl_error.h>
#include <gdal.h>
#include <gdal_utils.h>

#include "core/error.hpp"

namespace sansui::io {

void write_vrt_mosaic(const std::filesystem::path& path, const std::vector<std::filesystem::path>& tiles) {
  GDALAllRegister();
  const std::filesystem::path temporary = path.parent_path() / (path.filename().string() + ".partial");
  std::vector<std::string> names;
  names.reserve(tiles.size());
  for (const auto& tile : tiles) names.push_back(tile.string());
  std::vector<const char*> sources;
  sources.reserve(names.size());
  for (const auto& name : names) sources.push_back(name.c_str());
  CPLPushErrorHandler(CPLQuietErrorHandler);
  CPLErrorReset();
  int usage_error = 0;
  GDALDatasetH vrt = GDALBuildVRT(temporary.c_str(), static_cast<int>(sources.size()), nullptr, sources.data(), nullptr, &usage_error);
  const std::string reason = CPLGetLastErrorMsg();
  CPLPopErrorHandler();
  if (vrt == nullptr || usage_error != 0) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    fail("cannot write {}: GDAL's VRT builder says: {}", path.string(), reason.empty() ? "no reason given" : reason);
  }
  GDALClose(vrt);
  std::filesystem::rename(temporary, path);
}

}  // namespace sansui::io
