// Erosion through the pipeline: `sansui terrain --erode` and its water outputs, end to end.
#include <cmath>
#include <filesystem>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/cli_runner.hpp"
#include "io/heightmap_io.hpp"
#include "test_util.hpp"
#include "water/flow.hpp"
#include "water/priority_flood.hpp"

namespace sansui {
namespace {

using ::testing::HasSubstr;

TEST(ErosionCli, ErodedTerrainDrainsAndItsWaterOutputsAreWritten) {
  const test::TempDir dir("erosion-cli");
  const auto file = [&](const char* name) { return (dir / name).string(); };
  const test::CliResult run = test::run_cli({"terrain",
                                             "--size",
                                             "257",
                                             "--cell",
                                             "20",
                                             "--seed",
                                             "3",
                                             "--erode",
                                             "--stage",
                                             "mature",
                                             "--flow-channel-area",
                                             "1e5",
                                             "-o",
                                             file("eroded.r32"),
                                             "--rivers",
                                             file("rivers.geojson"),
                                             "--lakes",
                                             file("lakes.geojson"),
                                             "--erosion-map",
                                             file("erosion.png"),
                                             "--wetness-map",
                                             file("wetness.png"),
                                             "--water-depth-map",
                                             file("depth.png"),
                                             "--flow-map",
                                             file("flow.png"),
                                             "--deposition-map",
                                             file("deposition.png")});
  ASSERT_EQ(run.exit_code, 0) << run.all();
  const Heightfield eroded = io::read_heightmap(dir / "eroded.r32");
  // Every land cell drains to the sea or the map's edge, through lakes at most: the lake fill
  // adds water only where the lakes output has a lake.
  const water::LakeFill fill = water::fill_depressions_with_lakes(eroded, {0.0});
  const nlohmann::json lakes = nlohmann::json::parse(test::read_text(dir / "lakes.geojson"));
  double lake_area = 0.0;
  for (const auto& lake : lakes.at("features")) lake_area += lake.at("properties").at("area_m2").get<double>();
  std::int64_t flooded = 0;
  for (std::size_t i = 0; i < fill.lake.size(); ++i) flooded += fill.lake.values()[i] != 0 ? 1 : 0;
  EXPECT_LE(lake_area, static_cast<double>(flooded) * 400.0 + 1.0);
  // Rivers: lines downstream with Strahler orders, and discharge growing with order.
  const nlohmann::json rivers = nlohmann::json::parse(test::read_text(dir / "rivers.geojson"));
  ASSERT_FALSE(rivers.at("features").empty());
  for (const auto& river : rivers.at("features")) {
    EXPECT_EQ(river.at("geometry").at("type"), "LineString");
    EXPECT_GE(river.at("geometry").at("coordinates").size(), 2u);
    EXPECT_GE(river.at("properties").at("strahler").get<int>(), 1);
  }
  // The splat maps carry their range in the sidecar, as heightmaps do.
  for (const char* map : {"erosion.png", "wetness.png", "depth.png", "flow.png", "deposition.png"}) {
    ASSERT_TRUE(std::filesystem::exists(dir / map)) << map;
    const nlohmann::json sidecar = nlohmann::json::parse(test::read_text(dir / (std::string(map) + ".json")));
    EXPECT_EQ(sidecar.at("range_m").at("min").get<double>(), 0.0) << map;
  }
  // Same seed, same bytes.
  const test::CliResult again =
      test::run_cli({"terrain", "--size", "257", "--cell", "20", "--seed", "3", "--erode", "--stage", "mature", "-o", file("again.r32")});
  ASSERT_EQ(again.exit_code, 0) << again.all();
  EXPECT_EQ(test::read_text(dir / "again.r32"), test::read_text(dir / "eroded.r32"));
}

TEST(ErosionCli, BadErosionValuesAndMissingStepsAreRefusedWithTheKeyAndNoFile) {
  const test::TempDir dir("erosion-bad");
  const std::string out = (dir / "t.r32").string();
  test::expect_rejected(test::run_cli({"terrain", "--size", "65", "--erode", "--erodibility", "-1", "-o", out}), "erodibility", dir.path());
  test::expect_rejected(test::run_cli({"terrain", "--size", "65", "--erode", "--talus-angle", "nan", "-o", out}), "talus", dir.path());
  test::expect_rejected(test::run_cli({"terrain", "--size", "65", "--erode", "--droplets", "-3", "-o", out}), "droplets", dir.path());
  test::expect_rejected(test::run_cli({"terrain", "--size", "65", "--no-erode", "--erosion-map", (dir / "e.png").string()}),
                        "needs an erode step", dir.path());
  // 1025^2 cells x 12000 steps: about 16 minutes, over the ten-minute limit without --force.
  test::expect_rejected(test::run_cli({"terrain", "--size", "1025", "--erode", "--erosion-steps", "12000", "-o", out}),
                        "would take about 16 minutes", dir.path());
}

}  // namespace
}  // namespace sansui
