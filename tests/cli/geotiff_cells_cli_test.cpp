// GeoTIFFs whose cells are not square, through the binary (issue 17 item 7): every command that
// reads a DEM (render, contour --from-dem, contour-dem --grid-from, compare's real DEM) resamples
// rectangular cells to square ones and says so in a note; rotated georeferencing is refused with
// exit 2, one line and no file.
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <geotiff.h>
#include <tiffio.h>

#include <geovalues.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <xtiffio.h>

#include "tests/cli/cli_runner.hpp"
#include "tests/test_util.hpp"

namespace sansui::test {
namespace {

using ::testing::HasSubstr;

/// A float32 GeoTIFF of `height(x_m, y_m)` (metres east and south of the corner), cells
/// `scale_x` x `scale_y` m, or georeferenced by the 4x4 `transform` when given.
void write_geotiff(const std::filesystem::path& path, int width, int height, double scale_x, double scale_y,
                   const std::function<double(double, double)>& height_at, const double* transform = nullptr) {
  TIFF* tiff = XTIFFOpen(path.c_str(), "w");
  ASSERT_NE(tiff, nullptr);
  TIFFSetField(tiff, TIFFTAG_IMAGEWIDTH, width);
  TIFFSetField(tiff, TIFFTAG_IMAGELENGTH, height);
  TIFFSetField(tiff, TIFFTAG_SAMPLESPERPIXEL, 1);
  TIFFSetField(tiff, TIFFTAG_BITSPERSAMPLE, 32);
  TIFFSetField(tiff, TIFFTAG_SAMPLEFORMAT, SAMPLEFORMAT_IEEEFP);
  TIFFSetField(tiff, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
  TIFFSetField(tiff, TIFFTAG_ROWSPERSTRIP, 1);
  if (transform != nullptr) {
    TIFFSetField(tiff, TIFFTAG_GEOTRANSMATRIX, 16, transform);
  } else {
    double scale[3] = {scale_x, scale_y, 0.0};
    double tiepoint[6] = {0.0, 0.0, 0.0, 1000.0, 2000.0, 0.0};
    TIFFSetField(tiff, TIFFTAG_GEOPIXELSCALE, 3, scale);
    TIFFSetField(tiff, TIFFTAG_GEOTIEPOINTS, 6, tiepoint);
  }
  GTIF* keys = GTIFNew(tiff);
  GTIFKeySet(keys, GTModelTypeGeoKey, TYPE_SHORT, 1, ModelTypeProjected);
  GTIFKeySet(keys, GTRasterTypeGeoKey, TYPE_SHORT, 1, RasterPixelIsPoint);
  GTIFKeySet(keys, ProjectedCSTypeGeoKey, TYPE_SHORT, 1, 32633);
  GTIFWriteKeys(keys);
  GTIFFree(keys);
  std::vector<float> row(static_cast<std::size_t>(width));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) row[static_cast<std::size_t>(x)] = static_cast<float>(height_at(x * scale_x, y * scale_y));
    TIFFWriteScanline(tiff, row.data(), static_cast<std::uint32_t>(y), 0);
  }
  XTIFFClose(tiff);
}

/// A round hill 400 m high in a 640 m square, centred.
double hill(double x, double y) {
  const double r = std::hypot(x - 320.0, y - 320.0);
  return 400.0 * std::exp(-r * r / (2.0 * 120.0 * 120.0));
}

TEST(GeotiffCellsCli, RectangularCellsAreResampledWithANoteByEveryReader) {
  TempDir dir("geotiff-cells-rect");
  write_geotiff(dir / "rect.tif", 33, 65, 20.0, 10.0, hill);  // 640 x 640 m in cells 20 m east-west, 10 m north-south
  write_geotiff(dir / "square.tif", 65, 65, 10.0, 10.0, hill);
  {
    std::ofstream lines(dir / "lines.geojson");
    lines << R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{"elev":100},"geometry":{"type":"LineString",)"
          << R"("coordinates":[[1100,-2100],[1500,-2100],[1500,-2500],[1100,-2500],[1100,-2100]]}}]})";
  }
  const std::string note = "not square";
  const CliResult from_dem =
      run_cli({"contour", "--from-dem", (dir / "rect.tif").string(), "--level", "200", "--dem", (dir / "c.tif").string()});
  ASSERT_EQ(from_dem.exit_code, 0) << from_dem.err;
  EXPECT_THAT(from_dem.err, HasSubstr(note));
  const CliResult grid_from = run_cli(
      {"contour-dem", (dir / "lines.geojson").string(), "--grid-from", (dir / "rect.tif").string(), "--dem", (dir / "g.tif").string()});
  ASSERT_EQ(grid_from.exit_code, 0) << grid_from.err;
  EXPECT_THAT(grid_from.err, HasSubstr(note));
  // compare: the real DEM rectangular, the generated one square; only the real one is resampled.
  const CliResult compare = run_cli({"compare", (dir / "rect.tif").string(), (dir / "square.tif").string()});
  ASSERT_EQ(compare.exit_code, 0) << compare.err;
  EXPECT_THAT(compare.err, HasSubstr("rect.tif"));
  EXPECT_THAT(compare.err, HasSubstr(note));
  // A square-celled DEM gets no such note.
  const CliResult square =
      run_cli({"contour", "--from-dem", (dir / "square.tif").string(), "--level", "200", "--dem", (dir / "s.tif").string()});
  ASSERT_EQ(square.exit_code, 0) << square.err;
  EXPECT_THAT(square.err, ::testing::Not(HasSubstr(note)));
}

TEST(GeotiffCellsCli, RotatedGeotiffIsRefusedWithExitTwoAndNoFile) {
  TempDir dir("geotiff-cells-rotated");
  // 10 m cells turned by about 11 degrees: a ModelTransformation with shear terms.
  const double transform[16] = {10.0, 2.0, 0.0, 1000.0, 2.0, -10.0, 0.0, 2000.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0};
  write_geotiff(dir / "rot.tif", 65, 65, 10.0, 10.0, hill, transform);
  std::filesystem::create_directories(dir / "out");
  const auto out = dir / "out";
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"contour", "--from-dem", (dir / "rot.tif").string(), "--level", "200", "--dem", (out / "c.tif").string()},
        std::vector<std::string>{"render", (dir / "rot.tif").string(), "-o", (out / "r.png").string()}}) {
    const CliResult r = run_cli(args);
    expect_rejected(r, "rot.tif", out);
    EXPECT_THAT(r.err, HasSubstr("rotated")) << args[0];
    EXPECT_THAT(r.err, HasSubstr("gdalwarp")) << args[0];
  }
  const CliResult compare =
      run_cli({"compare", (dir / "rot.tif").string(), (dir / "rot.tif").string(), "--json", (out / "c.json").string()});
  expect_rejected(compare, "rotated", out);
}

}  // namespace
}  // namespace sansui::test
