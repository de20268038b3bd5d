// Heightmap files: 16-bit grey PNG, 16-bit RAW (Unity/Unreal), float32 .r32, float32 GeoTIFF,
// with a JSON sidecar NAME.EXT.json beside each (size, cell size, origin, sample layout, metres
// range, provenance). The sidecar keeps the extension (a.png.json, a.r32.json) so that one run
// writing a.png, a.r32 and a.glb gets one sidecar per file instead of three overwriting a.json.
// Writers never leave a half-written file: they write NAME.tmp-XXXX and rename.
// Errors (unwritable directory, unreadable or corrupt file, NaN) throw sansui::InputError with
// a one-line message naming the file. docs/formats.md describes every layout.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/grid.hpp"
#include "io/crs.hpp"
#include "io/file_formats.hpp"

namespace sansui::io {

/// The metres that 16-bit values 0 and 65535 stand for: metres = min_m + q * (max_m - min_m) / 65535.
struct HeightRange {
  double min_m = 0.0;  ///< [Units: m] [Range: finite, < max_m]
  double max_m = 1.0;  ///< [Units: m] [Range: finite, > min_m]
};

/// The range a 16-bit file is read with when neither the options nor a sidecar give one: one
/// metre per 65.535 levels, a common convention for heightmaps of unknown scale. [Units: m]
inline constexpr HeightRange default_16bit_read_range{0.0, 1000.0};

/// The cell size a file is read with when neither the file, a sidecar nor the options give one.
inline constexpr double default_read_cell_size_m = 1.0;

/// How the compressed formats (.png, .tif) trade writing time for size; the other formats are
/// never compressed. On a real 8193^2 terrain (2-core machine): `fast` writes the PNG in 2.6 s
/// (85 MB) and the GeoTIFF in 3.0 s (159 MB); `small` gives a PNG 1 % smaller in about the same
/// time and a GeoTIFF 6 % smaller in 10x the time; `none` writes the PNG in 0.85 s (134 MB) and
/// the GeoTIFF at disk speed (0.15 s, 269 MB).
enum class Compression {
  none,  ///< stored: PNG zlib level 0, TIFF uncompressed
  fast,  ///< PNG Up filter + zlib run-length level 1; TIFF Deflate level 1 + floating-point predictor
  small  ///< PNG Paeth filter + zlib run-length; TIFF Deflate level 9 + floating-point predictor
};

/// The heights format (io/file_formats.hpp) for a file name's extension (.png .raw .r16 .r32 .tif
/// .tiff), or null. raw16 (.raw) and r16 (.r16) are the same bytes: 16-bit little-endian levels
/// with no header; .r16 (Unreal's and Terrain3D's name) always stores the north row first.
const FileFormat* heightmap_format_for(const std::filesystem::path& path);

struct HeightmapWriteOptions {
  /// Metres range for 16-bit formats (values outside are clamped). nullopt: the data's range.
  std::optional<HeightRange> range;
  /// Written into the sidecar under "provenance": parameters, seed, version, command line.
  nlohmann::json provenance = nlohmann::json::object();
  /// Write NAME.EXT.json beside the file. [Default: true]
  bool sidecar = true;
  /// .raw only: store the south row first, as Unity's terrain importer expects (it reads rows
  /// bottom-up). The sidecar records the row order, so read_heightmap undoes it. [Default: false]
  bool raw_flip_y = false;
  /// .png and .tif: time against size. [Default: fast]
  Compression compression = Compression::fast;
  /// Written into the sidecar under "engine" when not null: what a game engine's importer needs
  /// (scales, location), filled by the caller.
  nlohmann::json engine = nullptr;
  /// The coordinate system of the grid's coordinates: GeoTIFF GeoKeys and the sidecar's "crs".
  /// nullopt: a local plane in metres (GeoTIFFs say "user-defined projection in metres").
  /// A CRS that is not in metres is refused (the grid is metres).
  std::optional<Crs> crs;
};

/// Writes `heights` (metres; cell size and origin from the grid) in the format of the extension.
void write_heightmap(const std::filesystem::path& path, const Heightfield& heights, const HeightmapWriteOptions& options = {});

struct HeightmapReadOptions {
  /// For 16-bit files: overrides the sidecar's range. Without both: default_16bit_read_range.
  std::optional<HeightRange> range;
  /// Cell size when neither the file nor a sidecar gives one (and for GeoTIFFs in degrees).
  /// [Units: m] [Range: > 0] [Default: default_read_cell_size_m]
  std::optional<double> cell_size_m;
  /// For .raw/.r32 without a sidecar: width and height (default: square from the file size).
  /// With a sidecar they must agree with it. [Range: > 0]
  std::optional<int> width, height;
  /// For .raw without a sidecar: the file stores the south row first (Unity). [Default: false]
  bool raw_flip_y = false;
};

/// What read_heightmap took from its defaults because neither the file, a sidecar nor the
/// options said: the caller tells the user (the library never prints).
struct HeightmapAssumptions {
  bool range = false;      ///< a 16-bit (or 8-bit) file read with default_16bit_read_range
  bool cell_size = false;  ///< read with default_read_cell_size_m
  bool any() const { return range || cell_size; }
  /// Other things the reader did that the user should hear of (a GeoTIFF with non-square cells
  /// resampled to square ones), one line each.
  std::vector<std::string> notes;
};

/// Reads a heightmap in metres; format from the extension, metadata from the sidecar if present.
/// Precedence: the file's own tags (GeoTIFF cell size and origin) > sidecar > options > defaults,
/// except `options.range`, which overrides a sidecar's range. 8-bit grey PNGs are read too
/// (q / 255 of the range); GeoTIFFs may hold uint8/int16/uint16/int32/uint32/float32/float64.
/// `assumed`, if given, says which defaults were used.
Heightfield read_heightmap(const std::filesystem::path& path, const HeightmapReadOptions& options = {},
                           HeightmapAssumptions* assumed = nullptr);

/// The coordinate system of a heightmap file: a GeoTIFF's GeoKeys (an EPSG code, or the WKT GDAL
/// writes into the citation of a user-defined one), else its sidecar's "crs". nullopt when
/// neither says one, and for a geographic GeoTIFF (read as metres only with a given cell size,
/// so its degrees do not carry over). A CRS whose unit is not the metre is not carried either
/// (the samples were converted to metres), nor one PROJ does not know: `note`, if given, then
/// says so. Throws InputError for an unreadable file or sidecar.
std::optional<Crs> read_heightmap_crs(const std::filesystem::path& path, std::string* note = nullptr);

/// One line for the user naming the defaults `assumed` a read of `path` used and how to set them
/// (`[file] range` / `--range`, `[file] cell` / `--cell`, or a sidecar). Empty if none.
std::string assumptions_note(const std::filesystem::path& path, const HeightmapAssumptions& assumed);

/// The sidecar path of a heightmap or mesh: the file name with ".json" appended (a.png.json).
std::filesystem::path sidecar_path(const std::filesystem::path& path);

/// Called by a program that owns its process (the CLI): when GDAL is first used, every driver but
/// the local DEM formats Sansui reads is removed from it, and its network options are set for
/// every thread. A library host (Python) keeps its own GDAL as it is: Sansui then sets its options
/// for its own reads only, and checks the driver of every file a DEM names.
void let_gdal_own_the_process();

}  // namespace sansui::io
