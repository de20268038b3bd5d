// 8-bit RGBA pictures: round trip and bad files.
#include "io/image_io.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/io/io_test_util.hpp"
#include "tests/test_util.hpp"

namespace sansui {
namespace {

TEST(ImageIo, RgbaRoundTripsExactly) {
  test::TempDir directory("image-round");
  Image image(5, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x)
      image(x, y) = Rgba8{static_cast<std::uint8_t>(40 * x), static_cast<std::uint8_t>(80 * y), 7, static_cast<std::uint8_t>(255 - x)};
  io::write_png(directory / "p.png", image);
  const Image back = io::read_png(directory / "p.png");
  ASSERT_EQ(back.width(), 5);
  ASSERT_EQ(back.height(), 3);
  for (std::size_t i = 0; i < image.size(); ++i) EXPECT_EQ(back.data()[i], image.data()[i]);
}

TEST(ImageIo, MissingAndCorruptFilesAreNamed) {
  test::TempDir directory("image-bad");
  EXPECT_THAT(test::input_error_of([&] { io::read_png(directory / "none.png"); }),
              ::testing::StartsWith("cannot read " + (directory / "none.png").string()));
  io::write_png(directory / "p.png", Image(64, 64, Rgba8{1, 2, 3, 4}));
  test::truncate_file(directory / "p.png", 60);
  EXPECT_THAT(test::input_error_of([&] { io::read_png(directory / "p.png"); }),
              ::testing::StartsWith("cannot read " + (directory / "p.png").string()));
}

}  // namespace
}  // namespace sansui
