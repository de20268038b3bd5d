// 16-bit greyscale PNG heightmaps through libpng's full API. Samples are stored as they are:
// big-endian 16-bit levels (PNG's byte order), no gAMA, sRGB or iCCP chunk and no transform on
// either side, so level q always means min + q * (max - min) / 65535 metres and no viewer or
// importer applies a gamma curve. Rows are encoded and written one at a time (no copy of the grid).
//
// libpng reports errors by longjmp, which skips C++ destructors. So every libpng call lives in
// the `*_png_*` functions below, whose own locals are trivially destructible, and those return
// false with the message in PngError; the C++ side around them owns the buffers and throws.
#include <csetjmp>
#include <cstdio>
#include <new>
#include <vector>

#include <png.h>

#include <zlib.h>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "io/binary_file.hpp"
#include "io/heightmap_formats.hpp"
#include "io/png_error.hpp"

namespace sansui::io::detail {
namespace {

/// Writes a 16-bit grey PNG to `file`. `row` has room for 2 * width bytes.
bool write_png_rows(std::FILE* file, const Heightfield& heights, const Quantizer& quantizer, Compression compression, png_bytep row,
                    PngError& error) {
  return write_png_with(file, error, [&](png_structp png, png_infop info) {
    png_set_IHDR(png, info, static_cast<png_uint_32>(heights.width()), static_cast<png_uint_32>(heights.height()), 16, PNG_COLOR_TYPE_GRAY,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    // Terrain predicts well from the row above, and the filtered residuals are small numbers that
    // zlib's run-length strategy packs as tightly as full deflate at a fraction of the time: on an
    // 8193 x 8193 terrain this is ~8x faster than libpng's defaults (Deflate level 6, adaptive
    // filters) and 1 % smaller. Paeth's predictor saves another 1 %; no other filter, level or
    // strategy of zlib beats it (measured: level 9 with Z_FILTERED is 13x slower for the same size).
    if (compression == Compression::none) {
      png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
      png_set_compression_level(png, 0);
    } else {
      png_set_filter(png, PNG_FILTER_TYPE_BASE, compression == Compression::small ? PNG_FILTER_PAETH : PNG_FILTER_UP);
      png_set_compression_strategy(png, Z_RLE);
      png_set_compression_level(png, 1);
    }
    png_write_info(png, info);
    // Copies the byte stores cannot alias (the captures are references, and bytes alias all).
    const Quantizer local = quantizer;
    const png_bytep out = row;
    for (int y = 0; y < heights.height(); ++y) {
      const auto samples = heights.row(y);
      for (std::size_t x = 0; x < samples.size(); ++x) {
        const std::uint16_t level = local.encode(samples[x]);
        out[2 * x] = static_cast<png_byte>(level >> 8);
        out[2 * x + 1] = static_cast<png_byte>(level & 0xFFu);
      }
      png_write_row(png, out);
    }
    png_write_end(png, info);
  });
}

/// An open libpng read session; destroyed by PngReader's destructor.
struct PngReader {
  png_structp png = nullptr;
  png_infop info = nullptr;
  PngError error;
  ~PngReader() {
    if (png != nullptr) png_destroy_read_struct(&png, info != nullptr ? &info : nullptr, nullptr);
  }
};

/// Deflate cannot compress more than 1032 to 1: a header declaring more rows than the file's
/// bytes can hold is refused before memory is allocated for them (a 200-byte PNG declared
/// 30,000 x 30,000 interlaced samples).
void require_compressed_size_fits(const std::filesystem::path& path, std::uintmax_t file_bytes, png_uint_32 width, png_uint_32 height,
                                  std::size_t row_bytes) {
  const double decoded = static_cast<double>(row_bytes + 1) * height;  // a filter byte per row
  if (decoded > 1032.0 * static_cast<double>(file_bytes) + 65536.0)
    fail("cannot read {}: it declares {} x {} samples ({:.3g} MB decoded), more than its {} bytes can hold (corrupt or truncated)",
         path.string(), width, height, decoded / 1e6, file_bytes);
}

struct PngHeader {
  png_uint_32 width = 0, height = 0;
  int bit_depth = 0, color_type = 0, interlace = 0;
};

bool read_png_header(std::FILE* file, PngReader& reader, PngHeader& header) {
  reader.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &reader.error, on_png_error, on_png_warning);
  if (reader.png == nullptr) return false;
  reader.info = png_create_info_struct(reader.png);
  if (reader.info == nullptr) return false;
  if (setjmp(png_jmpbuf(reader.png))) return false;
  png_init_io(reader.png, file);
  png_read_info(reader.png, reader.info);
  png_get_IHDR(reader.png, reader.info, &header.width, &header.height, &header.bit_depth, &header.color_type, &header.interlace, nullptr,
               nullptr);
  // Only greyscale is a heightmap; 1/2/4-bit grey becomes 8-bit, an alpha channel is dropped.
  if (header.color_type == PNG_COLOR_TYPE_GRAY && header.bit_depth < 8) png_set_expand_gray_1_2_4_to_8(reader.png);
  if (header.color_type == PNG_COLOR_TYPE_GRAY_ALPHA) png_set_strip_alpha(reader.png);
  return true;
}

/// Reads all rows: row by row into `row` (decoded into `heights` by `decode_row`) for plain
/// files; interlaced files need every row at once, so they go into `image` first.
template <class DecodeRow>
bool read_png_rows(PngReader& reader, const PngHeader& header, png_bytep row, png_bytepp image_rows, const DecodeRow& decode_row) {
  if (setjmp(png_jmpbuf(reader.png))) return false;
  if (header.interlace != PNG_INTERLACE_NONE) {
    png_set_interlace_handling(reader.png);
    png_read_update_info(reader.png, reader.info);
    png_read_image(reader.png, image_rows);
    for (png_uint_32 y = 0; y < header.height; ++y) decode_row(image_rows[y], y);
  } else {
    png_read_update_info(reader.png, reader.info);
    for (png_uint_32 y = 0; y < header.height; ++y) {
      png_read_row(reader.png, row, nullptr);
      decode_row(row, y);
    }
  }
  png_read_end(reader.png, nullptr);  // checks the rest of the file, so truncation shows
  return true;
}

}  // namespace

void write_png16(const std::filesystem::path& temporary, const std::filesystem::path& target, const Heightfield& heights,
                 const HeightRange& range, Compression compression) {
  OutputFile file(temporary, target);
  std::vector<png_byte> row(static_cast<std::size_t>(heights.width()) * 2);
  PngError error;
  if (!write_png_rows(file.get(), heights, Quantizer(range), compression, row.data(), error)) {
    if (std::ferror(file.get()) != 0) file.fail_with_errno();
    fail("cannot write {}: {}", target.string(), error.message);
  }
  file.close();
}

Heightfield read_png16(const std::filesystem::path& path, const HeightRange& range) {
  InputFile file(path);
  PngReader reader;
  PngHeader header;
  if (!read_png_header(file.get(), reader, header)) fail("cannot read {}: not a readable PNG ({})", path.string(), reader.error.message);
  if (header.color_type != PNG_COLOR_TYPE_GRAY && header.color_type != PNG_COLOR_TYPE_GRAY_ALPHA)
    fail("cannot read {}: it is a colour PNG; a heightmap must be a greyscale PNG (16-bit, or 8-bit)", path.string());
  require_plausible_size(path, header.width, header.height);

  const bool sixteen = header.bit_depth == 16;
  const std::size_t channels = header.color_type == PNG_COLOR_TYPE_GRAY_ALPHA ? 2 : 1;
  const std::size_t row_bytes = static_cast<std::size_t>(header.width) * channels * (sixteen ? 2 : 1);
  require_compressed_size_fits(path, file.size(), header.width, header.height, row_bytes);
  if (header.interlace != PNG_INTERLACE_NONE)  // the whole image is decoded first, beside the grid
    check_memory(static_cast<double>(row_bytes) * header.height + 4.0 * header.width * header.height,
                 fmt::format("cannot read {}: its {} x {} interlaced samples", path.string(), header.width, header.height));
  const Quantizer quantizer(range);
  auto heights = Heightfield::uninitialized(static_cast<int>(header.width), static_cast<int>(header.height));
  std::vector<png_byte> row(row_bytes);
  std::vector<png_byte> image;
  std::vector<png_bytep> image_rows;
  if (header.interlace != PNG_INTERLACE_NONE) {
    image.resize(row_bytes * header.height);
    for (png_uint_32 y = 0; y < header.height; ++y) image_rows.push_back(image.data() + y * row_bytes);
  }
  const auto decode_row = [&](png_const_bytep bytes, png_uint_32 y) {
    const auto samples = heights.row(static_cast<int>(y));
    for (std::size_t x = 0; x < samples.size(); ++x)
      samples[x] =
          sixteen ? quantizer.decode(static_cast<std::uint32_t>(bytes[2 * x] << 8 | bytes[2 * x + 1])) : quantizer.decode(bytes[x], 255);
  };
  if (!read_png_rows(reader, header, row.data(), image_rows.data(), decode_row))
    fail("cannot read {}: the file is truncated or corrupt ({})", path.string(), reader.error.message);
  return heights;
}

}  // namespace sansui::io::detail
