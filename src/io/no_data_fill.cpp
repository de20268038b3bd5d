#include "io/no_data_fill.hpp"

#include <fmt/format.h>

#include "core/error.hpp"

namespace sansui::io::detail {

std::size_t fill_no_data(Heightfield& heights, const std::vector<std::uint8_t>& missing, const char* what) {
  const int width = heights.width(), height = heights.height();
  const auto count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  std::vector<std::uint32_t> queue;
  queue.reserve(count);
  std::vector<std::uint8_t> known(count, 0);
  for (std::size_t i = 0; i < count; ++i)
    if (missing[i] == 0) {
      known[i] = 1;
      queue.push_back(static_cast<std::uint32_t>(i));
    }
  if (queue.empty()) fail("cannot read {}: every sample is NoData", what);
  const std::size_t filled = count - queue.size();
  float* values = heights.values().data();
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::uint32_t at = queue[head];
    const int x = static_cast<int>(at % static_cast<std::uint32_t>(width)), y = static_cast<int>(at / static_cast<std::uint32_t>(width));
    const auto visit = [&](int nx, int ny) {
      if (nx < 0 || ny < 0 || nx >= width || ny >= height) return;
      const auto next = static_cast<std::size_t>(ny) * static_cast<std::size_t>(width) + static_cast<std::size_t>(nx);
      if (known[next] != 0) return;
      known[next] = 1;
      values[next] = values[at];
      queue.push_back(static_cast<std::uint32_t>(next));
    };
    visit(x - 1, y), visit(x + 1, y), visit(x, y - 1), visit(x, y + 1);
  }
  return filled;
}

std::string no_data_note(const std::string& name, std::size_t filled, std::size_t samples) {
  return fmt::format("{}: {} of {} samples ({:.3g} %) were NoData; each took the height of its nearest valid sample", name, filled, samples,
                     100.0 * static_cast<double>(filled) / static_cast<double>(samples));
}

}  // namespace sansui::io::detail
