// The JSON sidecar NAME.EXT.json: its contents, precedence when reading, stale or corrupt sidecars.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/heightmap_io.hpp"
#include "tests/io/io_test_util.hpp"
#include "tests/test_util.hpp"

namespace sansui {
namespace {

using ::testing::HasSubstr;

nlohmann::json read_json(const std::filesystem::path& path) {
  std::ifstream stream(path);
  return nlohmann::json::parse(stream);
}

TEST(HeightmapSidecar, KeepsTheExtensionSoFormatsOfOneNameDoNotCollide) {
  EXPECT_EQ(io::sidecar_path("out/terrain.png"), std::filesystem::path("out/terrain.png.json"));
  test::TempDir directory("sidecar-names");
  const Heightfield heights = test::sample_heights(5, 5);
  for (const char* name : {"t.png", "t.raw", "t.r32", "t.tif"}) io::write_heightmap(directory / name, heights);
  // Raw files get an ENVI header too, for GDAL (io/envi_header.hpp); a 16-bit PNG a world file
  // and GDAL's scale and offset.
  EXPECT_EQ(test::files_in(directory.path()),
            (std::vector<std::string>{"t.pgw", "t.png", "t.png.aux.xml", "t.png.json", "t.r32", "t.r32.hdr", "t.r32.json", "t.raw",
                                      "t.raw.hdr", "t.raw.json", "t.tif", "t.tif.json"}));
}

TEST(HeightmapSidecar, DescribesA16BitFile) {
  test::TempDir directory("sidecar-png");
  Heightfield heights = test::sample_heights(9, 4);
  heights.cell_size_m = 12.5;
  heights.origin_x_m = 250.0;
  heights.origin_y_m = 500.0;
  io::HeightmapWriteOptions options{io::HeightRange{-2400.0, 2400.0}};
  options.provenance = {{"seed", 7}, {"command_line", {"sansui", "terrain"}}};
  io::write_heightmap(directory / "h.png", heights, options);
  const nlohmann::json sidecar = read_json(directory / "h.png.json");
  EXPECT_EQ(sidecar["kind"], "heightmap");
  EXPECT_EQ(sidecar["file"], "h.png");
  EXPECT_EQ(sidecar["width"], 9);
  EXPECT_EQ(sidecar["height"], 4);
  EXPECT_EQ(sidecar["cell_size_m"], 12.5);
  EXPECT_EQ(sidecar["origin"]["east_m"], 250.0);
  EXPECT_EQ(sidecar["origin"]["south_m"], 500.0);
  EXPECT_EQ(sidecar["format"]["sample_type"], "uint16");
  EXPECT_EQ(sidecar["format"]["byte_order"], "big-endian");
  EXPECT_EQ(sidecar["format"]["row_order"], "north row first");
  EXPECT_EQ(sidecar["range_m"]["min"], -2400.0);
  EXPECT_EQ(sidecar["range_m"]["max"], 2400.0);
  const auto [low, high] = std::ranges::minmax(heights.values());
  EXPECT_EQ(sidecar["data_range_m"]["min"], low);
  EXPECT_EQ(sidecar["data_range_m"]["max"], high);
  EXPECT_EQ(sidecar["provenance"], options.provenance);
}

TEST(HeightmapSidecar, DescribesFloatFilesWithoutARange) {
  test::TempDir directory("sidecar-float");
  io::write_heightmap(directory / "h.r32", test::sample_heights(3, 3));
  const nlohmann::json r32 = read_json(directory / "h.r32.json");
  EXPECT_EQ(r32["format"]["sample_type"], "float32");
  EXPECT_EQ(r32["format"]["byte_order"], "little-endian");
  EXPECT_FALSE(r32.contains("range_m"));
  io::HeightmapWriteOptions unity{io::HeightRange{0.0, 100.0}};
  unity.raw_flip_y = true;
  io::write_heightmap(directory / "h.raw", test::sample_heights(3, 3), unity);
  const nlohmann::json raw = read_json(directory / "h.raw.json");
  EXPECT_EQ(raw["format"]["byte_order"], "little-endian");
  EXPECT_EQ(raw["format"]["row_order"], "south row first (Unity)");
}

TEST(HeightmapSidecar, CanBeLeftOut) {
  test::TempDir directory("sidecar-none");
  io::write_heightmap(directory / "h.png", test::sample_heights(3, 3), {std::nullopt, {}, false});
  EXPECT_EQ(test::files_in(directory.path()), std::vector<std::string>{"h.png"});
}

TEST(HeightmapSidecar, TheReadOptionsRangeOverridesTheSidecars) {
  test::TempDir directory("sidecar-override");
  Heightfield heights(2, 1, 0.0f);
  heights(1, 0) = 100.0f;
  io::write_heightmap(directory / "h.png", heights, {io::HeightRange{0.0, 100.0}});
  EXPECT_EQ(io::read_heightmap(directory / "h.png")(1, 0), 100.0f);
  io::HeightmapReadOptions options;
  options.range = io::HeightRange{0.0, 10.0};
  EXPECT_EQ(io::read_heightmap(directory / "h.png", options)(1, 0), 10.0f);
}

TEST(HeightmapSidecar, AStaleSidecarOfAnotherSizeIsAnError) {
  test::TempDir directory("sidecar-stale");
  io::write_heightmap(directory / "h.png", test::sample_heights(8, 8));
  const auto sidecar = test::file_bytes(directory / "h.png.json");
  io::write_heightmap(directory / "h.png", test::sample_heights(4, 4), {std::nullopt, {}, false});
  test::write_bytes(directory / "h.png.json", sidecar);
  EXPECT_THAT(test::input_error_of([&] { io::read_heightmap(directory / "h.png"); }),
              HasSubstr("h.png.json describes 8 x 8 samples but the file has 4 x 4"));
}

TEST(HeightmapSidecar, ACorruptSidecarIsAnErrorNamingIt) {
  test::TempDir directory("sidecar-corrupt");
  io::write_heightmap(directory / "h.r32", test::sample_heights(4, 4));
  test::write_text(directory / "h.r32.json", "{\"width\": 4, \"height\": ");
  EXPECT_THAT(
      test::input_error_of([&] { io::read_heightmap(directory / "h.r32"); }),
      HasSubstr("cannot read sidecar " + (directory / "h.r32.json").string() + ": not valid JSON: parse error at line 1, column 24"));
  test::write_text(directory / "h.r32.json", "[4, 4]");
  EXPECT_EQ(test::input_error_of([&] { io::read_heightmap(directory / "h.r32"); }),
            "cannot read sidecar " + (directory / "h.r32.json").string() + ": it is not a JSON object (fix or remove it)");
  test::write_text(directory / "h.r32.json", R"({"width": "four", "height": 4})");
  EXPECT_THAT(test::input_error_of([&] { io::read_heightmap(directory / "h.r32"); }),
              HasSubstr("h.r32.json: /width is \"four\", not a finite number"));
  test::write_text(directory / "h.r32.json", R"({"width": 4, "height": 4, "cell_size_m": -1})");
  EXPECT_THAT(test::input_error_of([&] { io::read_heightmap(directory / "h.r32"); }), HasSubstr("cell_size_m is -1, it must be > 0"));
}

}  // namespace
}  // namespace sansui
