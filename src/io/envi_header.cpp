#include "io/envi_header.hpp"

#include <fmt/format.h>

namespace sansui::io {
std::string envi_header_text(const Heightfield& heights, const EnviLayout& layout, const std::optional<Crs>& crs) {
  const double cell = heights.cell_size_m;
  // Sample (0, 0) stands at the centre of the upper-left pixel: its corner is half a cell out.
  const double west = heights.origin_x_m - 0.5 * cell, north = -heights.origin_y_m + 0.5 * cell;
  std::string text = "ENVI\ndescription = {Sansui heightmap, heights in metres above the datum}\n";
  text +=
      fmt::format("samples = {}\nlines = {}\nbands = 1\nheader offset = 0\nfile type = ENVI Standard\n", heights.width(), heights.height());
  text += fmt::format("data type = {}\ninterleave = bsq\nbyte order = 0\n", layout.sixteen_bit ? 12 : 4);
  text += fmt::format("map info = {{Arbitrary, 1, 1, {:.17g}, {:.17g}, {:.17g}, {:.17g}, units=Meters}}\n", west + 0.0, north + 0.0, cell,
                      cell);
  if (crs)
    if (const std::string wkt = crs_wkt1(*crs); !wkt.empty()) text += fmt::format("coordinate system string = {{{}}}\n", wkt);
  if (layout.sixteen_bit)
    text += fmt::format("data gain values = {{{:.17g}}}\ndata offset values = {{{:.17g}}}\n", layout.gain_m, layout.offset_m);
  text += "band names = {height}\n";
  return text;
}

std::filesystem::path envi_header_path(const std::filesystem::path& path) {
  return std::filesystem::path(path.string() + ".hdr");
}

}  // namespace sansui::io
