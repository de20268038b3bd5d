// A VRT mosaic through GDAL's C API (see vrt_mosaic.hpp).
#include "io/vrt_mosaic.hpp"

#include <string>
#include <system_error>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/gdal_api.hpp"
#include "io/gdal_local.hpp"
#include "io/sidecar.hpp"

namespace sansui::io {

void write_vrt_mosaic(const std::filesystem::path& path, const std::vector<std::filesystem::path>& tiles,
                      const std::optional<nlohmann::json>& provenance, std::string_view kind) {
  const detail::LocalGdal local;
  std::vector<std::string> names;
  names.reserve(tiles.size());
  for (const auto& tile : tiles) names.push_back(tile.string());
  std::vector<const char*> sources;
  sources.reserve(names.size());
  for (const auto& name : names) sources.push_back(name.c_str());
  // Through a temporary of write_atomically's (made anew, never a planted link), renamed when whole.
  std::optional<nlohmann::json> sidecar;
  if (provenance) {
    sidecar = detail::sidecar_head(kind, path);
    (*sidecar)["tiles"] = tiles.size();
    (*sidecar)["provenance"] = *provenance;
  }
  detail::write_with_sidecar(path, sidecar, [&](const std::filesystem::path& temporary) {
    detail::gdal_api().CPLPushErrorHandler(detail::gdal_api().CPLQuietErrorHandler);
    detail::gdal_api().CPLErrorReset();
    int usage_error = 0;
    GDALDatasetH vrt = detail::gdal_api().GDALBuildVRT(temporary.c_str(), static_cast<int>(sources.size()), nullptr, sources.data(),
                                                       nullptr, &usage_error);
    const std::string reason = detail::gdal_api().CPLGetLastErrorMsg();
    detail::gdal_api().CPLPopErrorHandler();
    if (vrt == nullptr || usage_error != 0)
      fail("cannot write {}: GDAL's VRT builder says: {}", path.string(), reason.empty() ? "no reason given" : reason);
    detail::gdal_api().GDALClose(vrt);
  });
}

}  // namespace sansui::io
