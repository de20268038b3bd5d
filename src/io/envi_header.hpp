// The ENVI header (.hdr) that lets GDAL, QGIS and ENVI open a raw heightmap (.r32, .r16, .raw):
// its size, sample type, byte order, where it lies (map info: the upper-left corner and the cell
// size) and its CRS (coordinate system string, WKT), and for 16-bit files the metres the levels
// stand for (data gain and offset values). GDAL's ENVI driver finds `NAME.r32.hdr` beside `NAME.r32`.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "core/grid.hpp"
#include "io/crs.hpp"

namespace sansui::io {

/// How the raw samples are stored.
struct EnviLayout {
  bool sixteen_bit = false;  ///< unsigned 16-bit levels (else float32 metres), little-endian
  double gain_m = 1.0;       ///< metres per level (16-bit)
  double offset_m = 0.0;     ///< metres of level 0 (16-bit)
};

/// The header's text for `heights` (its size, cell size and origin) stored as `layout`.
std::string envi_header_text(const Heightfield& heights, const EnviLayout& layout, const std::optional<Crs>& crs);

/// `path` + ".hdr": where GDAL looks for the header of `path`.
std::filesystem::path envi_header_path(const std::filesystem::path& path);

}  // namespace sansui::io
