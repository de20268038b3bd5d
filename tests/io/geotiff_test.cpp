// GeoTIFF heightmaps: float32 round trips bit for bit with cell size and origin; the tags and
// GeoKeys as libtiff/libgeotiff read them; DEMs of other sample types, tiled, pixel-is-point,
// geographic, with no-data or several bands, as later issues will read them.
#include <cstring>
#include <limits>
#include <optional>
#include <vector>

#include <geotiff.h>
#include <tiffio.h>

#include <geovalues.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <xtiffio.h>

#include "io/heightmap_io.hpp"
#include "tests/io/io_test_util.hpp"
#include "tests/test_util.hpp"

namespace sansui {
namespace {

using ::testing::HasSubstr;

/// What a hand-made test DEM looks like.
struct DemSpec {
  int width = 5, height = 4;
  std::uint16_t sample_format = SAMPLEFORMAT_INT, bits = 16, bands = 1;
  bool tiled = false;
  bool pixel_is_point = false;
  bool geographic = false;
  double scale = 30.0, tie_x = 500000.0, tie_y = 4100000.0;
  double scale_y = 0.0;  ///< north-south pixel scale; 0: the same as scale
  const char* no_data = nullptr;
  std::optional<double> linear_unit_size;  ///< a user-defined linear unit of this many metres
};

/// Sample (x, y) of the test DEMs: distinct, exactly representable in every sample type.
double dem_value(int x, int y) {
  return 100.0 + 7.0 * x + 3.0 * y;
}

template <class T>
void put(std::vector<unsigned char>& bytes, std::size_t index, double value) {
  const T typed = static_cast<T>(value);
  std::memcpy(bytes.data() + index * sizeof(T), &typed, sizeof(T));
}

void write_dem(const std::filesystem::path& path, const DemSpec& spec) {
  TIFF* tiff = XTIFFOpen(path.c_str(), "w");
  ASSERT_NE(tiff, nullptr);
  const std::size_t sample_bytes = spec.bits / 8u;
  TIFFSetField(tiff, TIFFTAG_IMAGEWIDTH, spec.width);
  TIFFSetField(tiff, TIFFTAG_IMAGELENGTH, spec.height);
  TIFFSetField(tiff, TIFFTAG_SAMPLESPERPIXEL, spec.bands);
  TIFFSetField(tiff, TIFFTAG_BITSPERSAMPLE, spec.bits);
  TIFFSetField(tiff, TIFFTAG_SAMPLEFORMAT, spec.sample_format);
  TIFFSetField(tiff, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
  TIFFSetField(tiff, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
  TIFFSetField(tiff, TIFFTAG_COMPRESSION, COMPRESSION_LZW);
  if (spec.no_data != nullptr) {
    // libtiff does not know GDAL's tag unless told (GDAL registers it the same way).
    static const TIFFFieldInfo no_data_field = {TIFFTAG_GDAL_NODATA, -1, -1, TIFF_ASCII,
                                                FIELD_CUSTOM,        1,  0,  const_cast<char*>("GDALNoDataValue")};
    if (TIFFFindField(tiff, TIFFTAG_GDAL_NODATA, TIFF_ANY) == nullptr) TIFFMergeFieldInfo(tiff, &no_data_field, 1);
    TIFFSetField(tiff, TIFFTAG_GDAL_NODATA, spec.no_data);
  }
  double scale[3] = {spec.scale, spec.scale_y != 0.0 ? spec.scale_y : spec.scale, 0.0};
  double tiepoint[6] = {0.0, 0.0, 0.0, spec.tie_x, spec.tie_y, 0.0};
  TIFFSetField(tiff, TIFFTAG_GEOPIXELSCALE, 3, scale);
  TIFFSetField(tiff, TIFFTAG_GEOTIEPOINTS, 6, tiepoint);
  GTIF* keys = GTIFNew(tiff);
  GTIFKeySet(keys, GTModelTypeGeoKey, TYPE_SHORT, 1, spec.geographic ? ModelTypeGeographic : ModelTypeProjected);
  GTIFKeySet(keys, GTRasterTypeGeoKey, TYPE_SHORT, 1, spec.pixel_is_point ? RasterPixelIsPoint : RasterPixelIsArea);
  if (spec.geographic)
    GTIFKeySet(keys, GeographicTypeGeoKey, TYPE_SHORT, 1, GCS_WGS_84);
  else
    GTIFKeySet(keys, ProjectedCSTypeGeoKey, TYPE_SHORT, 1, 32633);  // WGS 84 / UTM 33N, metres
  if (spec.linear_unit_size) {
    GTIFKeySet(keys, ProjLinearUnitsGeoKey, TYPE_SHORT, 1, KvUserDefined);
    GTIFKeySet(keys, ProjLinearUnitSizeGeoKey, TYPE_DOUBLE, 1, *spec.linear_unit_size);
  }
  GTIFWriteKeys(keys);
  GTIFFree(keys);

  const auto fill = [&](std::vector<unsigned char>& bytes, int x0, int y0, int block_width, int block_height) {
    for (int y = 0; y < block_height; ++y)
      for (int x = 0; x < block_width; ++x)
        for (int band = 0; band < spec.bands; ++band) {
          const std::size_t index = (static_cast<std::size_t>(y * block_width + x)) * spec.bands + band;
          const double value = dem_value(x0 + x, y0 + y);
          if (spec.sample_format == SAMPLEFORMAT_IEEEFP)
            spec.bits == 32 ? put<float>(bytes, index, value) : put<double>(bytes, index, value);
          else if (spec.sample_format == SAMPLEFORMAT_INT)
            spec.bits == 16 ? put<std::int16_t>(bytes, index, value) : put<std::int32_t>(bytes, index, value);
          else
            spec.bits == 16 ? put<std::uint16_t>(bytes, index, value) : put<std::uint8_t>(bytes, index, value);
        }
  };
  if (spec.tiled) {
    const int tile = 16;  // TIFF tiles are multiples of 16; the image is smaller, so edges are padding
    TIFFSetField(tiff, TIFFTAG_TILEWIDTH, tile);
    TIFFSetField(tiff, TIFFTAG_TILELENGTH, tile);
    for (int y0 = 0; y0 < spec.height; y0 += tile)
      for (int x0 = 0; x0 < spec.width; x0 += tile) {
        std::vector<unsigned char> bytes(static_cast<std::size_t>(tile * tile) * spec.bands * sample_bytes);
        fill(bytes, x0, y0, tile, tile);
        TIFFWriteTile(tiff, bytes.data(), static_cast<std::uint32_t>(x0), static_cast<std::uint32_t>(y0), 0, 0);
      }
  } else {
    TIFFSetField(tiff, TIFFTAG_ROWSPERSTRIP, 2);
    for (int y = 0; y < spec.height; ++y) {
      std::vector<unsigned char> bytes(static_cast<std::size_t>(spec.width) * spec.bands * sample_bytes);
      fill(bytes, 0, y, spec.width, 1);
      TIFFWriteScanline(tiff, bytes.data(), static_cast<std::uint32_t>(y), 0);
    }
  }
  XTIFFClose(tiff);
}

TEST(GeoTiff, Float32RoundTripsBitForBitWithCellSizeAndOrigin) {
  test::TempDir directory("geotiff-round");
  Heightfield heights = test::sample_heights(300, 77, 6);  // several strips, width not a multiple of anything
  heights.cell_size_m = 2.5;
  heights.origin_x_m = 1000.0;
  heights.origin_y_m = 2000.0;
  io::write_heightmap(directory / "h.tif", heights, {std::nullopt, {}, false});
  const Heightfield back = io::read_heightmap(directory / "h.tif");  // no sidecar: all from the tags
  ASSERT_EQ(back.width(), 300);
  ASSERT_EQ(back.height(), 77);
  EXPECT_EQ(test::hash_of(back), test::hash_of(heights));
  EXPECT_EQ(back.cell_size_m, 2.5);
  EXPECT_EQ(back.origin_x_m, 1000.0);
  EXPECT_EQ(back.origin_y_m, 2000.0);
}

TEST(GeoTiff, EveryCompressionRoundTripsBitForBit) {
  test::TempDir directory("geotiff-compression");
  const Heightfield heights = test::sample_heights(300, 77, 8);
  std::uintmax_t previous_size = 0;
  for (const auto& [compression, tag] :
       {std::pair{io::Compression::none, COMPRESSION_NONE}, std::pair{io::Compression::fast, COMPRESSION_ADOBE_DEFLATE},
        std::pair{io::Compression::small, COMPRESSION_ADOBE_DEFLATE}}) {
    io::HeightmapWriteOptions options;
    options.compression = compression;
    io::write_heightmap(directory / "h.tif", heights, options);
    EXPECT_EQ(test::hash_of(io::read_heightmap(directory / "h.tif")), test::hash_of(heights));
    TIFF* tiff = XTIFFOpen((directory / "h.tif").c_str(), "r");
    ASSERT_NE(tiff, nullptr);
    std::uint16_t stored = 0;
    TIFFGetField(tiff, TIFFTAG_COMPRESSION, &stored);
    XTIFFClose(tiff);
    EXPECT_EQ(stored, tag);
    // Each setting is smaller than the one before; stored samples take all their bytes.
    const std::uintmax_t size = std::filesystem::file_size(directory / "h.tif");
    if (compression == io::Compression::none)
      EXPECT_GE(size, heights.size() * sizeof(float));
    else
      EXPECT_LT(size, previous_size);
    previous_size = size;
  }
}

TEST(GeoTiff, WritesFloat32WithPixelScaleTiepointAndLocalMetreGeoKeys) {
  test::TempDir directory("geotiff-tags");
  Heightfield heights = test::sample_heights(9, 5);
  heights.cell_size_m = 10.0;
  heights.origin_x_m = 100.0;
  heights.origin_y_m = 40.0;
  io::write_heightmap(directory / "h.tif", heights);

  TIFF* tiff = XTIFFOpen((directory / "h.tif").c_str(), "r");
  ASSERT_NE(tiff, nullptr);
  std::uint16_t bits = 0, format = 0, samples = 0;
  TIFFGetField(tiff, TIFFTAG_BITSPERSAMPLE, &bits);
  TIFFGetField(tiff, TIFFTAG_SAMPLEFORMAT, &format);
  TIFFGetFieldDefaulted(tiff, TIFFTAG_SAMPLESPERPIXEL, &samples);
  EXPECT_EQ(bits, 32);
  EXPECT_EQ(format, SAMPLEFORMAT_IEEEFP);
  EXPECT_EQ(samples, 1);
  std::uint16_t count = 0;
  double* values = nullptr;
  ASSERT_EQ(TIFFGetField(tiff, TIFFTAG_GEOPIXELSCALE, &count, &values), 1);
  EXPECT_EQ(std::vector<double>(values, values + count), (std::vector<double>{10.0, 10.0, 0.0}));
  ASSERT_EQ(TIFFGetField(tiff, TIFFTAG_GEOTIEPOINTS, &count, &values), 1);
  // The corner of pixel (0, 0) is half a cell west and north of sample (0, 0); model y is north.
  EXPECT_EQ(std::vector<double>(values, values + count), (std::vector<double>{0.0, 0.0, 0.0, 95.0, -35.0, 0.0}));

  GTIF* keys = GTIFNew(tiff);
  ASSERT_NE(keys, nullptr);
  unsigned short model = 0, raster = 0, projected = 0, units = 0;
  EXPECT_EQ(GTIFKeyGetSHORT(keys, GTModelTypeGeoKey, &model, 0, 1), 1);
  EXPECT_EQ(GTIFKeyGetSHORT(keys, GTRasterTypeGeoKey, &raster, 0, 1), 1);
  EXPECT_EQ(GTIFKeyGetSHORT(keys, ProjectedCSTypeGeoKey, &projected, 0, 1), 1);
  EXPECT_EQ(GTIFKeyGetSHORT(keys, ProjLinearUnitsGeoKey, &units, 0, 1), 1);
  EXPECT_EQ(model, ModelTypeProjected);
  EXPECT_EQ(raster, RasterPixelIsArea);
  EXPECT_EQ(projected, KvUserDefined);
  EXPECT_EQ(units, Linear_Meter);
  GTIFFree(keys);

  std::vector<float> row(9);
  for (std::uint32_t y = 0; y < 5; ++y) ASSERT_EQ(TIFFReadScanline(tiff, row.data(), y, 0), 1);  // compressed: in order
  EXPECT_EQ(row[8], heights(8, 4));
  XTIFFClose(tiff);
}

TEST(GeoTiff, ReadsDemsOfEverySampleType) {
  test::TempDir directory("geotiff-types");
  const std::pair<std::uint16_t, std::uint16_t> types[] = {{SAMPLEFORMAT_INT, 16},    {SAMPLEFORMAT_UINT, 16}, {SAMPLEFORMAT_IEEEFP, 64},
                                                           {SAMPLEFORMAT_IEEEFP, 32}, {SAMPLEFORMAT_INT, 32},  {SAMPLEFORMAT_UINT, 8}};
  for (const auto& [format, bits] : types) {
    DemSpec spec;
    spec.sample_format = format;
    spec.bits = bits;
    const auto path = directory / ("dem-" + std::to_string(format) + "-" + std::to_string(bits) + ".tif");
    write_dem(path, spec);
    const Heightfield dem = io::read_heightmap(path);
    ASSERT_EQ(dem.width(), 5) << path;
    ASSERT_EQ(dem.height(), 4) << path;
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 5; ++x) EXPECT_EQ(dem(x, y), static_cast<float>(dem_value(x, y))) << path;
    EXPECT_EQ(dem.cell_size_m, 30.0);
    EXPECT_EQ(dem.origin_x_m, 500015.0);  // pixel-is-area: sample (0, 0) is the first pixel's centre
    EXPECT_EQ(dem.origin_y_m, -4099985.0);
  }
}

TEST(GeoTiff, ReadsTiledAndPixelIsPointDems) {
  test::TempDir directory("geotiff-tiled");
  DemSpec spec;
  spec.width = 37;
  spec.height = 21;
  spec.tiled = true;
  spec.pixel_is_point = true;
  write_dem(directory / "dem.tif", spec);
  const Heightfield dem = io::read_heightmap(directory / "dem.tif");
  ASSERT_EQ(dem.width(), 37);
  ASSERT_EQ(dem.height(), 21);
  for (int y = 0; y < 21; ++y)
    for (int x = 0; x < 37; ++x) ASSERT_EQ(dem(x, y), static_cast<float>(dem_value(x, y)));
  EXPECT_EQ(dem.origin_x_m, 500000.0);  // pixel-is-point: the tiepoint is sample (0, 0) itself
  EXPECT_EQ(dem.origin_y_m, -4100000.0);
}

TEST(GeoTiff, GeographicDemsNeedACellSizeInMetres) {
  test::TempDir directory("geotiff-degrees");
  DemSpec spec;
  spec.geographic = true;
  spec.scale = 1.0 / 3600.0;
  spec.tie_x = 138.0;
  spec.tie_y = 36.0;
  write_dem(directory / "dem.tif", spec);
  EXPECT_THAT(test::input_error_of([&] { io::read_heightmap(directory / "dem.tif"); }),
              HasSubstr("dem.tif: it is in geographic coordinates"));
  io::HeightmapReadOptions options;
  options.cell_size_m = 30.0;
  const Heightfield dem = io::read_heightmap(directory / "dem.tif", options);
  EXPECT_EQ(dem.cell_size_m, 30.0);
  EXPECT_EQ(dem(4, 3), static_cast<float>(dem_value(4, 3)));
}

TEST(GeoTiff, NoDataSamplesAreFilledAndSeveralBandsAreAnError) {
  test::TempDir directory("geotiff-nodata");
  DemSpec spec;
  spec.no_data = "121";  // dem_value(3, 0) == 121
  write_dem(directory / "holes.tif", spec);
  // The hole takes its nearest valid neighbour's height, and a note says how many were filled.
  io::HeightmapAssumptions assumed;
  const Heightfield filled = io::read_heightmap(directory / "holes.tif", {}, &assumed);
  EXPECT_EQ(filled(3, 0), filled(2, 0));
  ASSERT_EQ(assumed.notes.size(), 1u);
  EXPECT_THAT(assumed.notes[0], HasSubstr("holes.tif: 1 of"));
  EXPECT_THAT(assumed.notes[0], HasSubstr("were NoData; each took the height of its nearest valid sample"));
  spec.no_data = "-32768";  // present but unused: fine
  write_dem(directory / "complete.tif", spec);
  EXPECT_EQ(io::read_heightmap(directory / "complete.tif")(3, 0), 121.0f);

  DemSpec rgb;
  rgb.bands = 3;
  rgb.sample_format = SAMPLEFORMAT_UINT;
  rgb.bits = 8;
  write_dem(directory / "rgb.tif", rgb);
  EXPECT_THAT(test::input_error_of([&] { io::read_heightmap(directory / "rgb.tif"); }),
              HasSubstr("rgb.tif: it has 3 bands; a heightmap has one"));
}

TEST(GeoTiff, UserDefinedLinearUnitSizesMustBePositiveAndFinite) {
  test::TempDir directory("geotiff-unit");
  DemSpec spec;
  spec.linear_unit_size = 2.0;  // a unit of 2 m: cells of 30 units are 60 m
  write_dem(directory / "two.tif", spec);
  EXPECT_EQ(io::read_heightmap(directory / "two.tif").cell_size_m, 60.0);
  for (const double size : {std::numeric_limits<double>::quiet_NaN(), 0.0, -1.0, std::numeric_limits<double>::infinity(), 1e300}) {
    spec.linear_unit_size = size;
    write_dem(directory / "unit.tif", spec);
    EXPECT_THAT(test::input_error_of([&] { io::read_heightmap(directory / "unit.tif"); }),
                HasSubstr(fmt::format("unit.tif: its linear unit size (ProjLinearUnitSizeGeoKey) is {} m: it must be a finite number "
                                      "between 0.001 and 1e6 m",
                                      size)));
  }
}

TEST(GeoTiff, PixelScalesThatWouldMakeUnusableCellsAreRefused) {
  test::TempDir directory("geotiff-cells");
  DemSpec spec;
  spec.scale = 1e-9;  // a nanometre
  write_dem(directory / "tiny.tif", spec);
  EXPECT_THAT(test::input_error_of([&] { io::read_heightmap(directory / "tiny.tif"); }),
              HasSubstr("tiny.tif: its cells are 1e-09 x 1e-09 m (pixel scale times linear unit): each side must be between"));
  spec.scale = 30.0;
  spec.scale_y = 40000.0;  // resampled to square cells, this would be 1333 x more rows
  write_dem(directory / "long.tif", spec);
  EXPECT_THAT(test::input_error_of([&] { io::read_heightmap(directory / "long.tif"); }),
              HasSubstr("long.tif: its cells are 30 x 40000 m, more than 1000 times longer than wide"));
  spec.scale_y = 0.0;
  spec.tie_x = 1e300;
  write_dem(directory / "far.tif", spec);
  EXPECT_THAT(test::input_error_of([&] { io::read_heightmap(directory / "far.tif"); }), HasSubstr("far.tif: its origin"));
}

TEST(GeoTiff, NaNInAFloatDemIsAnError) {
  test::TempDir directory("geotiff-nan");
  // A float32 TIFF with one NaN, as a broken DEM might have.
  Heightfield heights = test::sample_heights(4, 4);
  TIFF* tiff = XTIFFOpen((directory / "nan.tif").c_str(), "w");
  ASSERT_NE(tiff, nullptr);
  TIFFSetField(tiff, TIFFTAG_IMAGEWIDTH, 4);
  TIFFSetField(tiff, TIFFTAG_IMAGELENGTH, 4);
  TIFFSetField(tiff, TIFFTAG_SAMPLESPERPIXEL, 1);
  TIFFSetField(tiff, TIFFTAG_BITSPERSAMPLE, 32);
  TIFFSetField(tiff, TIFFTAG_SAMPLEFORMAT, SAMPLEFORMAT_IEEEFP);
  TIFFSetField(tiff, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
  heights(1, 2) = std::numeric_limits<float>::quiet_NaN();
  for (int y = 0; y < 4; ++y) TIFFWriteScanline(tiff, heights.row(y).data(), static_cast<std::uint32_t>(y), 0);
  XTIFFClose(tiff);
  EXPECT_THAT(test::input_error_of([&] { io::read_heightmap(directory / "nan.tif"); }), HasSubstr("nan.tif: sample (1, 2) is nan"));
}

}  // namespace
}  // namespace sansui
