// End-to-end tests of `sansui terrain`: determinism, tiles, and every bad input.
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "io/heightmap_io.hpp"
#include "io/image_io.hpp"
#include "terrain/midpoint.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/test_util.hpp"

namespace sansui::test {
namespace {

std::uint64_t file_hash(const std::filesystem::path& path) {
  const std::string bytes = read_text(path);
  return fnv1a(bytes.data(), bytes.size());
}

TEST(TerrainCli, SameArgumentsGiveIdenticalBytesInEveryFormat) {
  TempDir dir("terrain-determinism");
  // The same file names in two directories (an .obj names its material and texture files).
  for (const char* run : {"a", "b"}) {
    std::filesystem::create_directories(dir / run);
    const std::string stem = (dir / run / "t").string();
    const CliResult r = run_cli({"terrain", "--size", "129", "--seed", "5", "-o", stem + ".png", "-o", stem + ".r32", "-o", stem + ".raw",
                                 "-o", stem + ".tif", "-o", stem + ".obj", "-o", stem + ".glb"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "");  // stderr is not a terminal: no progress bar, nothing extra
  }
  for (const char* file : {"t.png", "t.r32", "t.raw", "t.tif", "t.obj", "t.glb", "t.mtl", "t_basecolor.png"})
    EXPECT_EQ(file_hash(dir / "a" / file), file_hash(dir / "b" / file)) << file;
}

TEST(TerrainCli, OneAndTwoThreadsGiveIdenticalBytes) {
  TempDir dir("terrain-threads");
  ASSERT_EQ(run_cli({"terrain", "--size", "1025", "--threads", "1", "-o", (dir / "one.r32").string()}).exit_code, 0);
  ASSERT_EQ(run_cli({"terrain", "--size", "1025", "--threads", "2", "-o", (dir / "two.r32").string()}).exit_code, 0);
  EXPECT_EQ(file_hash(dir / "one.r32"), file_hash(dir / "two.r32"));
}

TEST(TerrainCli, TilesJoinTheWholeWorldAtTheirSharedBorder) {
  TempDir dir("terrain-tiles");
  ASSERT_EQ(run_cli({"terrain", "--world-size", "257", "--tile", "1,0", "--tile-size", "129", "-o", (dir / "tile.r32").string()}).exit_code,
            0);
  ASSERT_EQ(run_cli({"terrain", "--size", "257", "-o", (dir / "world.r32").string()}).exit_code, 0);
  const Heightfield tile = io::read_heightmap(dir / "tile.r32");
  const Heightfield world = io::read_heightmap(dir / "world.r32");
  ASSERT_EQ(tile.width(), 129);
  for (int y = 0; y < 129; ++y)
    for (int x = 0; x < 129; ++x) ASSERT_EQ(tile(x, y), world(128 + x, y));
  EXPECT_DOUBLE_EQ(tile.origin_x_m, 128 * 10.0);  // metres, default 10 m cells
}

// Tiles agree: the splat map of each of 2 x 2 tiles is the whole world's, cut to the tile, bit
// for bit (the bands are metres, the same on every tile, and the slopes at a tile's border see
// the samples beyond it); eroded tiles agree at their shared border.
TEST(TerrainCli, TilesSplatMapsAreTheWholeWorldsCutToTheTiles) {
  TempDir dir("terrain-tile-splat");
  ASSERT_EQ(run_cli_line("terrain --size 129 --no-erode --splat-map whole.png -o whole.r32", dir.path()).exit_code, 0);
  const Image whole = io::read_png(dir / "whole.png");
  for (int ty = 0; ty < 2; ++ty)
    for (int tx = 0; tx < 2; ++tx) {
      const std::string name = "t" + std::to_string(tx) + std::to_string(ty) + ".png";
      ASSERT_EQ(run_cli_line("terrain --world-size 129 --tile-size 65 --no-erode --tile " + std::to_string(tx) + "," + std::to_string(ty) +
                                 " --splat-map " + name + " -o t.r32",
                             dir.path())
                    .exit_code,
                0);
      const Image tile = io::read_png(dir / name);
      ASSERT_EQ(tile.width(), 65);
      int differing = 0;
      for (int y = 0; y < 65; ++y)
        for (int x = 0; x < 65; ++x) differing += std::memcmp(&tile(x, y), &whole(64 * tx + x, 64 * ty + y), sizeof(Rgba8)) != 0;
      EXPECT_EQ(differing, 0) << name;
    }
  for (const char* tile : {"0,0", "1,0"})
    ASSERT_EQ(
        run_cli_line(std::string("terrain --world-size 257 --tile-size 129 --tile ") + tile + " --splat-map e" + tile[0] + ".png -o e.r32",
                     dir.path())
            .exit_code,
        0);
  const Image west = io::read_png(dir / "e0.png"), east = io::read_png(dir / "e1.png");
  for (int y = 0; y < 129; ++y) ASSERT_EQ(std::memcmp(&west(128, y), &east(0, y), sizeof(Rgba8)), 0) << y;

  // The plants of a tile are the whole world's on the tile, line for line.
  std::ofstream(dir / "whole.toml") << "source = \"midpoint\"\n[world]\nsize = 129\n[[output]]\nfile = \"whole.csv\"\n";
  std::ofstream(dir / "tile.toml") << "source = \"midpoint\"\n[world]\nworld_size = 129\ntile_size = 65\ntile = [1, 1]\n"
                                      "[[output]]\nfile = \"tile.csv\"\n";
  ASSERT_EQ(run_cli_line("run whole.toml", dir.path()).exit_code, 0);
  ASSERT_EQ(run_cli_line("run tile.toml", dir.path()).exit_code, 0);
  const auto rows = [&](const char* file, bool on_tile) {
    std::set<std::string> lines;
    std::istringstream in(read_text(dir / file));
    for (std::string line; std::getline(in, line);) {
      if (line.empty() || line[0] == '#' || line.starts_with("layer")) continue;
      std::istringstream fields(line);
      std::string layer, species, x, y;
      std::getline(fields, layer, ','), std::getline(fields, species, ','), std::getline(fields, x, ','), std::getline(fields, y, ',');
      if (!on_tile || (std::stod(x) >= 640.0 && std::stod(x) <= 1280.0 && std::stod(y) >= 640.0 && std::stod(y) <= 1280.0))
        lines.insert(line);
    }
    return lines;
  };
  const std::set<std::string> tile_plants = rows("tile.csv", false), whole_plants = rows("whole.csv", true);
  EXPECT_GT(tile_plants.size(), 1000u);
  EXPECT_TRUE(tile_plants == whole_plants) << tile_plants.size() << " plants on the tile, " << whole_plants.size()
                                           << " of the whole world's there";
}

TEST(TerrainCli, TilesOfAWorldShareOneSixteenBitRange) {
  TempDir dir("terrain-tile-range");
  for (const char* tile : {"0,0", "1,1"})
    ASSERT_EQ(run_cli({"terrain", "--world-size", "257", "--tile", tile, "--tile-size", "129", "-o",
                       (dir / (std::string("t") + tile[0] + ".png")).string()})
                  .exit_code,
              0);
  const auto sidecar = [&](const char* name) { return nlohmann::json::parse(read_text(io::sidecar_path(dir / name))); };
  const nlohmann::json first = sidecar("t0.png"), second = sidecar("t1.png");
  ASSERT_TRUE(first.contains("range_m"));
  EXPECT_EQ(first["range_m"], second["range_m"]);
  // Sea level - 6 sigma, the sigma of a world 2,560 m across (257 samples 10 m apart).
  EXPECT_DOUBLE_EQ(first["range_m"]["min"].get<double>(), -6 * terrain::default_sigma_for_extent(2560.0, 0.7));
  const Heightfield a = io::read_heightmap(dir / "t0.png"), b = io::read_heightmap(dir / "t1.png");
  EXPECT_EQ(a.width(), 129);
  EXPECT_EQ(b.width(), 129);
}

struct BadInput {
  std::vector<std::string> args;
  std::string message;  // part of the one-line message
};

class TerrainCliBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(TerrainCliBadInput, IsRejectedWithExitTwoAMessageAndNoFile) {
  TempDir dir("terrain-bad");
  std::vector<std::string> args = {"terrain"};
  for (const auto& arg : GetParam().args) args.push_back(arg.starts_with("OUT") ? (dir / "out").string() + arg.substr(3) : arg);
  if (std::ranges::find(GetParam().args, "-o") == GetParam().args.end()) {
    args.push_back("-o");
    args.push_back((dir / "out.png").string());
  }
  expect_rejected(run_cli(args), GetParam().message, dir.path());
}

INSTANTIATE_TEST_SUITE_P(
    Cases, TerrainCliBadInput,
    ::testing::Values(
        BadInput{{"--size", "1000"},
                 "--size 1000 is not allowed: it must be 2^k+1 or an Unreal landscape size (505, 1009, 2017, 4033, 8129...) between 3 and "
                 "16385"},
        BadInput{{"--size", "32769"}, "--size 32769 is not allowed"},
        BadInput{{"--hurst", "0"}, "--hurst 0 is not allowed: it must be > 0 and <= 1"},
        BadInput{{"--hurst", "1.2"}, "--hurst 1.2 is not allowed"}, BadInput{{"--hurst", "nan"}, "--hurst nan is not allowed"},
        BadInput{{"--sigma", "-3"}, "--sigma -3 is not allowed: it must be between 0 and 100000 m"},
        BadInput{{"--sigma", "nan"}, "--sigma nan is not allowed"},
        BadInput{{"--sea-level", "inf"}, "--sea-level inf is not allowed: it must be between -100000 and 100000 m"},
        BadInput{{"--stage", "teenage"}, "--stage 'teenage' is not allowed: it must be one of original, young, mature, old, peneplain"},
        BadInput{{"--world-size", "1025", "--tile", "4,0", "--tile-size", "257"},
                 "world.tile 4,0 is outside the world: tiles go from 0,0 to 3,3"},
        BadInput{{"--world-size", "1025", "--tile", "0", "--tile-size", "257"}, "--tile 0 is not allowed: it must be 2 whole numbers"},
        BadInput{{"--world-size", "1025", "--tile", "0,0", "--tile-size", "300"}, "--tile-size 300 is not allowed"},
        BadInput{{"--size", "65", "--lod", "7"}, "world.lod 7 is not allowed: it must be 0..5"},
        BadInput{{"--range", "5,1"}, "--range 5,1 is not allowed: it must be MIN,MAX with MIN below MAX"},
        BadInput{{"--no-such-option"}, "no-such-option"}, BadInput{{"-o", "/no/such/dir/x.png"}, "directory /no/such/dir does not exist"},
        BadInput{{"-o", "OUT.xyz"}, "unknown extension '.xyz'"}));

TEST(TerrainCli, HelpAndVersionExitZero) {
  const CliResult help = run_cli({"terrain", "--help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--hurst"), std::string::npos);
  EXPECT_NE(help.out.find("[Units: m]"), std::string::npos);
  const CliResult version = run_cli({"--version"});
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_NE(version.out.find("sansui"), std::string::npos);
}

}  // namespace
}  // namespace sansui::test
