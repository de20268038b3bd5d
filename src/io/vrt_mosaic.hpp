// A GDAL VRT mosaic over raster tiles: one virtual raster that GIS tools read as the whole grid.
#pragma once

#include <filesystem>
#include <vector>

namespace sansui::io {

/// Writes `path` (.vrt) over `tiles` (GeoTIFFs beside it, non-overlapping, georeferenced alike)
/// with GDAL's gdalbuildvrt, atomically (a temporary file renamed into place). The tiles are
/// named relative to the VRT, so the folder can move. Throws InputError on GDAL's refusal.
void write_vrt_mosaic(const std::filesystem::path& path, const std::vector<std::filesystem::path>& tiles);

}  // namespace sansui::io
