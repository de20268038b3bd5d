// A GDAL VRT mosaic over raster tiles: one virtual raster that GIS tools read as the whole grid.
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace sansui::io {

/// Writes `path` (.vrt) over `tiles` (GeoTIFFs beside it, non-overlapping, georeferenced alike)
/// with GDAL's gdalbuildvrt, atomically (a temporary file renamed into place). The tiles are
/// named relative to the VRT, so the folder can move. With `provenance`, a sidecar beside it
/// (kind `kind`), as every output has. Throws InputError on GDAL's refusal.
void write_vrt_mosaic(const std::filesystem::path& path, const std::vector<std::filesystem::path>& tiles,
                      const std::optional<nlohmann::json>& provenance = std::nullopt, std::string_view kind = "heightmap");

}  // namespace sansui::io
