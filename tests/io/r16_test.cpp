// .r16 heightmaps (Unreal, Terrain3D): the RAW16 bytes of .raw, always north row first, with a
// sidecar naming the format.
#include <gtest/gtest.h>

#include "io/heightmap_io.hpp"
#include "tests/io/io_test_util.hpp"
#include "tests/test_util.hpp"

namespace sansui {
namespace {

TEST(R16, RoundTripsWithinHalfAQuantumAndHasTheRawBytesNorthRowFirst) {
  test::TempDir directory("r16-round");
  const Heightfield heights = test::sample_heights(33, 17, 5);
  const io::HeightRange range{-100.0, 2500.0};
  io::HeightmapWriteOptions options{range};
  options.raw_flip_y = true;  // a .raw option: .r16 stays north row first
  io::write_heightmap(directory / "h.r16", heights, options);
  io::write_heightmap(directory / "h.raw", heights, {range});
  EXPECT_EQ(test::file_bytes(directory / "h.r16"), test::file_bytes(directory / "h.raw"));
  EXPECT_EQ(std::filesystem::file_size(directory / "h.r16"), 33u * 17u * 2u);

  const std::vector<unsigned char> sidecar_bytes = test::file_bytes(io::sidecar_path(directory / "h.r16"));
  const std::string sidecar(sidecar_bytes.begin(), sidecar_bytes.end());
  EXPECT_NE(sidecar.find("\"name\": \"r16\""), std::string::npos) << sidecar;
  EXPECT_NE(sidecar.find("north row first"), std::string::npos) << sidecar;

  const Heightfield back = io::read_heightmap(directory / "h.r16");
  ASSERT_EQ(back.width(), 33);
  ASSERT_EQ(back.height(), 17);
  for (std::size_t i = 0; i < heights.size(); ++i)
    EXPECT_NEAR(back.data()[i], heights.data()[i], 0.5 * (range.max_m - range.min_m) / 65535.0 + 1e-4);
}

TEST(R16, WithoutSidecarReadsASquareWithTheGivenRange) {
  test::TempDir directory("r16-bare");
  const Heightfield heights = test::sample_heights(9, 9, 2);
  io::HeightmapWriteOptions options{io::HeightRange{0.0, 1000.0}};
  options.sidecar = false;
  io::write_heightmap(directory / "h.r16", heights, options);
  io::HeightmapAssumptions assumed;
  const Heightfield back = io::read_heightmap(directory / "h.r16", {}, &assumed);
  EXPECT_EQ(back.width(), 9);
  EXPECT_TRUE(assumed.range);
  EXPECT_NEAR(back(3, 0), heights(3, 0), 0.01);
}

}  // namespace
}  // namespace sansui
