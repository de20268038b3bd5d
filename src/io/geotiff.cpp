// Float32 GeoTIFF heightmaps (libtiff + libgeotiff), and a reader for the single-band DEMs GIS
// tools write (uint8/int16/uint16/int32/uint32/float32/float64, stripped or tiled, any libtiff
// compression).
//
// Georeferencing written: ModelPixelScale (cell, cell, 0) and one ModelTiepoint mapping the
// corner of pixel (0, 0) to (origin_x - cell/2, -origin_y + cell/2), with RasterPixelIsArea:
// each sample is the centre of its pixel, the reading every GIS tool agrees on (PixelIsPoint is
// handled differently by different readers). Model Y points north, Sansui's y south, hence the
// sign. With a CRS (io/crs.hpp: the input's, or --crs), GTModelType = Projected and
// ProjectedCSType = its EPSG code, or, for a CRS without one, user-defined with its WKT in
// PCSCitation as "ESRI PE String = WKT" (where GDAL writes and reads it). Without one (a generated
// terrain), the GeoKeys say exactly what is known: ProjectedCSType = user-defined and
// ProjLinearUnits = metre, i.e. "planar coordinates in metres in some local projection". GDAL
// reads that as a local/engineering CRS in metres with the right geotransform, and a user can
// assign a real CRS later (gdal_edit.py -a_srs) without touching the samples. The reader reports
// the EPSG code or WKT, and rectangular cells (resampled by the caller); rotated georeferencing is
// refused. Samples are compressed with Deflate (level 1, or 9
// for the smallest files) and the floating-point predictor (GDAL's PREDICTOR=3), which QGIS, GDAL
// and ArcGIS all read, or not at all. Strips
// are written one at a time, so the grid is never copied whole.
#include <cerrno>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include <geotiff.h>
#include <tiffio.h>
#include <unistd.h>

#include <fcntl.h>
#include <geovalues.h>
#include <xtiffio.h>

#include "core/error.hpp"
#include "io/binary_file.hpp"
#include "io/heightmap_formats.hpp"
#include "io/no_data_fill.hpp"

namespace sansui::io::detail {
namespace {

/// The first libtiff error of one file, kept so the InputError can say what went wrong.
struct TiffMessages {
  char error[512] = "";
  int os_error = 0;  ///< errno when the first error was reported (a failed write's ENOSPC, EIO...)
};

int on_tiff_error(TIFF*, void* user_data, const char* module, const char* format, va_list arguments) {
  auto* messages = static_cast<TiffMessages*>(user_data);
  if (messages->error[0] == '\0') {
    messages->os_error = errno;
    char text[400];
    std::vsnprintf(text, sizeof text, format, arguments);
    std::snprintf(messages->error, sizeof messages->error, "%s: %s", module != nullptr ? module : "libtiff", text);
  }
  return 1;  // handled: libtiff's global handler (which prints to stderr) is not called
}

int on_tiff_warning(TIFF*, void*, const char*, const char*, va_list) {
  return 1;
}  // never print

void on_geotiff_error(GTIF*, int, const char*, ...) {}  // failures show in the return values

/// GDAL's no-data tag, as GDAL itself defines it: libtiff knows its number but not its layout.
const TIFFFieldInfo gdal_no_data_field = {TIFFTAG_GDAL_NODATA, -1, -1, TIFF_ASCII,
                                          FIELD_CUSTOM,        1,  0,  const_cast<char*>("GDALNoDataValue")};
TIFFExtendProc previous_tag_extender = nullptr;

void extend_tags(TIFF* tiff) {
  if (TIFFFindField(tiff, TIFFTAG_GDAL_NODATA, TIFF_ANY) == nullptr) TIFFMergeFieldInfo(tiff, &gdal_no_data_field, 1);
  if (previous_tag_extender != nullptr) previous_tag_extender(tiff);
}

/// Teaches libtiff the GeoTIFF tags (libgeotiff's extender) and GDAL's no-data tag, once per
/// process. libtiff keeps tag extenders globally; this chains to any installed before.
void register_tags() {
  static std::once_flag registered;
  std::call_once(registered, [] {
    XTIFFInitialize();
    previous_tag_extender = TIFFSetTagExtender(extend_tags);
  });
}

/// An open TIFF with the GeoTIFF tags registered and messages captured per file.
class TiffFile {
 public:
  /// Opens `path`; libtiff's messages name `name` (the user's file, not a temporary one).
  TiffFile(const std::filesystem::path& path, const std::filesystem::path& name, const char* mode) {
    register_tags();
    const bool writing = mode[0] == 'w';
    // Reading: a regular file only, never a device (open_regular_file throws InputError).
    const int descriptor = writing ? ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666) : open_regular_file(path);
    if (descriptor < 0) {
      std::snprintf(messages_.error, sizeof messages_.error, "%s", std::strerror(errno));
      return;
    }
    TIFFOpenOptions* options = TIFFOpenOptionsAlloc();
    TIFFOpenOptionsSetErrorHandlerExtR(options, on_tiff_error, &messages_);
    TIFFOpenOptionsSetWarningHandlerExtR(options, on_tiff_warning, nullptr);
    tiff_ = TIFFFdOpenExt(descriptor, name.c_str(), mode, options);
    TIFFOpenOptionsFree(options);
    if (tiff_ == nullptr) ::close(descriptor);  // on success TIFFClose closes it
  }
  ~TiffFile() {
    if (tiff_ != nullptr) TIFFClose(tiff_);
  }
  TiffFile(const TiffFile&) = delete;
  TiffFile& operator=(const TiffFile&) = delete;

  TIFF* get() const { return tiff_; }
  const char* error() const { return messages_.error[0] != '\0' ? messages_.error : "libtiff error"; }
  /// Why a write failed: the system's error (No space left on device...) if there was one.
  const char* write_error() const { return messages_.os_error != 0 ? std::strerror(messages_.os_error) : error(); }
  /// Flushes and closes; false if libtiff failed to write.
  bool close() {
    const bool flushed = TIFFFlush(tiff_) == 1 && messages_.error[0] == '\0';
    TIFFClose(tiff_);
    tiff_ = nullptr;
    return flushed && messages_.error[0] == '\0';
  }

 private:
  TiffMessages messages_;  // declared first: libtiff holds a pointer to it until TIFFClose
  TIFF* tiff_ = nullptr;
};

/// The GeoKey directory of an open TIFF.
class GeoKeys {
 public:
  explicit GeoKeys(TIFF* tiff) : keys_(GTIFNewEx(tiff, on_geotiff_error, nullptr)) {}
  ~GeoKeys() {
    if (keys_ != nullptr) GTIFFree(keys_);
  }
  GeoKeys(const GeoKeys&) = delete;
  GeoKeys& operator=(const GeoKeys&) = delete;
  GTIF* get() const { return keys_; }
  std::optional<unsigned short> get_short(geokey_t key) const {
    unsigned short value = 0;
    if (keys_ == nullptr || GTIFKeyGetSHORT(keys_, key, &value, 0, 1) != 1) return std::nullopt;
    return value;
  }
  std::optional<std::string> get_ascii(geokey_t key) const {
    if (keys_ == nullptr) return std::nullopt;
    int size = 0;
    tagtype_t type = TYPE_UNKNOWN;
    const int count = GTIFKeyInfo(keys_, key, &size, &type);
    if (count <= 0 || type != TYPE_ASCII) return std::nullopt;
    std::string text(static_cast<std::size_t>(count) + 1, '\0');
    if (GTIFKeyGet(keys_, key, text.data(), 0, count) <= 0) return std::nullopt;
    text.resize(std::strlen(text.c_str()));
    return text;
  }
  std::optional<double> get_double(geokey_t key) const {
    double value = 0.0;
    if (keys_ == nullptr || GTIFKeyGetDOUBLE(keys_, key, &value, 0, 1) != 1) return std::nullopt;
    return value;
  }

 private:
  GTIF* keys_;
};

/// What a file written without a CRS calls its coordinates (recipes before version 5).
constexpr char citation[] = "Sansui local grid in metres (no CRS known; x east, y north)";

/// The prefix under which GDAL reads (and writes) the WKT of a CRS without an EPSG code.
constexpr std::string_view esri_pe_prefix = "ESRI PE String = ";

/// Rows per strip so that one strip is about 256 KiB (small enough for partial reads, large
/// enough for the compressor).
std::uint32_t rows_per_strip(int width) {
  return static_cast<std::uint32_t>(std::max<std::size_t>(1, (std::size_t{1} << 18) / (static_cast<std::size_t>(width) * 4)));
}

void write_georeference(TIFF* tiff, const Heightfield& heights, const std::optional<Crs>& crs) {
  const double cell = heights.cell_size_m;
  double scale[3] = {cell, cell, 0.0};
  double tiepoint[6] = {0.0, 0.0, 0.0, heights.origin_x_m - 0.5 * cell, -heights.origin_y_m + 0.5 * cell, 0.0};
  TIFFSetField(tiff, TIFFTAG_GEOPIXELSCALE, 3, scale);
  TIFFSetField(tiff, TIFFTAG_GEOTIEPOINTS, 6, tiepoint);
  GeoKeys keys(tiff);
  GTIF* gtif = keys.get();
  GTIFKeySet(gtif, GTModelTypeGeoKey, TYPE_SHORT, 1, ModelTypeProjected);
  GTIFKeySet(gtif, GTRasterTypeGeoKey, TYPE_SHORT, 1, RasterPixelIsArea);
  if (!crs || is_local_metres(*crs)) {
    // No CRS, or local metres (version 5 on): only what is known, "planar metres in some local
    // projection", under a name GDAL reads as an engineering CRS's.
    const char* name = crs ? crs->name.c_str() : citation;
    GTIFKeySet(gtif, GTCitationGeoKey, TYPE_ASCII, 0, name);
    GTIFKeySet(gtif, ProjectedCSTypeGeoKey, TYPE_SHORT, 1, KvUserDefined);
    GTIFKeySet(gtif, PCSCitationGeoKey, TYPE_ASCII, 0, name);
    GTIFKeySet(gtif, ProjLinearUnitsGeoKey, TYPE_SHORT, 1, Linear_Meter);
  } else if (crs->epsg > 0 && crs->epsg < KvUserDefined) {
    // A CRS with an EPSG code: the code says everything (GDAL, QGIS and ArcGIS look it up).
    GTIFKeySet(gtif, GTCitationGeoKey, TYPE_ASCII, 0, crs->name.c_str());
    GTIFKeySet(gtif, ProjectedCSTypeGeoKey, TYPE_SHORT, 1, crs->epsg);
  } else {
    // No code (or one too large for the key): user-defined, with the WKT where GDAL reads it.
    const std::string text = std::string(esri_pe_prefix) + crs->wkt;
    GTIFKeySet(gtif, GTCitationGeoKey, TYPE_ASCII, 0, crs->name.c_str());
    GTIFKeySet(gtif, ProjectedCSTypeGeoKey, TYPE_SHORT, 1, KvUserDefined);
    GTIFKeySet(gtif, PCSCitationGeoKey, TYPE_ASCII, 0, text.c_str());
    GTIFKeySet(gtif, ProjLinearUnitsGeoKey, TYPE_SHORT, 1, Linear_Meter);
  }
  GTIFKeySet(gtif, VerticalUnitsGeoKey, TYPE_SHORT, 1, Linear_Meter);
  GTIFWriteKeys(gtif);
}

// ---- reading ---------------------------------------------------------------------------------

enum class SampleType { u8, i16, u16, i32, u32, f32, f64 };

std::optional<SampleType> sample_type_of(std::uint16_t format, std::uint16_t bits) {
  if (format == SAMPLEFORMAT_UINT && bits == 8) return SampleType::u8;
  if (format == SAMPLEFORMAT_INT && bits == 16) return SampleType::i16;
  if (format == SAMPLEFORMAT_UINT && bits == 16) return SampleType::u16;
  if (format == SAMPLEFORMAT_INT && bits == 32) return SampleType::i32;
  if (format == SAMPLEFORMAT_UINT && bits == 32) return SampleType::u32;
  if (format == SAMPLEFORMAT_IEEEFP && bits == 32) return SampleType::f32;
  if (format == SAMPLEFORMAT_IEEEFP && bits == 64) return SampleType::f64;
  return std::nullopt;
}

template <class T>
double load(const unsigned char* bytes) {
  T value;
  std::memcpy(&value, bytes, sizeof value);  // libtiff delivers native byte order
  return static_cast<double>(value);
}

/// Sample `index` of a decoded strip or tile, in the file's units.
double sample_at(const unsigned char* buffer, std::size_t index, SampleType type) {
  switch (type) {
    case SampleType::u8:
      return buffer[index];
    case SampleType::i16:
      return load<std::int16_t>(buffer + 2 * index);
    case SampleType::u16:
      return load<std::uint16_t>(buffer + 2 * index);
    case SampleType::i32:
      return load<std::int32_t>(buffer + 4 * index);
    case SampleType::u32:
      return load<std::uint32_t>(buffer + 4 * index);
    case SampleType::f32:
      return load<float>(buffer + 4 * index);
    case SampleType::f64:
      return load<double>(buffer + 8 * index);
  }
  return 0.0;
}

struct SampleDecoding {
  SampleType type;
  double scale_to_m = 1.0;                       ///< vertical unit (feet → metres)
  std::optional<double> no_data;                 ///< GDAL's no-data value, if the file has one
  std::vector<std::uint8_t>* missing = nullptr;  ///< set per NoData sample (row-major)
};

/// Converts one block (strip or tile) of `block_width` x `rows` samples whose top-left sample is
/// (x0, y0) into `heights`, clipped to the grid. Marks NoData samples missing; fails on other
/// non-finite samples.
void decode_block(const std::filesystem::path& path, const unsigned char* buffer, const SampleDecoding& decoding, std::uint32_t block_width,
                  std::uint32_t rows, std::uint32_t x0, std::uint32_t y0, Heightfield& heights) {
  const auto width = static_cast<std::uint32_t>(heights.width()), height = static_cast<std::uint32_t>(heights.height());
  for (std::uint32_t row = 0; row < rows && y0 + row < height; ++row) {
    for (std::uint32_t column = 0; column < block_width && x0 + column < width; ++column) {
      const double value = sample_at(buffer, static_cast<std::size_t>(row) * block_width + column, decoding.type);
      const std::uint32_t x = x0 + column, y = y0 + row;
      if (decoding.no_data && value == *decoding.no_data) {
        (*decoding.missing)[static_cast<std::size_t>(y) * width + x] = 1;
        heights(static_cast<int>(x), static_cast<int>(y)) = 0.0f;
        continue;
      }
      const auto metres = static_cast<float>(value * decoding.scale_to_m);
      if (!std::isfinite(metres)) fail("cannot read {}: sample ({}, {}) is {}: heights must be finite numbers", path.string(), x, y, value);
      heights(static_cast<int>(x), static_cast<int>(y)) = metres;
    }
  }
}

void read_samples(const std::filesystem::path& path, TiffFile& file, const SampleDecoding& decoding, Heightfield& heights) {
  TIFF* tiff = file.get();
  if (TIFFIsTiled(tiff)) {
    std::uint32_t tile_width = 0, tile_height = 0;
    TIFFGetField(tiff, TIFFTAG_TILEWIDTH, &tile_width);
    TIFFGetField(tiff, TIFFTAG_TILELENGTH, &tile_height);
    // A corrupt header must not make us allocate gigabytes: real DEM tiles are at most a few MiB.
    if (tile_width == 0 || tile_height == 0 || std::uint64_t{tile_width} * tile_height > (std::uint64_t{1} << 26))
      fail("cannot read {}: corrupt tile size {} x {}", path.string(), tile_width, tile_height);
    std::vector<unsigned char> buffer(static_cast<std::size_t>(TIFFTileSize(tiff)));
    for (std::uint32_t y0 = 0; y0 < static_cast<std::uint32_t>(heights.height()); y0 += tile_height)
      for (std::uint32_t x0 = 0; x0 < static_cast<std::uint32_t>(heights.width()); x0 += tile_width) {
        if (TIFFReadTile(tiff, buffer.data(), x0, y0, 0, 0) < 0)
          fail("cannot read {}: the file is truncated or corrupt ({})", path.string(), file.error());
        decode_block(path, buffer.data(), decoding, tile_width, tile_height, x0, y0, heights);
      }
    return;
  }
  std::uint32_t strip_rows = 0;
  TIFFGetFieldDefaulted(tiff, TIFFTAG_ROWSPERSTRIP, &strip_rows);
  strip_rows = std::min(strip_rows, static_cast<std::uint32_t>(heights.height()));
  if (strip_rows == 0) fail("cannot read {}: corrupt strip layout", path.string());
  std::vector<unsigned char> buffer(static_cast<std::size_t>(TIFFStripSize(tiff)));
  const std::uint32_t strips = TIFFNumberOfStrips(tiff);
  for (std::uint32_t strip = 0; strip < strips; ++strip) {
    const std::uint32_t y0 = strip * strip_rows;
    if (y0 >= static_cast<std::uint32_t>(heights.height())) break;
    if (TIFFReadEncodedStrip(tiff, strip, buffer.data(), static_cast<tmsize_t>(buffer.size())) < 0)
      fail("cannot read {}: the file is truncated or corrupt ({})", path.string(), file.error());
    decode_block(path, buffer.data(), decoding, static_cast<std::uint32_t>(heights.width()), strip_rows, 0, y0, heights);
  }
}

/// Metres per unit of a linear-units GeoKey value; nullopt for units we do not know.
std::optional<double> metres_per_unit(unsigned short unit) {
  switch (unit) {
    case Linear_Meter:
      return 1.0;
    case Linear_Foot:
      return 0.3048;
    case Linear_Foot_US_Survey:
      return 1200.0 / 3937.0;
    default:
      return std::nullopt;
  }
}

/// Cells from the file's tags, in metres, checked as a cell size option is: finite, within
/// [min_cell_m, max_cell_m], an origin within max_origin_m, and width and height at most 1000
/// to 1 apart (non-square cells are resampled to square ones: a larger ratio would multiply
/// the samples by it).
void check_cells(const std::filesystem::path& path, const GeoReference& georeference) {
  constexpr double min_cell_m = 1e-6, max_cell_m = 1e7, max_origin_m = 1e9, max_ratio = 1000.0;
  const double cell_x = *georeference.cell_size_m, cell_y = georeference.cell_height_m.value_or(cell_x);
  for (const double cell : {cell_x, cell_y})
    if (!(cell >= min_cell_m && cell <= max_cell_m))
      fail("cannot read {}: its cells are {:g} x {:g} m (pixel scale times linear unit): each side must be between {:g} and {:g} m",
           path.string(), cell_x, cell_y, min_cell_m, max_cell_m);
  if (std::max(cell_x, cell_y) > max_ratio * std::min(cell_x, cell_y))
    fail("cannot read {}: its cells are {:g} x {:g} m, more than {:g} times longer than wide: resample it first (gdalwarp -tr X Y)",
         path.string(), cell_x, cell_y, max_ratio);
  const double x0 = *georeference.origin_x_m, y0 = *georeference.origin_y_m;
  if (!(std::abs(x0) <= max_origin_m && std::abs(y0) <= max_origin_m))
    fail("cannot read {}: its origin ({:g}, {:g}) m is not allowed: coordinates must lie within {:g} m of 0", path.string(), x0, y0,
         max_origin_m);
}

/// Cell size and origin of the sample (0, 0) from ModelPixelScale + ModelTiepoint (or an
/// axis-aligned ModelTransformation), in metres.
void read_georeference(const std::filesystem::path& path, TIFF* tiff, GeoReference& georeference,
                       std::optional<double> cell_size_for_degrees_m) {
  GeoKeys keys(tiff);
  const auto model = keys.get_short(GTModelTypeGeoKey);
  const bool area = keys.get_short(GTRasterTypeGeoKey).value_or(RasterPixelIsArea) != RasterPixelIsPoint;
  double unit_m = 1.0;
  if (const auto unit = keys.get_short(ProjLinearUnitsGeoKey)) {
    const auto known = metres_per_unit(*unit);
    const auto user_defined = keys.get_double(ProjLinearUnitSizeGeoKey);
    if (!known && !user_defined) fail("cannot read {}: linear unit code {} is not supported (metres or feet)", path.string(), *unit);
    unit_m = known ? *known : *user_defined;
    // A user-defined unit is a number from the file: NaN, 0 or a negative size would make every
    // cell size and slope NaN or negative (1 mm to 1000 km covers every unit in use).
    if (!(unit_m >= 1e-3 && unit_m <= 1e6))
      fail("cannot read {}: its linear unit size (ProjLinearUnitSizeGeoKey) is {} m: it must be a finite number between 0.001 and 1e6 m",
           path.string(), unit_m);
  }

  // sample (i, j) stands at model (x0 + i * scale_x, y0 - j * scale_y)
  double scale_x = 0.0, scale_y = 0.0, x0 = 0.0, y0 = 0.0;
  std::uint16_t count = 0;  // the GeoTIFF tags are TIFF_VARIABLE: a 16-bit count
  double* values = nullptr;
  double* tiepoints = nullptr;
  std::uint16_t tiepoint_count = 0;
  if (TIFFGetField(tiff, TIFFTAG_GEOPIXELSCALE, &count, &values) == 1 && count >= 2) {
    scale_x = values[0];
    scale_y = values[1];
    if (TIFFGetField(tiff, TIFFTAG_GEOTIEPOINTS, &tiepoint_count, &tiepoints) == 1 && tiepoint_count >= 6) {
      const double pixel_offset = area ? 0.5 : 0.0;  // sample = pixel centre for PixelIsArea
      x0 = tiepoints[3] + (pixel_offset - tiepoints[0]) * scale_x;
      y0 = tiepoints[4] - (pixel_offset - tiepoints[1]) * scale_y;
    }
  } else if (TIFFGetField(tiff, TIFFTAG_GEOTRANSMATRIX, &count, &values) == 1 && count >= 16) {
    if (values[1] != 0.0 || values[4] != 0.0)
      fail(
          "cannot read {}: its georeferencing is rotated or sheared (ModelTransformation terms {} and {} are not 0); Sansui grids are "
          "north-up: warp it north-up first (gdalwarp -t_srs EPSG:CODE IN.tif OUT.tif)",
          path.string(), values[1], values[4]);
    scale_x = values[0];
    scale_y = -values[5];
    const double pixel_offset = area ? 0.5 : 0.0;
    x0 = values[3] + pixel_offset * scale_x;
    y0 = values[7] - pixel_offset * scale_y;
  } else {
    return;  // no georeferencing: the caller uses the sidecar, options or defaults
  }
  if (!(scale_x > 0.0) || !(scale_y > 0.0) || !std::isfinite(scale_x) || !std::isfinite(scale_y) || !std::isfinite(x0) ||
      !std::isfinite(y0))
    fail("cannot read {}: its pixel scale {} x {} is not usable (it must be > 0)", path.string(), scale_x, scale_y);

  if (const auto code = keys.get_short(model == ModelTypeGeographic ? GeographicTypeGeoKey : ProjectedCSTypeGeoKey);
      code && *code > 0 && *code < KvUserDefined)
    georeference.epsg = *code;
  for (const geokey_t key : {PCSCitationGeoKey, GTCitationGeoKey})
    if (const auto text = keys.get_ascii(key); text && text->starts_with(esri_pe_prefix) && georeference.esri_wkt.empty())
      georeference.esri_wkt = text->substr(esri_pe_prefix.size());
  georeference.geographic = model == ModelTypeGeographic;
  if (model == ModelTypeGeographic) {
    // Degrees are not metres, and Sansui grids are metric: the caller must say the cell size.
    if (!cell_size_for_degrees_m)
      fail(
          "cannot read {}: it is in geographic coordinates ({} x {} degrees per cell), not metres: reproject it to a projected CRS "
          "in metres (e.g. gdalwarp -t_srs EPSG:32633 IN.tif OUT.tif, the UTM zone of the place) or give the cell size in metres "
          "([file] cell, --cell M) to read it as a local grid without its CRS",
          path.string(), scale_x, scale_y);
    georeference.cell_size_m = *cell_size_for_degrees_m;
    georeference.origin_x_m = 0.0;
    georeference.origin_y_m = 0.0;
    return;
  }
  georeference.cell_size_m = scale_x * unit_m;
  if (std::abs(scale_x - scale_y) > 1e-9 * std::max(scale_x, scale_y)) georeference.cell_height_m = scale_y * unit_m;
  georeference.origin_x_m = x0 * unit_m + 0.0;
  georeference.origin_y_m = -y0 * unit_m + 0.0;  // north-up model y, south-going grid y; + 0.0 drops -0
  check_cells(path, georeference);
}

}  // namespace

void write_geotiff(const std::filesystem::path& temporary, const std::filesystem::path& target, const Heightfield& heights,
                   Compression compression, const std::optional<Crs>& crs) {
  // Classic TIFF addresses 4 GiB; larger grids need BigTIFF ("w8"), which GDAL and QGIS read too.
  const bool big = heights.size() * sizeof(float) > (std::size_t{1} << 31);
  TiffFile file(temporary, target, big ? "w8" : "w");
  TIFF* tiff = file.get();
  if (tiff == nullptr) fail("cannot write {}: {}", target.string(), file.error());
  errno = 0;  // so that an error libtiff reports while writing carries its own errno, not an old one
  TIFFSetField(tiff, TIFFTAG_IMAGEWIDTH, static_cast<std::uint32_t>(heights.width()));
  TIFFSetField(tiff, TIFFTAG_IMAGELENGTH, static_cast<std::uint32_t>(heights.height()));
  TIFFSetField(tiff, TIFFTAG_SAMPLESPERPIXEL, 1);
  TIFFSetField(tiff, TIFFTAG_BITSPERSAMPLE, 32);
  TIFFSetField(tiff, TIFFTAG_SAMPLEFORMAT, SAMPLEFORMAT_IEEEFP);
  TIFFSetField(tiff, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
  TIFFSetField(tiff, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
  // On an 8193 x 8193 terrain, Deflate level 1 takes 3.0 s for 159 MB (59 % of the samples);
  // level 6, 8.7 s for 154 MB; level 9, 29 s for 150 MB; level 12 (libdeflate's highest), 45 s
  // for 150 MB. The floating-point predictor does most of the work (233 MB without it).
  if (compression == Compression::none) {
    TIFFSetField(tiff, TIFFTAG_COMPRESSION, COMPRESSION_NONE);
  } else {
    TIFFSetField(tiff, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE);
    TIFFSetField(tiff, TIFFTAG_PREDICTOR, PREDICTOR_FLOATINGPOINT);
    TIFFSetField(tiff, TIFFTAG_ZIPQUALITY, compression == Compression::small ? 9 : 1);
  }
  const std::uint32_t strip_rows = rows_per_strip(heights.width());
  TIFFSetField(tiff, TIFFTAG_ROWSPERSTRIP, strip_rows);
  TIFFSetField(tiff, TIFFTAG_SOFTWARE, "Sansui " SANSUI_VERSION);
  write_georeference(tiff, heights, crs);

  // Whole strips at once: then libtiff compresses with libdeflate (twice as fast as zlib row by
  // row). The strip is a copy because the predictor works in place on the buffer it is given.
  std::vector<float> strip(static_cast<std::size_t>(heights.width()) * strip_rows);
  for (std::uint32_t y0 = 0, index = 0; y0 < static_cast<std::uint32_t>(heights.height()); y0 += strip_rows, ++index) {
    const std::uint32_t rows = std::min(strip_rows, static_cast<std::uint32_t>(heights.height()) - y0);
    for (std::uint32_t row = 0; row < rows; ++row)
      std::ranges::copy(heights.row(static_cast<int>(y0 + row)), strip.begin() + static_cast<std::ptrdiff_t>(row) * heights.width());
    const auto bytes = static_cast<tmsize_t>(rows) * heights.width() * static_cast<tmsize_t>(sizeof(float));
    if (TIFFWriteEncodedStrip(tiff, index, strip.data(), bytes) != bytes) fail("cannot write {}: {}", target.string(), file.write_error());
  }
  if (!file.close()) fail("cannot write {}: {}", target.string(), file.write_error());
}

Heightfield read_geotiff(const std::filesystem::path& path, GeoReference& georeference, std::optional<double> cell_size_for_degrees_m) {
  TiffFile file(path, path, "r");
  TIFF* tiff = file.get();
  if (tiff == nullptr) fail("cannot read {}: not a readable TIFF ({})", path.string(), file.error());

  std::uint32_t width = 0, height = 0;
  std::uint16_t samples_per_pixel = 1, bits = 1, format = SAMPLEFORMAT_UINT;
  TIFFGetField(tiff, TIFFTAG_IMAGEWIDTH, &width);
  TIFFGetField(tiff, TIFFTAG_IMAGELENGTH, &height);
  TIFFGetFieldDefaulted(tiff, TIFFTAG_SAMPLESPERPIXEL, &samples_per_pixel);
  TIFFGetFieldDefaulted(tiff, TIFFTAG_BITSPERSAMPLE, &bits);
  TIFFGetFieldDefaulted(tiff, TIFFTAG_SAMPLEFORMAT, &format);
  if (width == 0 || height == 0) fail("cannot read {}: the image is empty", path.string());
  if (samples_per_pixel != 1)
    fail("cannot read {}: it has {} bands; a heightmap has one (extract it with gdal_translate -b 1)", path.string(), samples_per_pixel);
  const auto type = sample_type_of(format, bits);
  if (!type)
    fail("cannot read {}: {}-bit samples of format {} are not supported (8/16/32-bit integers, 32/64-bit floats)", path.string(), bits,
         format);
  require_plausible_size(path, width, height);

  SampleDecoding decoding{*type, 1.0, std::nullopt};
  {
    GeoKeys keys(tiff);
    if (const auto unit = keys.get_short(VerticalUnitsGeoKey)) decoding.scale_to_m = metres_per_unit(*unit).value_or(1.0);
  }
  char* no_data_text = nullptr;
  if (TIFFGetField(tiff, TIFFTAG_GDAL_NODATA, &no_data_text) == 1 && no_data_text != nullptr) {
    char* end = nullptr;
    const double value = std::strtod(no_data_text, &end);
    if (end != no_data_text && !std::isnan(value)) decoding.no_data = value;  // NaN no-data fails as non-finite anyway
  }
  read_georeference(path, tiff, georeference, cell_size_for_degrees_m);

  auto heights = Heightfield::uninitialized(static_cast<int>(width), static_cast<int>(height));
  std::vector<std::uint8_t> missing(decoding.no_data ? heights.size() : 0, 0);
  decoding.missing = &missing;
  read_samples(path, file, decoding, heights);
  if (decoding.no_data) {
    const std::string name = path.filename().string();
    if (const std::size_t filled = fill_no_data(heights, missing, name.c_str()); filled > 0)
      georeference.notes.push_back(no_data_note(name, filled, heights.size()));
  }
  return heights;
}

}  // namespace sansui::io::detail

namespace sansui::io::detail {

GeoReference read_geotiff_georeference(const std::filesystem::path& path) {
  TiffFile file(path, path, "r");
  if (file.get() == nullptr) fail("cannot read {}: not a readable TIFF ({})", path.string(), file.error());
  GeoReference georeference;
  read_georeference(path, file.get(), georeference, 1.0);  // any cell size: only the keys are wanted
  return georeference;
}

}  // namespace sansui::io::detail
