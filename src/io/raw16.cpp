// 16-bit RAW heightmaps as Unity and Unreal import them: unsigned 16-bit little-endian levels,
// no header, rows one after another. Unity reads rows bottom-up, so it wants the south row
// first (RawLayout::south_row_first); Unreal and most tools read the north row first. .r16
// files (Unreal's and Terrain3D's name for the same bytes) always store the north row first.
#include <algorithm>
#include <vector>

#include "core/parallel.hpp"
#include "io/binary_file.hpp"
#include "io/heightmap_formats.hpp"

namespace sansui::io::detail {

void write_raw16(const std::filesystem::path& temporary, const std::filesystem::path& target, const Heightfield& heights,
                 const HeightRange& range, bool south_row_first) {
  const Quantizer quantizer(range);
  OutputFile file(temporary, target);
  // Rows are quantised in parallel, a few MiB of them at a time, and written in order: the same
  // bytes with any thread count, and no copy of the whole grid.
  const std::size_t row_bytes = static_cast<std::size_t>(heights.width()) * 2;
  const int rows_per_round = static_cast<int>(std::max<std::size_t>(1, (std::size_t{4} << 20) / row_bytes));
  std::vector<unsigned char> bytes(static_cast<std::size_t>(std::min(rows_per_round, heights.height())) * row_bytes);
  for (int first = 0; first < heights.height(); first += rows_per_round) {
    const int rows = std::min(rows_per_round, heights.height() - first);
    parallel_for(0, rows, [&](int i) {
      const int row = first + i;
      const auto samples = heights.row(south_row_first ? heights.height() - 1 - row : row);
      unsigned char* out = bytes.data() + static_cast<std::size_t>(i) * row_bytes;
      const Quantizer local = quantizer;  // a copy the byte stores cannot alias: the loop vectorises
      for (std::size_t x = 0; x < samples.size(); ++x) store_u16_le(out + 2 * x, local.encode(samples[x]));
    });
    file.write(bytes.data(), static_cast<std::size_t>(rows) * row_bytes);
  }
  file.close();
}

Heightfield read_raw16(const std::filesystem::path& path, const RawLayout& requested, const HeightRange& range) {
  InputFile file(path);
  const RawLayout layout = resolve_raw_layout(path, file.size(), 2, requested);
  const Quantizer quantizer(range);
  auto heights = Heightfield::uninitialized(layout.width, layout.height);
  std::vector<unsigned char> bytes(static_cast<std::size_t>(layout.width) * 2);
  for (int row = 0; row < layout.height; ++row) {
    file.read(bytes.data(), bytes.size());
    const auto samples = heights.row(layout.south_row_first ? layout.height - 1 - row : row);
    for (std::size_t x = 0; x < samples.size(); ++x) samples[x] = quantizer.decode(load_u16_le(&bytes[2 * x]));
  }
  return heights;
}

}  // namespace sansui::io::detail
