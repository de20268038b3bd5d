// The per-format heightmap writers and readers behind write_heightmap/read_heightmap, and the
// 16-bit quantiser they share. Internal to io/: heightmap_io.cpp validates the inputs (finite
// samples, range, cell size) and resolves the metadata (sidecar, options) before calling these.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <span>
#include <string>

#include <nlohmann/json.hpp>

#include "core/grid.hpp"
#include "io/heightmap_io.hpp"

namespace sansui::io::detail {

/// Maps metres to 16-bit levels and back: level q stands for min_m + q * step_m.
class Quantizer {
 public:
  explicit Quantizer(const HeightRange& range)
      : min_m_(range.min_m), step_m_((range.max_m - range.min_m) / 65535.0), inverse_step_(1.0 / step_m_) {}

  /// The nearest level, clamped to 0..65535. Branch-free, so that loops over a row vectorise.
  std::uint16_t encode(float height_m) const {
    const double level = (static_cast<double>(height_m) - min_m_) * inverse_step_;
    const double clamped = std::min(level > 0.0 ? level : 0.0, 65535.0);  // NaN (excluded anyway) gives 0
    return static_cast<std::uint16_t>(static_cast<std::int32_t>(clamped + 0.5));
  }
  float decode(std::uint32_t level) const { return static_cast<float>(min_m_ + level * step_m_); }
  /// For files with fewer bits (8-bit PNG): level of `max_level` stands for max_m.
  float decode(std::uint32_t level, std::uint32_t max_level) const {
    return static_cast<float>(min_m_ + level * (step_m_ * 65535.0 / max_level));
  }

 private:
  double min_m_, step_m_, inverse_step_;
};

/// Where samples live in a headerless file, and what a reader was told about the grid.
struct RawLayout {
  int width = 0;
  int height = 0;
  bool south_row_first = false;  ///< Unity's row order
};

/// What a GeoTIFF says about its grid: cell size and origin in metres, if it says anything, and
/// its coordinate system.
struct GeoReference {
  std::optional<double> cell_size_m;
  std::optional<double> origin_x_m, origin_y_m;
  /// Cells of cell_size_m across and this tall (north-south), when they are not square: the
  /// caller resamples. [Units: m]
  std::optional<double> cell_height_m;
  int epsg = 0;          ///< ProjectedCSTypeGeoKey (or GeographicTypeGeoKey): 0 if none or user-defined
  std::string esri_wkt;  ///< a user-defined CRS's WKT in the citation ("ESRI PE String = ", as GDAL writes it)
  bool geographic = false;
  /// What the reader did on its own (NoData filled, degrees converted), for the user.
  std::vector<std::string> notes;
};

// Writers: `temporary` is the file to create, `target` the name for messages.
/// What a heights reader is told.
struct HeightsRead {
  HeightRange range;                              ///< what 16-bit levels stand for
  RawLayout layout;                               ///< headerless files: size and row order
  std::optional<double> cell_size_for_degrees_m;  ///< GeoTIFFs in degrees
  GeoReference* georeference = nullptr;           ///< filled by formats that carry one
};

/// What a heights writer is told.
struct HeightsWrite {
  HeightRange range;  ///< 16-bit formats
  Compression compression = Compression::fast;
  bool south_row_first = false;
  const std::optional<Crs>* crs = nullptr;
};

/// A heights format's driver (registered in io/file_formats.cpp).
struct HeightsDriver {
  bool sixteen_bit = false;    ///< levels of a metres range, not metres
  bool unity_rows = false;     ///< may store the south row first (raw_flip_y, Unity's importer)
  bool georeferenced = false;  ///< carries its own cell size, origin and CRS (GeoKeys)
  Heightfield (*read)(const std::filesystem::path& path, const HeightsRead& request);
  void (*write)(const std::filesystem::path& temporary, const std::filesystem::path& target, const Heightfield& heights,
                const HeightsWrite& request);
  /// The sidecar's "format": name, description, sample type, byte and row order.
  nlohmann::json (*describe)(bool south_row_first, Compression compression);
};
extern const HeightsDriver png16_driver, raw16_driver, r16_driver, r32_driver, geotiff_driver, gdal_driver;

/// A DEM in any raster format GDAL reads (io/gdal_raster.cpp): read only.
Heightfield read_gdal_raster(const std::filesystem::path& path, GeoReference& georeference, std::optional<double> cell_size_for_degrees_m);
/// Its CRS as WKT; "" when it has none or is geographic.
std::string read_gdal_raster_crs(const std::filesystem::path& path);

void write_png16(const std::filesystem::path& temporary, const std::filesystem::path& target, const Heightfield& heights,
                 const HeightRange& range, Compression compression);
void write_raw16(const std::filesystem::path& temporary, const std::filesystem::path& target, const Heightfield& heights,
                 const HeightRange& range, bool south_row_first);
void write_r32(const std::filesystem::path& temporary, const std::filesystem::path& target, const Heightfield& heights);
void write_geotiff(const std::filesystem::path& temporary, const std::filesystem::path& target, const Heightfield& heights,
                   Compression compression, const std::optional<Crs>& crs);

// Readers: they return samples in metres; cell size and origin are left for the caller except
// what the GeoTIFF reader reports in `georeference`.
Heightfield read_png16(const std::filesystem::path& path, const HeightRange& range);
Heightfield read_raw16(const std::filesystem::path& path, const RawLayout& layout, const HeightRange& range);
Heightfield read_r32(const std::filesystem::path& path, const RawLayout& layout);
Heightfield read_geotiff(const std::filesystem::path& path, GeoReference& georeference, std::optional<double> cell_size_for_degrees_m);
/// Only the georeferencing and GeoKeys of a GeoTIFF, without its samples.
GeoReference read_geotiff_georeference(const std::filesystem::path& path);

/// The width and height of a headerless file of `file_bytes` bytes with `sample_bytes` per sample:
/// the layout's if given, else the square that fills the file. Throws InputError naming the file.
RawLayout resolve_raw_layout(const std::filesystem::path& path, std::uintmax_t file_bytes, int sample_bytes, RawLayout layout);

/// The minimum and maximum of some samples, and whether all are finite.
struct SampleScan {
  float min = std::numeric_limits<float>::infinity();
  float max = -std::numeric_limits<float>::infinity();
  bool finite = true;
};

/// Scans samples into `scan`. Written so the compiler vectorises it (independent lanes instead of
/// one running minimum with NaN semantics): 5x faster than std::minmax on an 8193^2 grid.
SampleScan& scan_samples(std::span<const float> samples, SampleScan& scan);

/// Throws InputError "cannot read PATH: sample (x, y) is nan: ..." for the first non-finite sample.
void require_finite(const std::filesystem::path& path, const Heightfield& heights);

/// Caps what a file header may ask us to allocate, so a corrupt header fails cleanly.
void require_plausible_size(const std::filesystem::path& path, std::uint64_t width, std::uint64_t height);

/// Little-endian byte order helpers for the headerless formats.
inline void store_u16_le(unsigned char* out, std::uint16_t value) {
  out[0] = static_cast<unsigned char>(value & 0xFFu);
  out[1] = static_cast<unsigned char>(value >> 8);
}
inline std::uint16_t load_u16_le(const unsigned char* in) {
  return static_cast<std::uint16_t>(in[0] | (in[1] << 8));
}

}  // namespace sansui::io::detail
