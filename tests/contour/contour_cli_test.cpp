// End-to-end tests of `sansui contour` and `sansui compare`: outputs, determinism, bad input.
#include <algorithm>
#include <cmath>
#include <fstream>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/heightmap_io.hpp"
#include "scene/contour_geojson.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/test_paths.hpp"
#include "tests/test_util.hpp"

namespace sansui::test {
namespace {

const std::string examples = std::string(sansui::test::source_dir) + "/examples/";

std::uint64_t file_hash(const std::filesystem::path& path) {
  const std::string bytes = read_text(path);
  return fnv1a(bytes.data(), bytes.size());
}

/// The features of a GeoJSON written by sansui, without the provenance (which names the command).
std::string features_of(const std::filesystem::path& path) {
  return nlohmann::json::parse(read_text(path))["features"].dump();
}

TEST(ContourCli, WritesContoursMapsAndDem) {
  TempDir dir("contour-outputs");
  const CliResult r = run_cli({"contour", examples + "contours/ridge.geojson", "--offset", "20", "--contours",
                               (dir / "ridge.geojson").string(), "--map", (dir / "ridge.svg").string(), "--map",
                               (dir / "ridge.png").string(), "--dem", (dir / "ridge.r32").string(), "--dem-size", "257"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("contours on levels 0.."), std::string::npos) << r.out;
  const contour::ContourTree tree = scene::contours_from_geojson(read_text(dir / "ridge.geojson"), "ridge");
  EXPECT_GT(tree.nodes.size(), 10u);
  EXPECT_NE(read_text(dir / "ridge.svg").find("<svg"), std::string::npos);
  EXPECT_EQ(read_text(dir / "ridge.png").substr(1, 3), "PNG");
  const Heightfield dem = io::read_heightmap(dir / "ridge.r32");
  EXPECT_EQ(std::max(dem.width(), dem.height()), 257);
}

TEST(ContourCli, SameArgumentsAndAnyThreadCountGiveIdenticalBytes) {
  TempDir dir("contour-determinism");
  for (const char* threads : {"1", "2"}) {
    const std::string stem = (dir / threads).string();
    // A varied offset (issue 17 item 2) too: the field is a pure function of the seed.
    std::vector<std::string> args{"--threads", threads, "contour", examples + "contours/neck.geojson", "--offset", "15", "--outward", "2"};
    args.insert(args.end(), {"--offset-variation", "0.6", "--contours", stem + ".geojson", "--dem", stem + ".r32", "--dem-size", "300"});
    args.insert(args.end(), {"--dem-noise", "3", "--map", stem + ".png"});
    const CliResult r = run_cli(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  EXPECT_EQ(features_of(dir / "1.geojson"), features_of(dir / "2.geojson"));
  EXPECT_EQ(file_hash(dir / "1.r32"), file_hash(dir / "2.r32"));
  EXPECT_EQ(file_hash(dir / "1.png"), file_hash(dir / "2.png"));
}

TEST(ContourCli, CraterAndFoothillsGiveIdenticalBytesWithAnyThreadCount) {
  TempDir dir("contour-crater");
  for (const char* threads : {"1", "2"}) {
    const std::string stem = (dir / threads).string();
    const CliResult r =
        run_cli({"--threads", threads, "contour", examples + "contours/ridge.geojson", "--offset", "20", "--crater-depth", "25", "--base",
                 "-33", "--dem-surround", "foothills", "--contours", stem + ".geojson", "--dem", stem + ".r32", "--dem-size", "300"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  EXPECT_EQ(features_of(dir / "1.geojson"), features_of(dir / "2.geojson"));
  EXPECT_EQ(file_hash(dir / "1.r32"), file_hash(dir / "2.r32"));
  const contour::ContourTree tree = scene::contours_from_geojson(read_text(dir / "1.geojson"), "crater");
  double lowest = INFINITY;
  for (const auto& node : tree.nodes) lowest = std::min(lowest, node.elevation_m);
  EXPECT_EQ(lowest, -33.0);  // --base reached exactly
}

TEST(ContourCli, EverySeedFormatAndMethodRuns) {
  TempDir dir("contour-formats");
  for (const auto& [seed, extra] : std::vector<std::pair<std::string, std::string>>{
           {"contours/ridge.geojson", "simple"}, {"contours/c_shape.csv", "midpoint"}, {"contours/neck.svg", "fourier"}}) {
    std::vector<std::string> args{
        "contour", examples + seed, "--method", extra, "--offset", "25", "--contours", (dir / "out.geojson").string()};
    if (seed.ends_with(".svg")) args.insert(args.end(), {"--scale", "10"});
    const CliResult r = run_cli(args);
    EXPECT_EQ(r.exit_code, 0) << seed << ": " << r.err;
  }
}

TEST(ContourCli, RegeneratesTheRealDemAndComparesIt) {
  TempDir dir("contour-real");
  const std::string real = examples + "dem/jacksboro_ridge.tif";
  const CliResult r = run_cli(
      {"contour", "--from-dem", real, "--level", "800", "--contours", (dir / "m.geojson").string(), "--dem", (dir / "m.tif").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("from the DEM's mean slope"), std::string::npos) << r.err;
  const CliResult c =
      run_cli({"compare", real, (dir / "m.tif").string(), "--inside", (dir / "m.geojson").string(), "--json", (dir / "c.json").string()});
  ASSERT_EQ(c.exit_code, 0) << c.err;
  for (const char* metric : {"hypsometric curve difference", "slope histogram distance", "slope spread", "summits",
                             "contour length per level", "contour power spectrum slope", "DEM power spectrum slope"})
    EXPECT_NE(c.out.find(metric), std::string::npos) << metric << "\n" << c.out;
  const auto json = nlohmann::json::parse(read_text(dir / "c.json"));
  EXPECT_LT(json["hypsometric_difference"].get<double>(), 0.2);
  EXPECT_GT(json["length_ratio"].get<double>(), 0.5);
}

/// Level-0 contours (seeds) of a contour GeoJSON written by sansui, and the highest elevation.
std::pair<int, double> seeds_and_top(const std::filesystem::path& path) {
  const contour::ContourTree tree = scene::contours_from_geojson(read_text(path), path.string());
  int seeds = 0;
  double top = -INFINITY;
  for (const auto& node : tree.nodes) seeds += node.level == 0 ? 1 : 0, top = std::max(top, node.elevation_m);
  return {seeds, top};
}

// Issue 17 item 6: every polygon of a multi-feature seed file is a mountain of its own (never
// silently only the first), said in a note; overlapping ones are refused.
TEST(ContourCli, EveryPolygonOfAMultiFeatureSeedIsAMountain) {
  TempDir dir("contour-multi");
  const auto square_at = [](int x, int y, int side) {
    return fmt::format("[[{0},{1}],[{2},{1}],[{2},{3}],[{0},{3}],[{0},{1}]]", x, y, x + side, y + side);
  };
  {
    std::ofstream(dir / "multi.geojson") << R"({"type":"MultiPolygon","coordinates":[[)" << square_at(0, 0, 200) << "],["
                                         << square_at(400, 0, 120) << "]]}";
    std::ofstream(dir / "two.geojson") << R"({"type":"FeatureCollection","features":[)"
                                       << R"({"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[)"
                                       << square_at(0, 0, 200) << "]}},"
                                       << R"({"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[)"
                                       << square_at(0, 300, 200) << "]}}]}";
    std::ofstream(dir / "two.svg") << R"(<svg xmlns="http://www.w3.org/2000/svg"><path d="M0,0 h200 v200 h-200 z"/>)"
                                   << R"(<path d="M300,0 h150 v150 h-150 z"/></svg>)";
    std::ofstream(dir / "overlap.geojson") << R"({"type":"MultiPolygon","coordinates":[[)" << square_at(0, 0, 200) << "],["
                                           << square_at(100, 100, 200) << "]]}";
  }
  for (const char* name : {"multi.geojson", "two.geojson", "two.svg"}) {
    const std::string stem = (dir / name).string();
    const CliResult r = run_cli({"contour", stem, "--offset", "10", "--base", "-30", "--dem-size", "129", "--dem-surround", "flat",
                                 "--contours", stem + ".out.geojson", "--dem", stem + ".r32"});
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
    EXPECT_NE(r.err.find("2 seed contours: one mountain from each"), std::string::npos) << name << ": " << r.err;
    const auto [seeds, top] = seeds_and_top(stem + ".out.geojson");
    EXPECT_EQ(seeds, 2) << name;
    // Both mountains are in the DEM: the highest cell of each half rises above the seeds' level.
    const Heightfield dem = io::read_heightmap(stem + ".r32");
    const bool side_by_side = std::string(name) != "two.geojson";
    double first = -INFINITY, second = -INFINITY;
    for (int j = 0; j < dem.height(); ++j)
      for (int i = 0; i < dem.width(); ++i) {
        const bool in_first = side_by_side ? i < dem.width() / 2 : j > dem.height() / 2;  // row 0 is north
        (in_first ? first : second) = std::max(in_first ? first : second, static_cast<double>(dem(i, j)));
      }
    EXPECT_GT(first, 30.0) << name;
    EXPECT_GT(second, 30.0) << name;
    EXPECT_LE(std::max(first, second), top + 10.0) << name;
  }
  std::filesystem::create_directories(dir / "out");
  expect_rejected(run_cli({"contour", (dir / "overlap.geojson").string(), "--offset", "10", "--dem", (dir / "out" / "d.tif").string()}),
                  "seed contours 1 and 2 of 2 overlap", dir / "out");
}

struct BadInput {
  std::vector<std::string> args;
  std::string message;
  std::string seed_text;  // written to SEED.csv when non-empty
};

class ContourCliBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(ContourCliBadInput, IsRejectedWithExitTwoAMessageAndNoFile) {
  TempDir dir("contour-bad");
  TempDir inputs("contour-bad-inputs");
  std::vector<std::string> args;
  const std::string seed_file = (inputs / "seed.csv").string();
  if (!GetParam().seed_text.empty()) {
    std::ofstream(seed_file) << GetParam().seed_text;
  }
  for (const auto& arg : GetParam().args) {
    if (arg == "SEED")
      args.push_back(seed_file);
    else if (arg.starts_with("EX/"))
      args.push_back(examples + arg.substr(3));
    else if (arg.starts_with("OUT"))
      args.push_back((dir / "out").string() + arg.substr(3));
    else
      args.push_back(arg);
  }
  expect_rejected(run_cli(args), GetParam().message, dir.path());
}

const std::string square = "0,0\n100,0\n100,100\n0,100\n";

INSTANTIATE_TEST_SUITE_P(
    Cases, ContourCliBadInput,
    ::testing::Values(
        BadInput{{"contour", "SEED", "--contours", "OUT.geojson"}, "crosses itself at (50, 50)", "0,0\n100,100\n100,0\n0,100\n"},
        BadInput{{"contour", "SEED", "--contours", "OUT.geojson"}, "has 2 distinct vertices", "0,0\n100,0\n"},
        BadInput{{"contour", "SEED", "--contours", "OUT.geojson"}, "zero area", "0,0\n50,50\n100,100\n"},
        BadInput{{"contour", "SEED", "--contours", "OUT.geojson"}, "vertex 1 is (nan, 0)", "0,0\nnan,0\n100,100\n"},
        BadInput{{"contour", "SEED", "--contours", "OUT.geojson"}, "vertex 2 is (inf, 100)", "0,0\n100,0\ninf,100\n"},
        BadInput{{"contour", "SEED", "--offset", "0", "--contours", "OUT.geojson"},
                 "--offset 0 is not allowed: it must be > 0 and <= 10000000 m",
                 square},
        BadInput{{"contour", "SEED", "--offset", "-5", "--contours", "OUT.geojson"}, "--offset -5 is not allowed", square},
        BadInput{{"contour", "SEED", "--interval", "0", "--contours", "OUT.geojson"}, "--interval 0 is not allowed", square},
        BadInput{{"contour", "SEED", "--theta", "10,90", "--contours", "OUT.geojson"},
                 "--theta 10,90 is not allowed: it must be 2 numbers, each >= 0 and < 90 deg",
                 square},
        BadInput{{"contour", "SEED", "--theta", "-1,20", "--contours", "OUT.geojson"}, "--theta -1,20 is not allowed", square},
        BadInput{{"contour", "SEED", "--f0", "513", "--contours", "OUT.geojson"},
                 "contour.f0 513 is not allowed: it must lie in 0..n/2 = 512",
                 square},
        BadInput{{"contour", "SEED", "--n", "1000", "--contours", "OUT.geojson"},
                 "--n 1000 is not allowed: it must be a power of two from 8 to 65536",
                 square},
        BadInput{{"contour", "SEED", "--method", "magic", "--contours", "OUT.geojson"},
                 "--method 'magic' is not allowed: it must be one of simple, midpoint, fourier, revised",
                 square},
        BadInput{{"contour", "SEED", "--join", "round", "--contours", "OUT.geojson"}, "--join 'round' is not allowed", square},
        BadInput{{"contour", "SEED", "--map", "OUT.jpg"}, "has the extension '.jpg': allowed are .svg .png", square},
        BadInput{{"contour", "SEED", "--dem", "OUT.exr"}, "has the extension '.exr'", square},
        BadInput{{"contour", "SEED"}, "no output", square},
        BadInput{
            {"contour", "SEED", "--offset-variation", "1", "--contours", "OUT.geojson"}, "--offset-variation 1 is not allowed", square},
        BadInput{{"contour", "SEED", "--offset-hurst", "0", "--contours", "OUT.geojson"}, "--offset-hurst 0 is not allowed", square},
        BadInput{{"contour", "SEED", "--offset", "1", "--contours", "OUT.geojson"},
                 "contour.offset 1 m would make about 50000 levels",
                 "0,0\n100000,0\n100000,100000\n0,100000\n"},
        BadInput{{"contour", "SEED", "--contours", "/no/such/dir/x.geojson"}, "/no/such/dir", square},
        BadInput{{"contour", "SEED", "--crater-depth", "0", "--contours", "OUT.geojson", "--dem", "OUT.tif"},
                 "--crater-depth 0 is not allowed: it must be > 0 and <= 100000 m",
                 square},
        BadInput{{"contour", "SEED", "--crater-depth", "-5", "--contours", "OUT.geojson"}, "--crater-depth -5 is not allowed", square},
        BadInput{{"contour", "SEED", "--offset", "5", "--crater-depth", "5000", "--contours", "OUT.geojson", "--dem", "OUT.tif"},
                 "contour.crater_depth 5000 m is not allowed: the crater's floor would be at",
                 square},
        BadInput{{"contour", "SEED", "--col-depth", "-5", "--contours", "OUT.geojson"}, "--col-depth -5 is not allowed", square},
        BadInput{{"contour", "SEED", "--offset", "5", "--base", "-20", "--crater-depth", "200", "--contours", "OUT.geojson"},
                 "below the map's base -20 m",
                 square},
        BadInput{{"contour", "SEED", "--crater-width", "1", "--contours", "OUT.geojson"}, "--crater-width 1 is not allowed", square},
        BadInput{{"contour", "SEED", "--crater-floor", "0", "--contours", "OUT.geojson"}, "--crater-floor 0 is not allowed", square},
        BadInput{{"contour", "SEED", "--dem-surround", "hills", "--dem", "OUT.tif"},
                 "--dem-surround 'hills' is not allowed: it must be one of flat, foothills",
                 square},
        BadInput{{"contour", "SEED", "--dem-foothill-relief", "-1", "--dem", "OUT.tif"}, "--dem-foothill-relief -1 is not allowed", square},
        BadInput{{"contour", "EX/contours/missing.geojson", "--contours", "OUT.geojson"}, "cannot read", ""},
        BadInput{{"contour", "--from-dem", "EX/dem/jacksboro_ridge.tif", "--level", "2000", "--contours", "OUT.geojson"},
                 "--level 2000 is outside the DEM's range",
                 ""},
        BadInput{{"contour", "--from-dem", "EX/dem/jacksboro_ridge.tif", "--level", "800", "--pick", "1,1", "--contours", "OUT.geojson"},
                 "--pick 1,1 lies outside every contour at level 800",
                 ""},
        BadInput{{"contour", "--from-dem", "EX/dem/jacksboro_ridge.tif", "--contours", "OUT.geojson"},
                 "contour_seed.from_dem needs contour_seed.level",
                 ""},
        BadInput{{"compare", "EX/dem/jacksboro_ridge.tif", "EX/dem/missing.tif"}, "missing.tif", ""}));

}  // namespace
}  // namespace sansui::test
