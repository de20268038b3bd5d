// Beside a 16-bit PNG heightmap, the two small files GIS tools read to place and scale it: the
// world file (NAME.pgw: cell size and the centre of the upper-left pixel) and GDAL's auxiliary
// file (NAME.png.aux.xml: the CRS, and the metres that levels 0 and 65535 stand for, as the
// band's offset and scale), so that QGIS and GDAL show metres on the map.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "core/grid.hpp"
#include "io/crs.hpp"

namespace sansui::io {

/// NAME.png -> NAME.pgw.
std::filesystem::path png_world_file_path(const std::filesystem::path& png);
/// NAME.png -> NAME.png.aux.xml.
std::filesystem::path png_aux_xml_path(const std::filesystem::path& png);

/// The world file's six lines for `heights` (its cell size and origin; north up).
std::string png_world_file_text(const Heightfield& heights);
/// The same for a picture whose pixel (0, 0) is the sample at `east_m`, `south_m` (Sansui's
/// origin convention: metres east, and south of the world's north edge), `cell_m` apart.
std::string png_world_file_text(double cell_m, double east_m, double south_m);

/// The .aux.xml: metres = offset_m + level x gain_m, and the CRS when there is one.
std::string png_aux_xml_text(double gain_m, double offset_m, const std::optional<Crs>& crs);

}  // namespace sansui::io
