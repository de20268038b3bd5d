// 16-bit little-endian RAW heightmaps (Unity/Unreal): byte layout, round trips, Unity's row flip,
// sizes from the sidecar, the options or the square that fills the file.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io/heightmap_io.hpp"
#include "tests/io/io_test_util.hpp"
#include "tests/test_util.hpp"

namespace sansui {
namespace {

using ::testing::HasSubstr;

std::uint16_t level_at(const std::vector<unsigned char>& bytes, std::size_t index) {
  return static_cast<std::uint16_t>(bytes[2 * index] | bytes[2 * index + 1] << 8);
}

TEST(Raw16, StoresLittleEndianLevelsNorthRowFirst) {
  test::TempDir directory("raw16-bytes");
  Heightfield heights(2, 2, 0.0f);
  heights(0, 0) = 0x1234;
  heights(1, 0) = 1;
  heights(0, 1) = 65535;
  heights(1, 1) = 256;
  io::write_heightmap(directory / "h.raw", heights, {io::HeightRange{0.0, 65535.0}});
  EXPECT_EQ(test::file_bytes(directory / "h.raw"), (std::vector<unsigned char>{0x34, 0x12, 1, 0, 0xFF, 0xFF, 0, 1}));
}

TEST(Raw16, RoundTripsWithinHalfAQuantum) {
  test::TempDir directory("raw16-round");
  const Heightfield heights = test::sample_heights(65, 65, 4);
  const io::HeightRange range{-200.0, 2600.0};
  io::write_heightmap(directory / "h.raw", heights, {range});
  EXPECT_EQ(std::filesystem::file_size(directory / "h.raw"), 65u * 65u * 2u);
  const Heightfield back = io::read_heightmap(directory / "h.raw");
  ASSERT_EQ(back.width(), 65);
  for (std::size_t i = 0; i < heights.size(); ++i)
    EXPECT_NEAR(back.data()[i], heights.data()[i], 0.5 * (range.max_m - range.min_m) / 65535.0 + 1e-4);
}

TEST(Raw16, UnityFlipStoresTheSouthRowFirstAndReadsBackUpright) {
  test::TempDir directory("raw16-unity");
  Heightfield heights(3, 2, 0.0f);
  for (int i = 0; i < 6; ++i) heights.data()[i] = static_cast<float>(i);  // row 0: 0 1 2, row 1: 3 4 5
  io::HeightmapWriteOptions options{io::HeightRange{0.0, 65535.0}};
  options.raw_flip_y = true;
  io::write_heightmap(directory / "h.raw", heights, options);
  const auto bytes = test::file_bytes(directory / "h.raw");
  EXPECT_EQ(level_at(bytes, 0), 3);  // the south row comes first
  EXPECT_EQ(level_at(bytes, 3), 0);

  const Heightfield upright = io::read_heightmap(directory / "h.raw");  // the sidecar says "south row first"
  for (int i = 0; i < 6; ++i) EXPECT_EQ(upright.data()[i], static_cast<float>(i));

  std::filesystem::remove(io::sidecar_path(directory / "h.raw"));
  io::HeightmapReadOptions read;
  read.range = io::HeightRange{0.0, 65535.0};
  read.width = 3;
  const Heightfield as_stored = io::read_heightmap(directory / "h.raw", read);
  EXPECT_EQ(as_stored(0, 0), 3.0f);
  read.raw_flip_y = true;
  const Heightfield flipped_back = io::read_heightmap(directory / "h.raw", read);
  EXPECT_EQ(flipped_back(0, 0), 0.0f);
  EXPECT_EQ(flipped_back(2, 1), 5.0f);
}

TEST(Raw16, SizeComesFromTheSidecarTheOptionsOrTheSquare) {
  test::TempDir directory("raw16-size");
  const Heightfield wide = test::sample_heights(6, 3);
  io::write_heightmap(directory / "wide.raw", wide);
  EXPECT_EQ(io::read_heightmap(directory / "wide.raw").width(), 6);

  std::filesystem::remove(io::sidecar_path(directory / "wide.raw"));
  EXPECT_THAT(test::input_error_of([&] { io::read_heightmap(directory / "wide.raw"); }),
              HasSubstr("wide.raw: its 18 samples do not make a square"));
  io::HeightmapReadOptions options;
  options.height = 3;
  const Heightfield by_height = io::read_heightmap(directory / "wide.raw", options);
  EXPECT_EQ(by_height.width(), 6);
  EXPECT_EQ(by_height.height(), 3);

  io::write_heightmap(directory / "square.raw", test::sample_heights(5, 5), {std::nullopt, {}, false});
  EXPECT_EQ(io::read_heightmap(directory / "square.raw").width(), 5);
}

TEST(Raw16, OptionsThatContradictTheSidecarAreAnError) {
  test::TempDir directory("raw16-conflict");
  io::write_heightmap(directory / "h.raw", test::sample_heights(4, 4));
  io::HeightmapReadOptions options;
  options.width = 8;
  EXPECT_THAT(test::input_error_of([&] { io::read_heightmap(directory / "h.raw", options); }),
              HasSubstr("h.raw: width 8 disagrees with its sidecar"));
}

}  // namespace
}  // namespace sansui
