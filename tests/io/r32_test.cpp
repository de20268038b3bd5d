// float32 little-endian .r32 heightmaps: bit-for-bit round trips, byte layout, sizes, bad files.
#include <bit>
#include <cstring>
#include <limits>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io/heightmap_io.hpp"
#include "tests/io/io_test_util.hpp"
#include "tests/test_util.hpp"

namespace sansui {
namespace {

using ::testing::HasSubstr;

TEST(R32, RoundTripsBitForBit) {
  test::TempDir directory("r32-round");
  Heightfield heights = test::sample_heights(129, 65, 5);
  heights(0, 0) = -0.0f;
  heights(1, 0) = std::numeric_limits<float>::denorm_min();
  heights(2, 0) = std::numeric_limits<float>::max();
  heights(3, 0) = -8848.86f;
  heights.cell_size_m = 2.5;
  heights.origin_x_m = 320.0;
  heights.origin_y_m = 160.0;
  io::write_heightmap(directory / "h.r32", heights);
  const Heightfield back = io::read_heightmap(directory / "h.r32");
  ASSERT_EQ(back.width(), 129);
  ASSERT_EQ(back.height(), 65);
  EXPECT_EQ(test::hash_of(back), test::hash_of(heights));
  EXPECT_EQ(back.cell_size_m, 2.5);
  EXPECT_EQ(back.origin_x_m, 320.0);
  EXPECT_EQ(back.origin_y_m, 160.0);
}

TEST(R32, IsHeaderlessLittleEndianFloat32NorthRowFirst) {
  test::TempDir directory("r32-bytes");
  Heightfield heights(2, 2, 0.0f);
  heights(0, 0) = 1.0f;   // 0x3F800000
  heights(1, 1) = -2.0f;  // 0xC0000000
  io::write_heightmap(directory / "h.r32", heights);
  const auto bytes = test::file_bytes(directory / "h.r32");
  ASSERT_EQ(bytes.size(), 16u);
  EXPECT_EQ((std::vector<unsigned char>(bytes.begin(), bytes.begin() + 4)), (std::vector<unsigned char>{0, 0, 0x80, 0x3F}));
  EXPECT_EQ((std::vector<unsigned char>(bytes.begin() + 12, bytes.end())), (std::vector<unsigned char>{0, 0, 0, 0xC0}));
}

TEST(R32, ReadsWithoutSidecarAsASquareOrWithTheGivenSize) {
  test::TempDir directory("r32-nosidecar");
  const Heightfield heights = test::sample_heights(7, 3);
  io::write_heightmap(directory / "h.r32", heights, {std::nullopt, {}, false});
  EXPECT_FALSE(std::filesystem::exists(io::sidecar_path(directory / "h.r32")));
  io::HeightmapReadOptions options;
  options.width = 7;
  options.height = 3;
  options.cell_size_m = 4.0;
  const Heightfield back = io::read_heightmap(directory / "h.r32", options);
  EXPECT_EQ(test::hash_of(back), test::hash_of(heights));
  EXPECT_EQ(back.cell_size_m, 4.0);
  options.width = 5;
  EXPECT_THAT(test::input_error_of([&] { io::read_heightmap(directory / "h.r32", options); }),
              HasSubstr("h.r32: it has 84 bytes but 5 x 3 32-bit samples need 60 bytes"));
}

TEST(R32, NaNOrInfinityInTheFileIsAnError) {
  test::TempDir directory("r32-nan");
  std::vector<float> values(9, 1.0f);
  values[5] = std::numeric_limits<float>::quiet_NaN();
  std::vector<unsigned char> bytes(36);
  std::memcpy(bytes.data(), values.data(), 36);
  test::write_bytes(directory / "h.r32", bytes);
  EXPECT_EQ(test::input_error_of([&] { io::read_heightmap(directory / "h.r32"); }),
            "cannot read " + (directory / "h.r32").string() + ": sample (2, 1) is nan: heights must be finite numbers");
  values[5] = std::numeric_limits<float>::infinity();
  std::memcpy(bytes.data(), values.data(), 36);
  test::write_bytes(directory / "h.r32", bytes);
  EXPECT_THAT(test::input_error_of([&] { io::read_heightmap(directory / "h.r32"); }), HasSubstr("sample (2, 1) is inf"));
}

}  // namespace
}  // namespace sansui
