// Heightmap files: 16-bit grey PNG, 16-bit RAW (Unity/Unreal), float32 .r32, float32 GeoTIFF,
// with a JSON sidecar NAME.json beside each (size, cell size, metres range, provenance).
// Writers never leave a half-written file: they write NAME.tmp-XXXX and rename.
// Errors (unwritable directory, unreadable or corrupt file, NaN) throw sansui::InputError with
// a one-line message naming the file.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/grid.hpp"

namespace sansui::io {

/// The metres that 16-bit values 0 and 65535 stand for.
struct HeightRange {
  double min_m = 0.0;
  double max_m = 1.0;
};

enum class HeightmapFormat { png16, raw16, r32, geotiff };

/// The format for a file name's extension (.png .raw .r32 .tif .tiff), or nullopt.
std::optional<HeightmapFormat> heightmap_format_for(const std::filesystem::path& path);

struct HeightmapWriteOptions {
  /// Metres range for 16-bit formats (values outside are clamped). nullopt: the data's range.
  std::optional<HeightRange> range;
  /// Written into the sidecar under "provenance": parameters, seed, version, command line.
  nlohmann::json provenance = nlohmann::json::object();
  /// Write NAME.json beside the file. [Default: true]
  bool sidecar = true;
};

/// Writes `heights` (metres; cell size and origin from the grid) in the format of the extension.
void write_heightmap(const std::filesystem::path& path, const Heightfield& heights,
                     const HeightmapWriteOptions& options = {});

struct HeightmapReadOptions {
  /// For 16-bit files: overrides the sidecar's range. Without both, [0, 65535] maps to [0, 1000] m... see docs.
  std::optional<HeightRange> range;
  /// Cell size when neither the file nor a sidecar gives one. [Units: m]
  std::optional<double> cell_size_m;
  /// For .raw/.r32 without a sidecar: width and height (default: square from the file size).
  std::optional<int> width, height;
};

/// Reads a heightmap in metres; format from the extension, metadata from the sidecar if present.
Heightfield read_heightmap(const std::filesystem::path& path, const HeightmapReadOptions& options = {});

/// The sidecar path of a heightmap or mesh: the same name with extension .json.
std::filesystem::path sidecar_path(const std::filesystem::path& path);

}  // namespace sansui::io
