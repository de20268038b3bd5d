// Coordinate reference systems (issue 14 item 3, issue 17 item 7): PROJ checks codes and WKT and
// tells geographic from projected; a GeoTIFF written with a CRS carries it in its GeoKeys (read
// back by libgeotiff and by sansui's own reader) and its sidecar; GeoJSON crs members are read,
// and GeoJSON in longitude/latitude is refused; rectangular cells are resampled to square ones
// and rotated georeferencing is refused.
#include "io/crs.hpp"

#include <cmath>
#include <vector>

#include <geotiff.h>
#include <tiffio.h>

#include <geovalues.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <xtiffio.h>

#include "io/geojson_crs.hpp"
#include "io/heightmap_io.hpp"
#include "io/sidecar.hpp"
#include "io/text_file.hpp"
#include "tests/io/io_test_util.hpp"
#include "tests/test_util.hpp"

namespace sansui {
namespace {

using ::testing::HasSubstr;

TEST(Crs, EpsgCodesAreCheckedAndDescribedByProj) {
  const io::Crs nz = io::parse_crs("EPSG:2193", "--crs");
  EXPECT_EQ(nz.epsg, 2193);
  EXPECT_FALSE(nz.geographic);
  EXPECT_TRUE(nz.metric);
  EXPECT_THAT(nz.name, HasSubstr("New Zealand Transverse Mercator"));
  EXPECT_THAT(nz.wkt, HasSubstr("PROJCRS"));
  EXPECT_EQ(io::parse_crs("epsg:2193", "--crs").epsg, 2193);
  EXPECT_EQ(io::parse_crs("urn:ogc:def:crs:EPSG::2193", "--crs").epsg, 2193);

  const io::Crs wgs84 = io::parse_crs("EPSG:4326", "--crs");
  EXPECT_TRUE(wgs84.geographic);
  EXPECT_FALSE(wgs84.metric);
  EXPECT_TRUE(io::parse_crs("OGC:CRS84", "--crs").geographic);
  // A compound CRS (NZTM + NZVD2016 heights): its horizontal part is carried.
  const io::Crs compound = io::parse_crs("EPSG:2193+7839", "--crs");
  EXPECT_EQ(compound.epsg, 2193);
  EXPECT_TRUE(compound.metric);
  const io::Crs feet = io::parse_crs("EPSG:2227", "--crs");
  EXPECT_FALSE(feet.geographic);
  EXPECT_FALSE(feet.metric);
}

TEST(Crs, WktWithoutAnIdIsIdentified) {
  const io::Crs nz = io::parse_crs("EPSG:2193", "--crs");
  std::string wkt = nz.wkt;
  wkt.erase(wkt.rfind(",\n    ID[\"EPSG\",2193]"), std::string::npos);
  wkt += "]";
  const io::Crs again = io::parse_crs(wkt, "--crs");
  EXPECT_EQ(again.epsg, 2193);
  EXPECT_TRUE(again == nz);
}

TEST(Crs, UnknownAndMalformedCrsAreRefusedNamingTheValue) {
  for (const char* text : {"EPSG:99999999", "banana", "EPSG:abc", "", "+proj=utm +zone=33"}) {
    const std::string message = test::message_of([&] { io::parse_crs(text, "--crs"); });
    EXPECT_THAT(message, HasSubstr("--crs")) << text;
    EXPECT_THAT(message, HasSubstr("EPSG:CODE")) << text;
    EXPECT_EQ(message.find('\n'), std::string::npos) << text;
  }
  EXPECT_THAT(test::message_of([] { io::parse_crs("EPSG:5703", "--crs"); }), HasSubstr("not a horizontal"));  // NAVD88 height
  EXPECT_EQ(io::output_crs_problem("EPSG:2193"), "");
  EXPECT_THAT(io::output_crs_problem("EPSG:4326"), HasSubstr("geographic"));
  EXPECT_THAT(io::output_crs_problem("EPSG:2227"), HasSubstr("not metres"));
  EXPECT_THAT(io::output_crs_problem("EPSG:99999999"), HasSubstr("PROJ"));
}

TEST(Crs, GeojsonCrsMemberIsAddedAndRead) {
  const io::Crs nz = io::parse_crs("EPSG:2193", "--crs");
  const std::string text = io::with_geojson_crs(R"({"type":"FeatureCollection","features":[]})", nz);
  const auto root = nlohmann::json::parse(text);
  EXPECT_EQ(root["crs"]["properties"]["name"], "urn:ogc:def:crs:EPSG::2193");
  EXPECT_EQ(root["type"], "FeatureCollection");
  EXPECT_EQ(nlohmann::json::parse(io::with_geojson_crs("{}", nz))["crs"]["type"], "name");
  const auto read = io::geojson_input_crs(text, "t.geojson", false);
  ASSERT_TRUE(read);
  EXPECT_EQ(read->epsg, 2193);
  const auto by_code = io::geojson_input_crs(
      R"({"type":"FeatureCollection","crs":{"type":"EPSG","properties":{"code":2193}},"features":[]})", "t.geojson", false);
  ASSERT_TRUE(by_code);
  EXPECT_EQ(by_code->epsg, 2193);
}

const char* lonlat_seed = R"({"type":"Polygon","coordinates":[[[174.76,-41.29],[174.80,-41.29],[174.80,-41.25],[174.76,-41.29]]]})";

TEST(Crs, GeojsonInDegreesIsRefusedUnlessMetresAreForced) {
  const std::string message = test::message_of([] { io::geojson_input_crs(lonlat_seed, "seed.geojson", false); });
  EXPECT_THAT(message, HasSubstr("seed.geojson"));
  EXPECT_THAT(message, HasSubstr("174.76"));
  EXPECT_THAT(message, HasSubstr("ogr2ogr -t_srs"));
  EXPECT_THAT(message, HasSubstr("--force-metres"));
  EXPECT_FALSE(io::geojson_input_crs(lonlat_seed, "seed.geojson", true));

  const std::string geographic = R"({"type":"FeatureCollection","crs":{"type":"name","properties":{"name":"EPSG:4326"}},"features":[]})";
  EXPECT_THAT(test::message_of([&] { io::geojson_input_crs(geographic, "c.geojson", false); }), HasSubstr("geographic"));
  EXPECT_FALSE(io::geojson_input_crs(geographic, "c.geojson", true));
  const std::string unknown = R"({"type":"FeatureCollection","crs":{"type":"name","properties":{"name":"EPSG:99999999"}},"features":[]})";
  EXPECT_THAT(test::message_of([&] { io::geojson_input_crs(unknown, "c.geojson", true); }), HasSubstr("c.geojson"));

  // Metres: a 1 km seed near the origin, and a small seed far from it, are not degrees.
  EXPECT_FALSE(io::geojson_input_crs(R"({"type":"Polygon","coordinates":[[[0,0],[1000,0],[0,1000],[0,0]]]})", "m.geojson", false));
  EXPECT_FALSE(
      io::geojson_input_crs(R"({"type":"Polygon","coordinates":[[[500000,0],[500001,0],[500000,1],[500000,0]]]})", "m.geojson", false));
}

TEST(Crs, GeotiffCarriesTheEpsgCodeInItsGeoKeysAndSidecar) {
  test::TempDir directory("crs-geotiff");
  Heightfield heights = test::sample_heights(9, 7);
  heights.cell_size_m = 25.0;
  heights.origin_x_m = 1748000.0;
  heights.origin_y_m = -5431000.0;
  io::HeightmapWriteOptions options;
  options.crs = io::parse_crs("EPSG:2193", "--crs");
  io::write_heightmap(directory / "nz.tif", heights, options);

  TIFF* tiff = XTIFFOpen((directory / "nz.tif").c_str(), "r");
  ASSERT_NE(tiff, nullptr);
  GTIF* keys = GTIFNew(tiff);
  unsigned short model = 0, projected = 0;
  EXPECT_EQ(GTIFKeyGetSHORT(keys, GTModelTypeGeoKey, &model, 0, 1), 1);
  EXPECT_EQ(GTIFKeyGetSHORT(keys, ProjectedCSTypeGeoKey, &projected, 0, 1), 1);
  EXPECT_EQ(model, ModelTypeProjected);
  EXPECT_EQ(projected, 2193);
  GTIFFree(keys);
  XTIFFClose(tiff);

  const auto sidecar = nlohmann::json::parse(io::read_text_file(directory / "nz.tif.json"));
  EXPECT_EQ(sidecar["crs"]["epsg"], 2193);
  EXPECT_THAT(sidecar["crs"]["wkt"].get<std::string>(), HasSubstr("PROJCRS"));

  const auto read = io::read_heightmap_crs(directory / "nz.tif");
  ASSERT_TRUE(read);
  EXPECT_EQ(read->epsg, 2193);
  const Heightfield back = io::read_heightmap(directory / "nz.tif");
  EXPECT_EQ(back.origin_x_m, heights.origin_x_m);
  EXPECT_EQ(back.origin_y_m, heights.origin_y_m);

  // Other formats carry it in the sidecar only.
  io::write_heightmap(directory / "nz.r32", heights, options);
  ASSERT_TRUE(io::read_heightmap_crs(directory / "nz.r32"));
  EXPECT_EQ(io::read_heightmap_crs(directory / "nz.r32")->epsg, 2193);
  // Without a CRS: none read back.
  io::write_heightmap(directory / "local.tif", heights);
  EXPECT_FALSE(io::read_heightmap_crs(directory / "local.tif"));
}

TEST(Crs, GeotiffWithoutAnEpsgCodeCarriesItsWkt) {
  test::TempDir directory("crs-wkt");
  const std::string wkt =
      R"(PROJCRS["Local TM",BASEGEOGCRS["WGS 84",DATUM["World Geodetic System 1984",ELLIPSOID["WGS 84",6378137,298.257223563]]],)"
      R"(CONVERSION["TM 7.5E",METHOD["Transverse Mercator"],PARAMETER["Latitude of natural origin",0],)"
      R"(PARAMETER["Longitude of natural origin",7.5],PARAMETER["Scale factor at natural origin",1],)"
      R"(PARAMETER["False easting",100000],PARAMETER["False northing",0]],CS[Cartesian,2],)"
      R"(AXIS["easting",east,LENGTHUNIT["metre",1]],AXIS["northing",north,LENGTHUNIT["metre",1]]])";
  io::HeightmapWriteOptions options;
  options.crs = io::parse_crs(wkt, "--crs");
  ASSERT_EQ(options.crs->epsg, 0);
  io::write_heightmap(directory / "tm.tif", test::sample_heights(5, 5), options);
  const auto read = io::read_heightmap_crs(directory / "tm.tif");
  ASSERT_TRUE(read);
  EXPECT_EQ(read->epsg, 0);
  EXPECT_THAT(read->name, HasSubstr("Local TM"));
}

TEST(Crs, NonMetreCrsIsRefusedForWriting) {
  test::TempDir directory("crs-feet");
  io::HeightmapWriteOptions options;
  options.crs = io::parse_crs("EPSG:2227", "--crs");
  EXPECT_THAT(test::message_of([&] { io::write_heightmap(directory / "f.tif", test::sample_heights(5, 5), options); }),
              HasSubstr("not metres"));
  EXPECT_TRUE(test::files_in(directory.path()).empty());
}

/// A float32 GeoTIFF with the given pixel scale, or with a ModelTransformation if `transform`.
void write_raw_geotiff(const std::filesystem::path& path, int width, int height, double scale_x, double scale_y,
                       const double* transform = nullptr) {
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
    for (int x = 0; x < width; ++x) row[static_cast<std::size_t>(x)] = static_cast<float>(x * scale_x + 2.0 * y * scale_y);  // a plane
    TIFFWriteScanline(tiff, row.data(), static_cast<std::uint32_t>(y), 0);
  }
  XTIFFClose(tiff);
}

TEST(Crs, RectangularCellsAreResampledToSquareOnesWithANote) {
  test::TempDir directory("crs-rectangular");
  write_raw_geotiff(directory / "r.tif", 5, 9, 20.0, 10.0);  // 80 m east-west, 80 m north-south
  io::HeightmapAssumptions assumed;
  const Heightfield heights = io::read_heightmap(directory / "r.tif", {}, &assumed);
  EXPECT_EQ(heights.cell_size_m, 10.0);
  EXPECT_EQ(heights.width(), 9);
  EXPECT_EQ(heights.height(), 9);
  EXPECT_EQ(heights.origin_x_m, 1000.0);
  EXPECT_EQ(heights.origin_y_m, -2000.0);
  for (int y = 0; y < 9; ++y)
    for (int x = 0; x < 9; ++x) EXPECT_NEAR(heights(x, y), x * 10.0 + 2.0 * y * 10.0, 1e-3) << x << "," << y;  // a plane stays one
  ASSERT_EQ(assumed.notes.size(), 1u);
  EXPECT_THAT(assumed.notes[0], HasSubstr("not square"));
  EXPECT_THAT(assumed.notes[0], HasSubstr("5 x 9 to 9 x 9"));
  EXPECT_EQ(io::read_heightmap_crs(directory / "r.tif")->epsg, 32633);
}

TEST(Crs, RotatedGeoreferencingIsRefused) {
  test::TempDir directory("crs-rotated");
  const double transform[16] = {10.0, 2.0, 0.0, 1000.0, 2.0, -10.0, 0.0, 2000.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0};
  write_raw_geotiff(directory / "rot.tif", 4, 4, 10.0, 10.0, transform);
  const std::string message = test::message_of([&] { io::read_heightmap(directory / "rot.tif"); });
  EXPECT_THAT(message, HasSubstr("rot.tif"));
  EXPECT_THAT(message, HasSubstr("rotated"));
  EXPECT_THAT(message, HasSubstr("gdalwarp"));
}

}  // namespace
}  // namespace sansui
