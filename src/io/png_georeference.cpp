#include "io/png_georeference.hpp"

#include <fmt/format.h>

namespace sansui::io {
namespace {

/// Text as XML character data.
std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace

std::filesystem::path png_world_file_path(const std::filesystem::path& png) {
  return std::filesystem::path(png).replace_extension(".pgw");
}

std::filesystem::path png_aux_xml_path(const std::filesystem::path& png) {
  return std::filesystem::path(png.string() + ".aux.xml");
}

std::string png_world_file_text(const Heightfield& heights) {
  // x scale, two rotations, y scale (negative: rows run south), then the centre of the
  // upper-left pixel, which is sample (0, 0): east, north (origin_y_m counts south).
  const double cell = heights.cell_size_m;
  return fmt::format("{:.17g}\n0\n0\n{:.17g}\n{:.17g}\n{:.17g}\n", cell, -cell, heights.origin_x_m + 0.0, -heights.origin_y_m + 0.0);
}

std::string png_aux_xml_text(double gain_m, double offset_m, const std::optional<Crs>& crs) {
  std::string text = "<PAMDataset>\n";
  if (crs)
    if (const std::string wkt = crs_wkt1(*crs); !wkt.empty()) text += fmt::format("  <SRS>{}</SRS>\n", escaped(wkt));
  text += fmt::format(
      "  <PAMRasterBand band=\"1\">\n    <Description>height</Description>\n    <UnitType>m</UnitType>\n"
      "    <Offset>{:.17g}</Offset>\n    <Scale>{:.17g}</Scale>\n  </PAMRasterBand>\n</PAMDataset>\n",
      offset_m + 0.0, gain_m);
  return text;
}

}  // namespace sansui::io
