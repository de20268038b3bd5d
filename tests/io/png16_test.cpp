// 16-bit greyscale PNG heightmaps: round trips within half a quantum, raw big-endian levels with
// no gamma chunk, clamping, flat grids, 8-bit and interlaced inputs, colour PNGs refused.
#include <csetjmp>
#include <cstdint>
#include <vector>

#include <png.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io/heightmap_io.hpp"
#include "io/image_io.hpp"
#include "tests/io/io_test_util.hpp"
#include "tests/test_util.hpp"

namespace sansui {
namespace {

using ::testing::HasSubstr;

struct RawPng {
  png_uint_32 width = 0, height = 0;
  int bit_depth = 0, color_type = 0;
  bool has_gamma_chunk = false;
  std::vector<std::uint16_t> levels;  // as stored, no transform
};

/// Reads a PNG with libpng's full API and no transforms: the levels exactly as stored.
RawPng read_raw_png(const std::filesystem::path& path) {
  RawPng result;
  std::FILE* file = std::fopen(path.c_str(), "rb");
  EXPECT_NE(file, nullptr);
  if (file == nullptr) return result;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  std::vector<png_byte> row;
  if (setjmp(png_jmpbuf(png))) {
    ADD_FAILURE() << "libpng failed on " << path;
  } else {
    png_init_io(png, file);
    png_read_info(png, info);
    result.width = png_get_image_width(png, info);
    result.height = png_get_image_height(png, info);
    result.bit_depth = png_get_bit_depth(png, info);
    result.color_type = png_get_color_type(png, info);
    result.has_gamma_chunk = png_get_valid(png, info, PNG_INFO_gAMA | PNG_INFO_sRGB | PNG_INFO_iCCP) != 0;
    row.resize(png_get_rowbytes(png, info));
    for (png_uint_32 y = 0; y < result.height; ++y) {
      png_read_row(png, row.data(), nullptr);
      for (png_uint_32 x = 0; x < result.width; ++x)
        result.levels.push_back(result.bit_depth == 16 ? static_cast<std::uint16_t>(row[2 * x] << 8 | row[2 * x + 1]) : row[x]);
    }
  }
  png_destroy_read_struct(&png, &info, nullptr);
  std::fclose(file);
  return result;
}

/// Writes a greyscale PNG of `levels` with libpng (8 or 16 bits, optionally interlaced).
void write_grey_png(const std::filesystem::path& path, int width, int height, const std::vector<std::uint16_t>& levels, int bit_depth,
                    bool interlaced) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  ASSERT_NE(file, nullptr);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  const std::size_t bytes = bit_depth == 16 ? 2 : 1;
  std::vector<png_byte> image(static_cast<std::size_t>(width * height) * bytes);
  for (std::size_t i = 0; i < levels.size(); ++i) {
    if (bytes == 2) {
      image[2 * i] = static_cast<png_byte>(levels[i] >> 8);
      image[2 * i + 1] = static_cast<png_byte>(levels[i] & 0xFF);
    } else {
      image[i] = static_cast<png_byte>(levels[i]);
    }
  }
  std::vector<png_bytep> rows;
  for (int y = 0; y < height; ++y) rows.push_back(image.data() + static_cast<std::size_t>(y * width) * bytes);
  if (setjmp(png_jmpbuf(png))) {
    ADD_FAILURE() << "libpng failed writing " << path;
  } else {
    png_init_io(png, file);
    png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), bit_depth, PNG_COLOR_TYPE_GRAY,
                 interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    png_write_image(png, rows.data());
    png_write_end(png, info);
  }
  png_destroy_write_struct(&png, &info);
  std::fclose(file);
}

double quantum(const io::HeightRange& range) {
  return (range.max_m - range.min_m) / 65535.0;
}

/// Every sample within half a quantum (plus float rounding of the decoded value).
void expect_within_half_quantum(const Heightfield& expected, const Heightfield& actual, double quantum_m) {
  ASSERT_EQ(actual.width(), expected.width());
  ASSERT_EQ(actual.height(), expected.height());
  double worst = 0.0;
  for (std::size_t i = 0; i < expected.size(); ++i)
    worst = std::max(worst, std::abs(double{actual.data()[i]} - double{expected.data()[i]}));
  EXPECT_LE(worst, 0.5 * quantum_m + 1e-4);
  EXPECT_GT(worst, 0.0);  // it really was quantised
}

TEST(Png16, RoundTripsWithinHalfAQuantumWithAGivenRange) {
  test::TempDir directory("png16-range");
  const Heightfield heights = test::sample_heights(67, 41);
  const io::HeightRange range{-500.0, 3000.0};
  io::write_heightmap(directory / "h.png", heights, {range});
  const Heightfield back = io::read_heightmap(directory / "h.png");
  expect_within_half_quantum(heights, back, quantum(range));
  EXPECT_EQ(back.cell_size_m, 10.0);
}

TEST(Png16, RoundTripsWithinHalfAQuantumWithTheDataRange) {
  test::TempDir directory("png16-data");
  Heightfield heights = test::sample_heights(33, 65, 2);
  heights.origin_x_m = 1280.0;
  heights.origin_y_m = -640.0;
  io::write_heightmap(directory / "h.png", heights);
  const auto [low, high] = std::ranges::minmax(heights.values());
  const Heightfield back = io::read_heightmap(directory / "h.png");
  expect_within_half_quantum(heights, back, quantum({low, high}));
  EXPECT_EQ(back.origin_x_m, 1280.0);
  EXPECT_EQ(back.origin_y_m, -640.0);
  // The extremes are levels 0 and 65535, which decode exactly.
  const RawPng raw = read_raw_png(directory / "h.png");
  EXPECT_EQ(*std::ranges::min_element(raw.levels), 0);
  EXPECT_EQ(*std::ranges::max_element(raw.levels), 65535);
  EXPECT_EQ(*std::ranges::min_element(back.values()), low);
}

TEST(Png16, StoresRawBigEndianLevelsWithoutAnyGammaChunk) {
  test::TempDir directory("png16-raw");
  Heightfield heights(4, 2, 0.0f);
  const float values[] = {0.0f, 1.0f, 256.0f, 65535.0f, 4660.0f, 32768.0f, 12345.0f, 65534.0f};
  std::ranges::copy(values, heights.data());
  io::write_heightmap(directory / "h.png", heights, {io::HeightRange{0.0, 65535.0}});
  const RawPng raw = read_raw_png(directory / "h.png");
  EXPECT_EQ(raw.bit_depth, 16);
  EXPECT_EQ(raw.color_type, PNG_COLOR_TYPE_GRAY);
  EXPECT_FALSE(raw.has_gamma_chunk);
  EXPECT_EQ(raw.levels, (std::vector<std::uint16_t>{0, 1, 256, 65535, 4660, 32768, 12345, 65534}));
}

TEST(Png16, EveryCompressionStoresTheSameLevels) {
  test::TempDir directory("png16-compression");
  const Heightfield heights = test::sample_heights(300, 77, 9);
  std::vector<std::uint16_t> levels;
  std::uintmax_t previous_size = 0;
  for (const auto compression : {io::Compression::none, io::Compression::fast, io::Compression::small}) {
    io::HeightmapWriteOptions options;
    options.compression = compression;
    io::write_heightmap(directory / "h.png", heights, options);
    const RawPng raw = read_raw_png(directory / "h.png");
    if (levels.empty()) levels = raw.levels;
    EXPECT_EQ(raw.levels, levels);
    const std::uintmax_t size = std::filesystem::file_size(directory / "h.png");
    if (compression == io::Compression::none)
      EXPECT_GT(size, heights.size() * 2);  // stored
    else
      EXPECT_LT(size, previous_size);
    previous_size = size;
  }
}

TEST(Png16, ClampsHeightsOutsideTheRange) {
  test::TempDir directory("png16-clamp");
  Heightfield heights(3, 1, 0.0f);
  heights(0, 0) = -50.0f;
  heights(1, 0) = 50.0f;
  heights(2, 0) = 150.0f;
  io::write_heightmap(directory / "h.png", heights, {io::HeightRange{0.0, 100.0}});
  const RawPng raw = read_raw_png(directory / "h.png");
  EXPECT_EQ(raw.levels, (std::vector<std::uint16_t>{0, 32768, 65535}));
  const Heightfield back = io::read_heightmap(directory / "h.png");
  EXPECT_EQ(back(0, 0), 0.0f);
  EXPECT_EQ(back(2, 0), 100.0f);
}

TEST(Png16, AFlatGridReadsBackExactly) {
  test::TempDir directory("png16-flat");
  const Heightfield heights(5, 5, 42.5f);
  io::write_heightmap(directory / "h.png", heights);
  const Heightfield back = io::read_heightmap(directory / "h.png");
  for (const float value : back.values()) EXPECT_EQ(value, 42.5f);
}

TEST(Png16, WithoutSidecarUsesTheOptionsOrTheDefaultRange) {
  test::TempDir directory("png16-default");
  write_grey_png(directory / "h.png", 3, 1, {0, 32768, 65535}, 16, false);
  const Heightfield by_default = io::read_heightmap(directory / "h.png");
  EXPECT_EQ(by_default(0, 0), io::default_16bit_read_range.min_m);
  EXPECT_EQ(by_default(2, 0), io::default_16bit_read_range.max_m);
  EXPECT_EQ(by_default.cell_size_m, io::default_read_cell_size_m);
  io::HeightmapReadOptions options;
  options.range = io::HeightRange{-100.0, 100.0};
  options.cell_size_m = 30.0;
  const Heightfield given = io::read_heightmap(directory / "h.png", options);
  EXPECT_EQ(given(0, 0), -100.0f);
  EXPECT_NEAR(given(1, 0), -100.0 + 32768 * 200.0 / 65535.0, 1e-6);
  EXPECT_EQ(given(2, 0), 100.0f);
  EXPECT_EQ(given.cell_size_m, 30.0);
}

TEST(Png16, Reads8BitAndInterlacedGreyPngs) {
  test::TempDir directory("png16-other");
  std::vector<std::uint16_t> levels;
  for (int i = 0; i < 9 * 7; ++i) levels.push_back(static_cast<std::uint16_t>(i * 4));
  write_grey_png(directory / "eight.png", 9, 7, levels, 8, false);
  io::HeightmapReadOptions options;
  options.range = io::HeightRange{0.0, 255.0};
  const Heightfield eight = io::read_heightmap(directory / "eight.png", options);
  for (int i = 0; i < 9 * 7; ++i) EXPECT_EQ(eight.data()[i], static_cast<float>(levels[static_cast<std::size_t>(i)]));

  for (auto& level : levels) level = static_cast<std::uint16_t>(level * 257);
  write_grey_png(directory / "interlaced.png", 9, 7, levels, 16, true);
  options.range = io::HeightRange{0.0, 65535.0};
  const Heightfield interlaced = io::read_heightmap(directory / "interlaced.png", options);
  for (int i = 0; i < 9 * 7; ++i) EXPECT_EQ(interlaced.data()[i], static_cast<float>(levels[static_cast<std::size_t>(i)]));
}

TEST(Png16, RefusesColourPngs) {
  test::TempDir directory("png16-colour");
  io::write_png(directory / "picture.png", Image(4, 4, Rgba8{10, 20, 30, 255}));
  EXPECT_THAT(test::input_error_of([&] { io::read_heightmap(directory / "picture.png"); }), HasSubstr("picture.png: it is a colour PNG"));
}

}  // namespace
}  // namespace sansui
