// Pictures side by side, for docs (docs/gallery.sh makes docs/gallery.png with it): each input
// shrunk by a whole factor (a box filter) and laid out in rows of COLUMNS with a white gap.
//
//   build/bench/contact_sheet OUTPUT.png COLUMNS SHRINK INPUT.png...
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <vector>

#include "core/color.hpp"
#include "io/image_io.hpp"

namespace sansui {
namespace {

constexpr int gap = 4;  // pixels between pictures

Image shrunk(const Image& image, int factor) {
  Image small(image.width() / factor, image.height() / factor);
  for (int y = 0; y < small.height(); ++y)
    for (int x = 0; x < small.width(); ++x) {
      int sum[4] = {0, 0, 0, 0};
      for (int dy = 0; dy < factor; ++dy)
        for (int dx = 0; dx < factor; ++dx) {
          const Rgba8 p = image(x * factor + dx, y * factor + dy);
          sum[0] += p.r, sum[1] += p.g, sum[2] += p.b, sum[3] += p.a;
        }
      const int n = factor * factor;
      auto mean = [n](int total) { return static_cast<std::uint8_t>((total + n / 2) / n); };
      small(x, y) = Rgba8{mean(sum[0]), mean(sum[1]), mean(sum[2]), mean(sum[3])};
    }
  return small;
}

Image contact_sheet(const std::vector<Image>& pictures, int columns) {
  int cell_w = 0, cell_h = 0;
  for (const Image& p : pictures) cell_w = std::max(cell_w, p.width()), cell_h = std::max(cell_h, p.height());
  const int count = static_cast<int>(pictures.size());
  const int rows = (count + columns - 1) / columns;
  const int used_columns = std::min(columns, count);
  Image sheet(used_columns * cell_w + (used_columns + 1) * gap, rows * cell_h + (rows + 1) * gap, Rgba8{255, 255, 255, 255});
  for (int i = 0; i < count; ++i) {
    const Image& p = pictures[static_cast<std::size_t>(i)];
    const int left = gap + (i % columns) * (cell_w + gap), top = gap + (i / columns) * (cell_h + gap);
    for (int y = 0; y < p.height(); ++y)
      for (int x = 0; x < p.width(); ++x) sheet(left + x, top + y) = p(x, y);
  }
  return sheet;
}

}  // namespace
}  // namespace sansui

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: contact_sheet OUTPUT.png COLUMNS SHRINK INPUT.png...\n");
    return 2;
  }
  const int columns = std::atoi(argv[2]), shrink = std::atoi(argv[3]);
  if (columns < 1 || shrink < 1) {
    std::fprintf(stderr, "contact_sheet: COLUMNS and SHRINK must be whole numbers from 1\n");
    return 2;
  }
  try {
    std::vector<sansui::Image> pictures;
    for (int i = 4; i < argc; ++i) pictures.push_back(sansui::shrunk(sansui::io::read_png(argv[i]), shrink));
    sansui::io::write_png(argv[1], sansui::contact_sheet(pictures, columns));
  } catch (const std::exception& error) {
    std::fprintf(stderr, "contact_sheet: %s\n", error.what());
    return 2;
  }
  std::printf("wrote %s\n", argv[1]);
  return 0;
}
