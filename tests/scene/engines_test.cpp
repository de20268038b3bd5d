// Engine presets (heightmap_output.engine, issue 14 item 4): the sizes each engine takes, Unreal
// landscape sizes as windows of a 2^k+1 world whose tiles share their borders bit for bit, and
// the Z scale and location the sidecar records bringing the 16-bit levels back to metres.
#include "scene/engines.hpp"

#include <cstring>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/cli_runner.hpp"
#include "io/heightmap_io.hpp"
#include "test_util.hpp"

namespace sansui {
namespace {

using ::testing::HasSubstr;

nlohmann::json sidecar_of(const std::filesystem::path& file) {
  std::ifstream in(io::sidecar_path(file));
  return nlohmann::json::parse(in);
}

std::vector<std::uint16_t> levels_of(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::uint16_t> levels(bytes.size() / 2);
  for (std::size_t i = 0; i < levels.size(); ++i) levels[i] = static_cast<std::uint16_t>(bytes[2 * i] | bytes[2 * i + 1] << 8);
  return levels;
}

TEST(Engines, SizesEachEngineTakes) {
  using scene::Engine;
  for (long long n : {127, 253, 505, 1009, 2017, 4033, 8129}) {
    EXPECT_TRUE(scene::is_unreal_landscape_size(n)) << n;
    EXPECT_EQ(scene::engine_size_problem(Engine::unreal, n, n), "") << n;
  }
  for (long long n : {1025, 1000, 4097, 513, 2}) EXPECT_FALSE(scene::is_unreal_landscape_size(n)) << n;
  EXPECT_THAT(scene::engine_size_problem(Engine::unreal, 1025, 1025), HasSubstr("505, 1009"));
  EXPECT_EQ(scene::engine_size_problem(Engine::unity, 513, 513), "");
  EXPECT_EQ(scene::engine_size_problem(Engine::unity, 4097, 4097), "");
  EXPECT_NE(scene::engine_size_problem(Engine::unity, 8193, 8193), "");
  EXPECT_NE(scene::engine_size_problem(Engine::unity, 1009, 1009), "");
  EXPECT_NE(scene::engine_size_problem(Engine::unity, 513, 257), "");
  EXPECT_EQ(scene::engine_size_problem(Engine::godot, 1025, 1025), "");
  EXPECT_NE(scene::engine_size_problem(Engine::godot, 33, 33), "");
  EXPECT_EQ(scene::engine_size_problem(Engine::none, 7, 1000), "");
}

TEST(Engines, AnUnrealSizeIsAWindowOfTheWorldAboveItAndItsTilesShareTheirBordersBitForBit) {
  const test::TempDir dir("engine-unreal-tiles");
  // The whole 505 landscape: samples 0..504 of the 513 world.
  const auto whole = test::run_cli({"terrain", "--size", "505", "--seed", "3", "-o", (dir / "whole.r32").string()});
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  const auto world = test::run_cli({"terrain", "--size", "513", "--seed", "3", "-o", (dir / "world.r32").string()});
  ASSERT_EQ(world.exit_code, 0) << world.err;
  const Heightfield w505 = io::read_heightmap(dir / "whole.r32"), w513 = io::read_heightmap(dir / "world.r32");
  ASSERT_EQ(w505.width(), 505);
  for (int y = 0; y < 505; ++y)
    for (int x = 0; x < 505; ++x) ASSERT_EQ(std::memcmp(&w505(x, y), &w513(x, y), sizeof(float)), 0) << x << "," << y;

  // 2x2 tiles of 253 of the 505 landscape, as Unreal's .r16 with the preset: every tile the same
  // 16-bit range (so the same Z scale), shared borders the same levels, and each the window.
  std::vector<std::uint16_t> mosaic(505 * 505, 0);
  std::vector<bool> seen(505 * 505, false);
  double scale_z = 0.0;
  for (int ty = 0; ty < 2; ++ty)
    for (int tx = 0; tx < 2; ++tx) {
      const auto file = dir / ("tile_x" + std::to_string(tx) + "_y" + std::to_string(ty) + ".r16");
      const auto run =
          test::run_cli({"terrain", "--world-size", "505", "--tile-size", "253", "--tile", std::to_string(tx) + "," + std::to_string(ty),
                         "--seed", "3", "--engine", "unreal", "-o", file.string()});
      ASSERT_EQ(run.exit_code, 0) << run.err;
      EXPECT_THAT(run.all(), HasSubstr("Unreal: import"));
      const nlohmann::json engine = sidecar_of(file).at("engine");
      if (scale_z == 0.0) scale_z = engine.at("/scale/z"_json_pointer).get<double>();
      EXPECT_EQ(engine.at("/scale/z"_json_pointer).get<double>(), scale_z);
      EXPECT_DOUBLE_EQ(engine.at("/location_cm/x"_json_pointer).get<double>(), tx * 252 * 10.0 * 100.0);
      EXPECT_DOUBLE_EQ(engine.at("/location_cm/y"_json_pointer).get<double>(), ty * 252 * 10.0 * 100.0);
      const std::vector<std::uint16_t> tile = levels_of(file);
      ASSERT_EQ(tile.size(), 253u * 253u);
      for (int y = 0; y < 253; ++y)
        for (int x = 0; x < 253; ++x) {
          const std::size_t at = static_cast<std::size_t>(ty * 252 + y) * 505 + tx * 252 + x;
          if (seen[at]) {
            ASSERT_EQ(mosaic[at], tile[static_cast<std::size_t>(y) * 253 + x]) << "tile " << tx << "," << ty;
          }
          mosaic[at] = tile[static_cast<std::size_t>(y) * 253 + x];
          seen[at] = true;
        }
    }
}

TEST(Engines, TheRecordedZScaleAndLocationGiveTheMetresBack) {
  const test::TempDir dir("engine-unreal-scale");
  const auto file = dir / "land.r16";
  const auto run = test::run_cli({"terrain", "--size", "1009", "--seed", "9", "--sigma", "300", "--cell", "2", "--engine", "unreal", "-o",
                                  file.string(), "-o", (dir / "land.r32").string()});
  // .r32 is not an Unreal format
  ASSERT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("land.r32"));
  EXPECT_FALSE(std::filesystem::exists(file));

  const auto ok = test::run_cli(
      {"terrain", "--size", "1009", "--seed", "9", "--sigma", "300", "--cell", "2", "--engine", "unreal", "-o", file.string()});
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  const auto metres_run =
      test::run_cli({"terrain", "--size", "1009", "--seed", "9", "--sigma", "300", "--cell", "2", "-o", (dir / "land.r32").string()});
  ASSERT_EQ(metres_run.exit_code, 0) << metres_run.err;
  const Heightfield metres = io::read_heightmap(dir / "land.r32");
  const nlohmann::json sidecar = sidecar_of(file);
  const nlohmann::json& engine = sidecar.at("engine");
  const double scale_z = engine.at("/scale/z"_json_pointer).get<double>();
  const double location_z = engine.at("/location_cm/z"_json_pointer).get<double>();
  EXPECT_DOUBLE_EQ(engine.at("/scale/x"_json_pointer).get<double>(), 200.0);  // 2 m cells in cm
  const double relief = sidecar.at("/range_m/max"_json_pointer).get<double>() - sidecar.at("/range_m/min"_json_pointer).get<double>();
  EXPECT_NEAR(scale_z, relief * 100.0 / 512.0, relief * 100.0 / 512.0 * 1e-4);  // the usual rule, to 1 part in 65536
  const std::vector<std::uint16_t> levels = levels_of(file);
  ASSERT_EQ(levels.size(), 1009u * 1009u);
  const double quantum_m = relief / 65535.0;
  double worst = 0.0;
  for (int y = 0; y < 1009; ++y)
    for (int x = 0; x < 1009; ++x) {
      // Unreal: height_cm = location.z + (level - 32768) * scale.z / 128
      const double unreal_m = (location_z + (levels[static_cast<std::size_t>(y) * 1009 + x] - 32768.0) * scale_z / 128.0) / 100.0;
      worst = std::max(worst, std::abs(unreal_m - metres(x, y)));
    }
  EXPECT_LE(worst, 0.5 * quantum_m + 1e-6 * relief);
}

TEST(Engines, ImpossibleSizesAndFormatsAreRefusedWithNothingWritten) {
  const test::TempDir dir("engine-refused");
  const auto unity = test::run_cli({"terrain", "--size", "1009", "--engine", "unity", "-o", (dir / "t.raw").string()});
  EXPECT_EQ(unity.exit_code, 2);
  EXPECT_THAT(unity.err, HasSubstr("1009x1009"));
  EXPECT_THAT(unity.err, HasSubstr("2^k+1"));
  const auto unreal = test::run_cli({"terrain", "--size", "1025", "--engine", "unreal", "-o", (dir / "t.r16").string()});
  EXPECT_EQ(unreal.exit_code, 2);
  EXPECT_THAT(unreal.err, HasSubstr("505, 1009"));
  const auto size = test::run_cli({"terrain", "--size", "1000", "-o", (dir / "t.r16").string()});
  EXPECT_EQ(size.exit_code, 2);
  EXPECT_THAT(size.err, HasSubstr("1000"));
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(Engines, UnityGetsTheSouthRowFirstAndItsTerrainSize) {
  const test::TempDir dir("engine-unity");
  const auto file = dir / "t.raw";
  const auto run = test::run_cli({"terrain", "--size", "65", "--seed", "4", "--cell", "5", "--engine", "unity", "-o", file.string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.all(), HasSubstr("Unity: Import Raw"));
  const nlohmann::json sidecar = sidecar_of(file);
  EXPECT_THAT(sidecar.at("/format/row_order"_json_pointer).get<std::string>(), HasSubstr("south"));
  EXPECT_DOUBLE_EQ(sidecar.at("/engine/terrain_size_m/x"_json_pointer).get<double>(), 320.0);
  EXPECT_EQ(sidecar.at("/engine/heightmap_resolution"_json_pointer).get<int>(), 65);
}

}  // namespace
}  // namespace sansui
