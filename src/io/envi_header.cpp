#include "io/envi_header.hpp"

#include <fmt/format.h>
#include <proj.h>

namespace sansui::io {
namespace {

/// The CRS as WKT1 (what GDAL's ENVI driver reads in a coordinate system string).
std::string wkt1_of(const Crs& crs) {
  PJ_CONTEXT* context = proj_context_create();
  proj_log_level(context, PJ_LOG_NONE);
  std::string text;
  if (PJ* object = proj_create(context, crs.wkt.c_str())) {
    const char* options[] = {"MULTILINE=NO", nullptr};
    if (const char* wkt = proj_as_wkt(context, object, PJ_WKT1_GDAL, options)) text = wkt;
    proj_destroy(object);
  }
  proj_context_destroy(context);
  return text;
}

}  // namespace

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
    if (const std::string wkt = wkt1_of(*crs); !wkt.empty()) text += fmt::format("coordinate system string = {{{}}}\n", wkt);
  if (layout.sixteen_bit)
    text += fmt::format("data gain values = {{{:.17g}}}\ndata offset values = {{{:.17g}}}\n", layout.gain_m, layout.offset_m);
  text += "band names = {height}\n";
  return text;
}

std::filesystem::path envi_header_path(const std::filesystem::path& path) {
  return std::filesystem::path(path.string() + ".hdr");
}

}  // namespace sansui::io
