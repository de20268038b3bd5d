// .r32 heightmaps (World Machine, Gaea, Unreal): float32 metres, little-endian, no header, the
// north row first. Written straight from the grid: no copy of the heightfield.
#include <bit>
#include <cstring>
#include <vector>

#include "io/binary_file.hpp"
#include "io/heightmap_formats.hpp"

namespace sansui::io::detail {
namespace {

constexpr bool native_little_endian = std::endian::native == std::endian::little;

/// Reverses the bytes of each float in place (big-endian hosts only).
[[maybe_unused]] void swap_bytes(std::span<float> values) {
  for (float& value : values) {
    unsigned char bytes[4];
    std::memcpy(bytes, &value, 4);
    std::swap(bytes[0], bytes[3]);
    std::swap(bytes[1], bytes[2]);
    std::memcpy(&value, bytes, 4);
  }
}

}  // namespace

void write_r32(const std::filesystem::path& temporary, const std::filesystem::path& target, const Heightfield& heights) {
  OutputFile file(temporary, target);
  if constexpr (native_little_endian) {
    // The grid's bytes are the file's: one write, which stdio hands to the kernel without copying
    // it through its buffer.
    file.write(heights.data(), heights.size() * sizeof(float));
    file.close();
    return;
  }
  std::vector<float> swapped;
  for (int y = 0; y < heights.height(); ++y) {
    std::span<const float> row = heights.row(y);
    if constexpr (!native_little_endian) {
      swapped.assign(row.begin(), row.end());
      swap_bytes(swapped);
      row = swapped;
    }
    file.write(row.data(), row.size_bytes());
  }
  file.close();
}

Heightfield read_r32(const std::filesystem::path& path, const RawLayout& requested) {
  InputFile file(path);
  const RawLayout layout = resolve_raw_layout(path, file.size(), 4, requested);
  auto heights = Heightfield::uninitialized(layout.width, layout.height);
  for (int y = 0; y < layout.height; ++y) {
    const std::span<float> row = heights.row(layout.south_row_first ? layout.height - 1 - y : y);
    file.read(row.data(), row.size_bytes());
    if constexpr (!native_little_endian) swap_bytes(row);
  }
  require_finite(path, heights);
  return heights;
}

}  // namespace sansui::io::detail
