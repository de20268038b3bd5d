// DEMs in every raster format GDAL reads (ESRI ASCII grid, SRTM HGT, ERDAS IMAGINE, VRT mosaics,
// BIL, ...), read through GDAL's C API: band 1 as float32 metres (its scale and offset applied),
// north up, square cells or resampled by the caller, NoData filled from the nearest valid sample
// with a note. The project's own readers keep PNG, RAW, R32 and GeoTIFF: they are byte-stable
// and faster, and their sidecars describe them.
#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "io/gdal_api.hpp"
#include "io/gdal_local.hpp"
#include "io/heightmap_formats.hpp"
#include "io/no_data_fill.hpp"

namespace sansui::io::detail {
namespace {

/// Largest side a DEM may have (as the GeoTIFF reader allows). [Units: samples]
constexpr int max_side = 1 << 20;
/// Metres per degree of latitude, and of longitude at the equator (WGS 84, rounded). [Units: m]
constexpr double metres_per_degree_latitude = 110574.0, metres_per_degree_longitude = 111320.0;

/// GDAL's errors go to the last-error slot, not to stderr, while one of these lives (per thread).
struct QuietGdal {
  QuietGdal() {
    gdal_api().CPLPushErrorHandler(gdal_api().CPLQuietErrorHandler);
    gdal_api().CPLErrorReset();
  }
  ~QuietGdal() { gdal_api().CPLPopErrorHandler(); }
  QuietGdal(const QuietGdal&) = delete;
  QuietGdal& operator=(const QuietGdal&) = delete;
};

std::string last_error() {
  const char* message = gdal_api().CPLGetLastErrorMsg();
  return message != nullptr && *message != '\0' ? message : "GDAL gave no reason";
}

struct DatasetCloser {
  void operator()(void* dataset) const { gdal_api().GDALClose(dataset); }
};
using Dataset = std::unique_ptr<void, DatasetCloser>;

/// Opens a checked raster (gdal_local.hpp): by its real name, with the local drivers only, and
/// with GDAL told which files beside it exist (the checked companions), so it looks for no others.
Dataset open_raster(const std::filesystem::path& path) {
  const CheckedRaster checked = check_gdal_input(path);
  std::vector<const char*> siblings;
  siblings.reserve(checked.siblings.size() + 1);
  for (const std::string& name : checked.siblings) siblings.push_back(name.c_str());
  siblings.push_back(nullptr);
  Dataset dataset(
      gdal_api().GDALOpenEx(checked.file.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, local_gdal_drivers(), nullptr, siblings.data()));
  if (!dataset) fail("cannot read {}: GDAL cannot open it as a raster ({})", path.string(), last_error());
  return dataset;
}

/// The dataset's CRS as WKT (empty when it has none), and whether it is geographic.
std::pair<std::string, bool> crs_of(GDALDatasetH dataset) {
  OGRSpatialReferenceH srs = gdal_api().GDALGetSpatialRef(dataset);
  if (srs == nullptr) return {"", false};
  char* wkt = nullptr;
  const char* options[] = {"FORMAT=WKT2_2019", nullptr};
  std::string text;
  if (gdal_api().OSRExportToWktEx(srs, &wkt, options) == OGRERR_NONE && wkt != nullptr) text = wkt;
  gdal_api().VSIFree(wkt);
  return {text, gdal_api().OSRIsGeographic(srs) != 0};
}

}  // namespace

Heightfield read_gdal_raster(const std::filesystem::path& path, GeoReference& georeference, std::optional<double> cell_size_for_degrees_m) {
  const LocalGdal local;  // before the dataset, which it outlives
  const QuietGdal quiet;
  const Dataset dataset = open_raster(path);
  GDALDatasetH handle = dataset.get();
  const int width = gdal_api().GDALGetRasterXSize(handle), height = gdal_api().GDALGetRasterYSize(handle);
  if (gdal_api().GDALGetRasterCount(handle) < 1) fail("cannot read {}: it has no raster band", path.string());
  if (width < 2 || height < 2 || width > max_side || height > max_side)
    fail("cannot read {}: {} x {} samples is not allowed: a DEM has 2 to {} samples a side", path.string(), width, height, max_side);
  check_memory(5.0 * static_cast<double>(width) * static_cast<double>(height), path.string());

  // Where it lies: north up, square cells (or the caller resamples), in metres.
  double transform[6] = {0.0, 1.0, 0.0, 0.0, 0.0, -1.0};
  const bool placed = gdal_api().GDALGetGeoTransform(handle, transform) == CE_None;
  if (placed && (transform[2] != 0.0 || transform[4] != 0.0))
    fail("cannot read {}: its grid is rotated; warp it north up first (gdalwarp IN OUT)", path.string());
  if (placed && !(transform[1] > 0.0 && transform[5] < 0.0))
    fail("cannot read {}: its rows do not run north to south with columns west to east (pixel size {:g} x {:g})", path.string(),
         transform[1], transform[5]);
  const auto [wkt, geographic] = crs_of(handle);
  georeference.geographic = geographic;
  const std::string name = path.filename().string();
  if (geographic) {
    // Degrees become metres at the middle latitude: a local grid, without the CRS.
    const double middle = transform[3] + 0.5 * height * transform[5];
    const double cell_x = transform[1] * metres_per_degree_longitude * std::cos(middle * std::numbers::pi / 180.0);
    const double cell_y = -transform[5] * metres_per_degree_latitude;
    if (cell_size_for_degrees_m) {
      georeference.cell_size_m = *cell_size_for_degrees_m;
    } else {
      georeference.cell_size_m = cell_x;
      if (std::abs(cell_x - cell_y) > 1e-9 * cell_y) georeference.cell_height_m = cell_y;
      georeference.notes.push_back(fmt::format(
          "{}: in degrees ({:g} x {:g} per cell); read as a local grid of {:.4g} x {:.4g} m cells at latitude {:.4g}, without its CRS "
          "(reproject it with gdalwarp -t_srs to keep one)",
          name, transform[1], -transform[5], cell_x, cell_y, middle));
    }
    georeference.origin_x_m = 0.0;
    georeference.origin_y_m = 0.0;
  } else if (placed) {
    georeference.cell_size_m = transform[1];
    if (std::abs(transform[1] + transform[5]) > 1e-9 * transform[1]) georeference.cell_height_m = -transform[5];
    // Sample (0, 0) is the centre of the upper-left pixel.
    georeference.origin_x_m = transform[0] + 0.5 * transform[1] + 0.0;
    georeference.origin_y_m = -(transform[3] + 0.5 * transform[5]) + 0.0;
    georeference.esri_wkt = wkt;  // the CRS, for read_gdal_raster_crs's callers
  }
  // No geotransform and not in degrees: no cell size yet (the sidecar's or the options' come later).
  const double cell_m = georeference.cell_size_m.value_or(1.0);
  if (!std::isfinite(cell_m) || cell_m <= 0.0 || !std::isfinite(georeference.origin_x_m.value_or(0.0)) ||
      !std::isfinite(georeference.origin_y_m.value_or(0.0)))
    fail("cannot read {}: its cell size or origin is not a finite position", path.string());
  if (!placed) georeference = GeoReference{};  // no geotransform: the sidecar's or the options' cell

  // The heights, band 1, as float32 metres.
  GDALRasterBandH band = gdal_api().GDALGetRasterBand(handle, 1);
  auto heights = Heightfield::uninitialized(width, height);
  if (gdal_api().GDALRasterIO(band, GF_Read, 0, 0, width, height, heights.values().data(), width, height, GDT_Float32, 0, 0) != CE_None)
    fail("cannot read {}: {}", path.string(), last_error());
  int has_no_data = 0, has_scale = 0, has_offset = 0;
  const double no_data = gdal_api().GDALGetRasterNoDataValue(band, &has_no_data);
  const double scale = gdal_api().GDALGetRasterScale(band, &has_scale), offset = gdal_api().GDALGetRasterOffset(band, &has_offset);
  const auto no_data_float = static_cast<float>(no_data);
  std::vector<std::uint8_t> missing(heights.size(), 0);
  std::size_t missing_count = 0;
  float* values = heights.values().data();
  for (std::size_t i = 0; i < heights.size(); ++i) {
    if ((has_no_data != 0 && (values[i] == no_data_float || (std::isnan(no_data) && std::isnan(values[i])))) || !std::isfinite(values[i])) {
      missing[i] = 1;
      ++missing_count;
      continue;
    }
    if (has_scale != 0 || has_offset != 0)
      values[i] = static_cast<float>(values[i] * (has_scale != 0 ? scale : 1.0) + (has_offset != 0 ? offset : 0.0));
  }
  if (missing_count > 0) {
    fill_no_data(heights, missing, name.c_str());
    georeference.notes.push_back(no_data_note(name, missing_count, heights.size()));
  }
  return heights;
}

std::string read_gdal_raster_crs(const std::filesystem::path& path) {
  const LocalGdal local;
  const QuietGdal quiet;
  const Dataset dataset = open_raster(path);
  const auto [wkt, geographic] = crs_of(dataset.get());
  return geographic ? "" : wkt;
}

}  // namespace sansui::io::detail
