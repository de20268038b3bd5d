// Coordinate reference systems through the binary (issue 14 item 3, issue 17 item 7): an
// EPSG:2193 DEM in gives GeoTIFF and GeoJSON out in EPSG:2193; --crs assigns one; a seed in
// longitude/latitude is refused; an unknown or malformed CRS is refused with exit 2 and no file.
// GDAL's own tools, when installed, read the outputs too (the tests skip without them).
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/heightmap_io.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/test_util.hpp"

namespace sansui::test {
namespace {

using ::testing::HasSubstr;

/// A 65 x 65 EPSG:2193 DEM (a hill) written with the project's writer, at a real NZTM position.
std::filesystem::path write_nztm_dem(const TempDir& dir) {
  auto heights = Heightfield::uninitialized(65, 65, 20.0);
  for (int y = 0; y < 65; ++y)
    for (int x = 0; x < 65; ++x) heights(x, y) = static_cast<float>(900.0 - 0.3 * ((x - 32) * (x - 32) + (y - 32) * (y - 32)));
  heights.origin_x_m = 1748000.0;
  heights.origin_y_m = -5431000.0;
  io::HeightmapWriteOptions options;
  options.crs = io::parse_crs("EPSG:2193", "test");
  auto path = dir / "nztm.tif";
  io::write_heightmap(path, heights, options);
  return path;
}

bool have_tool(const char* tool) {
  return std::system((std::string("command -v ") + tool + " > /dev/null 2>&1").c_str()) == 0;
}

TEST(CrsCli, An2193DemGivesGeotiffAndGeojsonIn2193) {
  TempDir dir("crs-cli-carry");
  const auto dem = write_nztm_dem(dir);
  const CliResult r = run_cli({"contour", "--from-dem", dem.string(), "--level", "700", "--dem", (dir / "out.tif").string(), "--contours",
                               (dir / "out.geojson").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto crs = io::read_heightmap_crs(dir / "out.tif");
  ASSERT_TRUE(crs);
  EXPECT_EQ(crs->epsg, 2193);
  const Heightfield out = io::read_heightmap(dir / "out.tif");
  EXPECT_EQ(out.origin_x_m, 1748000.0);  // the DEM's own grid
  EXPECT_EQ(out.origin_y_m, -5431000.0);
  const auto geojson = nlohmann::json::parse(read_text(dir / "out.geojson"));
  EXPECT_EQ(geojson["crs"]["properties"]["name"], "urn:ogc:def:crs:EPSG::2193");
  const auto sidecar = nlohmann::json::parse(read_text(dir / "out.geojson.json"));
  EXPECT_EQ(sidecar["provenance"]["crs"]["epsg"], 2193);
}

/// GDAL's tools are installed by scripts/setup; a machine without them skips, CI fails.
#define REQUIRE_TOOL(tool)                                                                                          \
  do {                                                                                                              \
    if (!have_tool(tool)) {                                                                                         \
      if (std::getenv("CI") != nullptr) FAIL() << (tool) << " is not installed (scripts/setup --test installs it)"; \
      GTEST_SKIP() << (tool) << " is not installed (scripts/setup --test installs it)";                             \
    }                                                                                                               \
  } while (false)

std::string tool_output(const std::string& command, const std::filesystem::path& dir) {
  const auto out = dir / "tool.txt";
  const int status = std::system((command + " > '" + out.string() + "' 2>&1").c_str());
  EXPECT_EQ(status, 0) << command << "\n" << read_text(out);
  return read_text(out);
}

TEST(CrsCli, GdalAndOgrReadTheOutputsAs2193) {
  REQUIRE_TOOL("gdalsrsinfo");
  REQUIRE_TOOL("ogrinfo");
  TempDir dir("crs-cli-gdal");
  const auto dem = write_nztm_dem(dir);
  ASSERT_EQ(run_cli({"contour", "--from-dem", dem.string(), "--level", "700", "--dem", (dir / "out.tif").string(), "--contours",
                     (dir / "out.geojson").string()})
                .exit_code,
            0);
  for (const char* file : {"out.tif", "out.geojson"})
    EXPECT_THAT(tool_output("gdalsrsinfo -o epsg '" + (dir / file).string() + "'", dir.path()), HasSubstr("EPSG:2193")) << file;
  // GDAL puts the DEM where the input DEM was: the corner of its first 20 m cell (half a cell
  // west and north of its first sample, 1748000 E 5431000 N), north up.
  const std::string info = tool_output("gdalinfo '" + (dir / "out.tif").string() + "'", dir.path());
  EXPECT_THAT(info, HasSubstr("Origin = (1747990.0"));
  EXPECT_THAT(info, HasSubstr(",5431010.0"));
  EXPECT_THAT(info, HasSubstr("Pixel Size = (20.0"));
  // OGR reads the contours (closed rings: polygons) in EPSG:2193 with their elevations.
  const std::string layer = tool_output("ogrinfo -ro -al -so '" + (dir / "out.geojson").string() + "'", dir.path());
  EXPECT_THAT(layer, HasSubstr("Geometry: Polygon"));
  EXPECT_THAT(layer, HasSubstr("elevation_m: Real"));
  EXPECT_THAT(layer, ::testing::ContainsRegex("ID\\[\"EPSG\",2193\\]"));
  EXPECT_THAT(layer, ::testing::ContainsRegex("Feature Count: [1-9]"));
}

TEST(CrsCli, CrsOptionAssignsTheOutputsCrs) {
  TempDir dir("crs-cli-assign");
  const CliResult r =
      run_cli({"terrain", "--size", "33", "--crs", "EPSG:32633", "-o", (dir / "t.tif").string(), "-o", (dir / "t.glb").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(io::read_heightmap_crs(dir / "t.tif")->epsg, 32633);
  EXPECT_EQ(nlohmann::json::parse(read_text(dir / "t.glb.json"))["provenance"]["crs"]["epsg"], 32633);
  // Without --crs a generated terrain has none.
  ASSERT_EQ(run_cli({"terrain", "--size", "33", "-o", (dir / "local.tif").string()}).exit_code, 0);
  EXPECT_FALSE(io::read_heightmap_crs(dir / "local.tif"));
}

TEST(CrsCli, SeedCrsMemberCarriesToTheOutputs) {
  TempDir dir("crs-cli-seed");
  {
    std::ofstream seed(dir / "seed.geojson");
    seed << R"({"type":"FeatureCollection","crs":{"type":"name","properties":{"name":"urn:ogc:def:crs:EPSG::2193"}},)"
         << R"("features":[{"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":)"
         << R"([[[1748000,5428000],[1749000,5428000],[1749000,5429000],[1748000,5429000],[1748000,5428000]]]}}]})";
  }
  std::filesystem::create_directories(dir / "out");
  const CliResult r = run_cli({"contour", (dir / "seed.geojson").string(), "--dem-size", "65", "--dem", (dir / "out" / "d.tif").string(),
                               "--contours", (dir / "out" / "c.geojson").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(io::read_heightmap_crs(dir / "out" / "d.tif")->epsg, 2193);
  const Heightfield dem = io::read_heightmap(dir / "out" / "d.tif");
  EXPECT_NEAR(dem.origin_x_m, 1748000.0, 600.0);  // the seed's own coordinates (with a margin), not a local origin
  EXPECT_NEAR(-dem.origin_y_m, 5429000.0, 600.0);
  EXPECT_EQ(nlohmann::json::parse(read_text(dir / "out" / "c.geojson"))["crs"]["properties"]["name"], "urn:ogc:def:crs:EPSG::2193");
}

TEST(CrsCli, LonLatSeedIsRefusedUnlessMetresAreForced) {
  TempDir dir("crs-cli-lonlat");
  {
    std::ofstream seed(dir / "ll.geojson");
    seed << R"({"type":"Polygon","coordinates":[[[174.76,-41.29],[174.80,-41.29],[174.80,-41.25],[174.76,-41.25],[174.76,-41.29]]]})";
  }
  std::filesystem::create_directories(dir / "out");
  const CliResult r = run_cli({"contour", (dir / "ll.geojson").string(), "--dem", (dir / "out" / "d.tif").string()});
  expect_rejected(r, "ll.geojson: it has no crs member and every coordinate lies within longitude/latitude bounds", dir / "out");
  EXPECT_THAT(r.err, HasSubstr("ogr2ogr -t_srs"));
  EXPECT_THAT(r.err, HasSubstr("--force-metres"));
  const CliResult forced =
      run_cli({"contour", (dir / "ll.geojson").string(), "--force-metres", "--dem-size", "33", "--dem", (dir / "out" / "d.tif").string()});
  EXPECT_EQ(forced.exit_code, 0) << forced.err;
  std::filesystem::remove_all(dir / "out");
  std::filesystem::create_directories(dir / "out");
  {
    std::ofstream seed(dir / "ll.csv");
    seed << "174.76,-41.29\n174.80,-41.29\n174.80,-41.25\n174.76,-41.25\n";
  }
  expect_rejected(run_cli({"contour", (dir / "ll.csv").string(), "--dem", (dir / "out" / "d.tif").string()}),
                  "ll.csv: every coordinate lies within longitude/latitude bounds", dir / "out");
}

TEST(CrsCli, BadCrsIsRefusedWithExitTwoAndNoFile) {
  TempDir dir("crs-cli-bad");
  const auto out = (dir / "out").string();
  std::filesystem::create_directories(dir / "out");
  const std::string tif = (dir / "out" / "t.tif").string();
  expect_rejected(run_cli({"terrain", "--size", "33", "--crs", "EPSG:99999999", "-o", tif}), "--crs 'EPSG:99999999' is not allowed",
                  dir / "out");
  expect_rejected(run_cli({"terrain", "--size", "33", "--crs", "banana", "-o", tif}), "--crs 'banana' is not allowed", dir / "out");
  expect_rejected(run_cli({"terrain", "--size", "33", "--crs", "EPSG:4326", "-o", tif}), "is geographic, in degrees", dir / "out");
  expect_rejected(run_cli({"terrain", "--size", "33", "--crs", "EPSG:2227", "-o", tif}), "not metres", dir / "out");
}

TEST(CrsCli, ContourMapCrsMemberCarriesToTheDem) {
  TempDir dir("crs-cli-contour-map");
  {
    // Three nested square contours, 100 m apart in elevation, as gdal_contour writes them in NZTM.
    std::ofstream map(dir / "lines.geojson");
    map << R"({"type":"FeatureCollection","crs":{"type":"name","properties":{"name":"urn:ogc:def:crs:EPSG::2193"}},"features":[)";
    for (int k = 0; k < 3; ++k) {
      const int a = 1000 * k, lo_x = 1748000 + a, hi_x = 1754000 - a, lo_y = 5428000 + a, hi_y = 5434000 - a;
      map << (k > 0 ? "," : "") << R"({"type":"Feature","properties":{"elev":)" << 100 * (k + 1)
          << R"(},"geometry":{"type":"LineString","coordinates":[)"
          << "[" << lo_x << "," << lo_y << "],[" << hi_x << "," << lo_y << "],[" << hi_x << "," << hi_y << "],[" << lo_x << "," << hi_y
          << "],[" << lo_x << "," << lo_y << "]]}}";
    }
    map << "]}";
  }
  std::filesystem::create_directories(dir / "out");
  const CliResult r =
      run_cli({"contour-dem", (dir / "lines.geojson").string(), "--dem-size", "33", "--dem", (dir / "out" / "d.tif").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(io::read_heightmap_crs(dir / "out" / "d.tif")->epsg, 2193);
  EXPECT_NEAR(io::read_heightmap(dir / "out" / "d.tif").origin_x_m, 1748000.0, 1000.0);
}

TEST(CrsCli, GeographicGeojsonCrsMemberIsRefused) {
  TempDir dir("crs-cli-geographic");
  {
    std::ofstream map(dir / "lines.geojson");
    map << R"({"type":"FeatureCollection","crs":{"type":"name","properties":{"name":"urn:ogc:def:crs:OGC:1.3:CRS84"}},"features":[)"
        << R"({"type":"Feature","properties":{"elev":100},"geometry":{"type":"LineString","coordinates":[[174.7,-41.3],[174.8,-41.2]]}}]})";
  }
  std::filesystem::create_directories(dir / "out");
  expect_rejected(run_cli({"contour-dem", (dir / "lines.geojson").string(), "--dem", (dir / "out" / "d.tif").string()}),
                  "lines.geojson: its crs member says OGC:CRS84", dir / "out");
}

}  // namespace
}  // namespace sansui::test

namespace sansui::test {
namespace {

// A world on the map: [world] origin places the terrain, raw files carry an ENVI header GDAL
// opens, GeoJSON without a CRS says "local metres", and lake polygons are valid OGC geometry.
TEST(WorldOnTheMap, OriginAndCrsReachGdalThroughGeotiffAndRawHeaders) {
  REQUIRE_TOOL("gdalinfo");
  TempDir dir("world-on-map");
  for (const char* file : {"t.tif", "t.r32", "t.r16"})
    ASSERT_EQ(
        run_cli_line(std::string("terrain --size 65 --no-erode --crs EPSG:32633 --origin 500000,5200000 -o ") + file, dir.path()).exit_code,
        0)
        << file;
  for (const char* file : {"t.tif", "t.r32", "t.r16"}) {
    const std::string info = tool_output(std::string("gdalinfo '") + (dir / file).string() + "'", dir.path());
    EXPECT_THAT(info, HasSubstr("Size is 65, 65")) << file;
    EXPECT_THAT(info, HasSubstr("Origin = (500000.0")) << file;
    EXPECT_THAT(info, HasSubstr(",5200000.0")) << file;
    EXPECT_THAT(info, HasSubstr("Pixel Size = (10.0")) << file;
    EXPECT_THAT(info, HasSubstr("WGS 84 / UTM zone 33N")) << file;
  }
  // The 16-bit file's levels stand for metres through the header's gain and offset.
  const std::string levels = tool_output("gdalinfo '" + (dir / "t.r16").string() + "'", dir.path());
  EXPECT_THAT(levels, HasSubstr("Offset:"));
  EXPECT_THAT(levels, HasSubstr("Scale:"));
}

TEST(WorldOnTheMap, AnOriginOutsideTheCrsAreaIsRefusedNamingBoth) {
  TempDir dir("world-off-map");
  const CliResult r = run_cli_line("terrain --size 65 --no-erode --crs EPSG:32633 --origin 5000000,5200000 -o t.tif", dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("lies outside the area where EPSG:32633"));
  EXPECT_FALSE(std::filesystem::exists(dir / "t.tif"));
}

// A graph of generated nodes takes [world] origin as the chain does: the same GeoTIFF bytes. A
// graph that reads a positioned input (a file, a drawing) keeps its position and is refused.
TEST(WorldOnTheMap, AGraphOfAMidpointNodeTakesTheOriginAsTheChainDoes) {
  TempDir dir("world-graph-origin");
  const std::string world = "[world]\nsize = 65\ncrs = \"EPSG:32633\"\norigin = [500000, 5200000]\n";
  std::ofstream(dir / "chain.toml") << "sansui_recipe = 4\nsource = \"midpoint\"\n"
                                    << world << "[midpoint]\nseed = 7\n[[output]]\nfile = \"chain.tif\"\n";
  std::ofstream(dir / "graph.toml") << "sansui_recipe = 4\n"
                                    << world << "[[node]]\nid = \"m\"\nkind = \"midpoint\"\nseed = 7\n"
                                    << "[[output]]\nnode = \"m\"\nfile = \"graph.tif\"\n";
  ASSERT_EQ(run_cli_line("run chain.toml --out-dir out", dir.path()).exit_code, 0);
  const CliResult graph = run_cli_line("run graph.toml --out-dir out", dir.path());
  ASSERT_EQ(graph.exit_code, 0) << graph.err;
  EXPECT_EQ(read_text(dir / "out" / "graph.tif"), read_text(dir / "out" / "chain.tif"));
  std::ofstream(dir / "file.toml") << "sansui_recipe = 4\n"
                                   << world << "[[node]]\nid = \"dem\"\nkind = \"file\"\npath = \"out/chain.tif\"\n"
                                   << "[[output]]\nnode = \"dem\"\nfile = \"file.tif\"\n";
  const CliResult refused = run_cli_line("run file.toml --out-dir out", dir.path());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_THAT(refused.err, HasSubstr("keeps its input's position"));
  EXPECT_THAT(refused.err, HasSubstr("file node 'dem'"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "file.tif"));
}

/// Invalid lake polygons in `file`, counted by GDAL's Python bindings (GEOS underneath).
/// The features OGR reads from `file` (in `count`), how many distinct "id" properties they
/// have (in `ids`), and how many geometries are not valid (returned).
int invalid_polygons(const std::filesystem::path& file, const std::filesystem::path& dir, int* count, int* ids = nullptr) {
  const std::string out = tool_output(
      "/usr/bin/python3 -c \"from osgeo import ogr\nimport sys\nds = ogr.Open(sys.argv[1])\nl = ds.GetLayer()\nn = b = 0\ns = set()\n"
      "for f in l:\n  n += 1\n  s.add(f.GetField('id'))\n  b += not f.GetGeometryRef().IsValid()\nprint(n, b, len(s))\" '" +
          file.string() + "' 2>/dev/null",
      dir);
  int bad = -1, distinct = -1;
  std::sscanf(out.c_str(), "%d %d %d", count, &bad, &distinct);
  if (ids != nullptr) *ids = distinct;
  return bad;
}

TEST(WorldOnTheMap, LakesAreValidPolygonsAndLocalMetresAreNotReadAsDegrees) {
  REQUIRE_TOOL("ogrinfo");
  if (std::system("/usr/bin/python3 -c 'import osgeo' > /dev/null 2>&1") != 0) GTEST_SKIP() << "python3-gdal is not installed";
  TempDir dir("world-lakes");
  int lakes = 0;
  for (int seed = 1; seed <= 6; ++seed) {
    const std::string scene = "lakes" + std::to_string(seed);
    std::ofstream(dir / (scene + ".toml")) << "source = \"midpoint\"\n[midpoint]\nseed = " << seed
                                           << "\n[world]\nsize = 257\n[[shape]]\nstep = \"erode\"\n[[output]]\nfile = \"" << scene
                                           << ".geojson\"\nkind = \"lakes\"\n";
    ASSERT_EQ(run_cli_line("run " + scene + ".toml", dir.path()).exit_code, 0) << seed;
    int count = 0, ids = 0;
    EXPECT_EQ(invalid_polygons(dir / (scene + ".geojson"), dir.path(), &count, &ids), 0) << "seed " << seed;
    EXPECT_EQ(count, ids) << "seed " << seed << ": one feature per lake";
    lakes += count;
  }
  EXPECT_GT(lakes, 10);
  const std::string layer = tool_output("ogrinfo -ro -al -so '" + (dir / "lakes1.geojson").string() + "'", dir.path());
  EXPECT_THAT(layer, HasSubstr("ENGCRS[\"Sansui local metres\""));
  EXPECT_THAT(layer, HasSubstr("Geometry: Multi Polygon"));
}

// A world given no CRS names one, "Sansui local metres", in every georeferenced file (version 5):
// GDAL reads the GeoTIFF, the 16-bit PNG's .aux.xml, the ENVI header and the GeoJSON as the same
// CRS, so QGIS lays them over each other; Sansui reads each back as no CRS. A version 4 recipe
// keeps its bytes: the GeoTIFF's old citation, the GeoJSON's named datum.
TEST(WorldOnTheMap, EveryFileOfAWorldWithoutACrsNamesTheSameLocalCrs) {
  REQUIRE_TOOL("ogrinfo");
  if (std::system("/usr/bin/python3 -c 'import osgeo' > /dev/null 2>&1") != 0) GTEST_SKIP() << "python3-gdal is not installed";
  TempDir dir("world-local-crs");
  const std::vector<std::string> files{"h.tif", "h.png", "h.r32", "rivers.geojson"};
  for (const int version : {4, 5}) {
    std::ofstream scene(dir / ("v" + std::to_string(version) + ".toml"));
    scene << "sansui_recipe = " << version << "\nsource = \"midpoint\"\n[world]\nsize = 129\n[[shape]]\nstep = \"erode\"\n";
    for (const std::string& file : files)
      scene << "[[output]]\nfile = \"v" << version << "-" << file << "\"\nkind = \"" << (file == files.back() ? "rivers" : "heightmap")
            << "\"\n";
  }
  for (const char* version : {"v4", "v5"})
    ASSERT_EQ(run_cli_line(std::string("run ") + version + ".toml", dir.path()).exit_code, 0) << version;
  // Each file's CRS as GDAL or OGR reads it, and whether it is the GeoJSON's.
  const std::string same = tool_output("cd '" + dir.path().string() +
                                           "' && /usr/bin/python3 -c \"from osgeo import gdal, ogr\ngdal.UseExceptions()\n"
                                           "v = ogr.Open('v5-rivers.geojson')\nref = v.GetLayer(0).GetSpatialRef()\n"
                                           "for f in ['v5-h.tif', 'v5-h.png', 'v5-h.r32']:\n  d = gdal.Open(f)\n  s = d.GetSpatialRef()\n"
                                           "  print(f, s.GetName() if s else None, bool(s and s.IsSame(ref)))\n\"",
                                       dir.path());
  for (const char* file : {"v5-h.tif", "v5-h.png", "v5-h.r32"})
    EXPECT_THAT(same, HasSubstr(std::string(file) + " Sansui local metres True")) << same;
  for (const char* file : {"v5-h.tif", "v5-h.r32"}) EXPECT_FALSE(io::read_heightmap_crs(dir / file)) << file;
  EXPECT_FALSE(nlohmann::json::parse(read_text(dir / "v5-h.tif.json"))["provenance"].contains("crs"));
  // Version 4 as it was.
  EXPECT_THAT(tool_output("gdalinfo '" + (dir / "v4-h.tif").string() + "'", dir.path()), HasSubstr("Sansui local grid in metres"));
  EXPECT_THAT(read_text(dir / "v4-rivers.geojson"), HasSubstr("EDATUM[\\\"Sansui world\\\"]"));
  EXPECT_THAT(read_text(dir / "v5-rivers.geojson"), HasSubstr("EDATUM[\\\"\\\"]"));
}

// DEMs in the formats GIS tools write are read through GDAL, with their position and CRS; NoData
// cells are filled from their nearest valid sample, with a note.
TEST(WorldOnTheMap, DemsInAscHgtAndVrtFormAreReadThroughGdal) {
  REQUIRE_TOOL("gdal_translate");
  TempDir dir("world-gdal-input");
  ASSERT_EQ(run_cli_line("terrain --size 65 --no-erode --crs EPSG:32633 --origin 500000,5200000 -o t.tif", dir.path()).exit_code, 0);
  const Heightfield original = io::read_heightmap(dir / "t.tif");
  const std::string in_dir = "cd '" + dir.path().string() + "' && ";
  tool_output(in_dir + "gdal_translate -q -of AAIGrid t.tif t.asc && gdal_translate -q -of VRT t.tif t.vrt", dir.path());
  for (const char* file : {"t.asc", "t.vrt"}) {
    const Heightfield read = io::read_heightmap(dir / file);
    EXPECT_EQ(read.width(), 65) << file;
    EXPECT_EQ(read.cell_size_m, 10.0) << file;
    EXPECT_EQ(read.origin_x_m, original.origin_x_m) << file;
    EXPECT_EQ(read.origin_y_m, original.origin_y_m) << file;
    EXPECT_NEAR(read(30, 40), original(30, 40), 1e-3f) << file;
    const auto crs = io::read_heightmap_crs(dir / file);
    ASSERT_TRUE(crs) << file;
    EXPECT_EQ(crs->epsg, 32633) << file;
  }
  // SRTM HGT: geographic, read as a local grid in metres at its latitude, with a note.
  tool_output(in_dir +
                  "gdal_translate -q -of SRTMHGT -a_srs EPSG:4326 -a_ullr 14.99958333 47.00041667 16.00041667 45.99958333 -outsize 1201 "
                  "1201 -ot Int16 t.tif N46E015.hgt",
              dir.path());
  std::ofstream(dir / "hgt.toml") << "source = \"file\"\n[file]\npath = \"N46E015.hgt\"\n[[output]]\nfile = \"h.r32\"\n";
  const CliResult hgt = run_cli_line("run hgt.toml", dir.path());
  ASSERT_EQ(hgt.exit_code, 0) << hgt.err;
  EXPECT_THAT(hgt.err, HasSubstr("N46E015.hgt: in degrees"));
  EXPECT_TRUE(std::filesystem::exists(dir / "h.r32"));
  // A GeoTIFF with NoData: filled, with a note saying how many.
  tool_output(in_dir + "gdal_translate -q -a_nodata 0 -scale 0 1 0 1 t.tif nd.tif", dir.path());
  std::ofstream(dir / "nd.toml") << "source = \"file\"\n[file]\npath = \"nd.tif\"\n[[output]]\nfile = \"nd.r32\"\n";
  const CliResult no_data = run_cli_line("run nd.toml", dir.path());
  ASSERT_EQ(no_data.exit_code, 0) << no_data.err;
  EXPECT_THAT(no_data.err, ::testing::ContainsRegex("nd.tif: [0-9]+ of 4225 samples \\([0-9.]+ %\\) were NoData"));
  // Not a raster: one line, exit 2, no file.
  std::ofstream(dir / "bad.asc") << "this is not a grid\n";
  const CliResult bad = run_cli_line("render bad.asc -o bad.png", dir.path());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_THAT(bad.err, HasSubstr("GDAL cannot open it as a raster"));
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.png"));
}

}  // namespace
}  // namespace sansui::test
