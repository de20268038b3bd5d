#include "io/map_svg.hpp"

#include <fmt/format.h>

namespace sansui::io {
namespace {

std::string colour(Rgba8 c) {
  return fmt::format("#{:02x}{:02x}{:02x}", c.r, c.g, c.b);
}

std::string escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else
      out += c;
  }
  return out;
}

void append_points(std::string& out, const std::vector<PlanePoint>& points, bool closed) {
  for (std::size_t i = 0; i < points.size(); ++i)
    fmt::format_to(std::back_inserter(out), "{}{:.2f},{:.2f}", i == 0 ? "M" : "L", points[i].x, points[i].y);
  if (closed) out += "Z";
}

}  // namespace

std::string map_to_svg(const MapDrawing& map) {
  std::string out;
  fmt::format_to(std::back_inserter(out),
                 "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                 "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\">\n"
                 "<rect width=\"100%\" height=\"100%\" fill=\"{2}\"/>\n",
                 map.width_px, map.height_px, colour(map.background));
  for (const MapItem& item : map.items) {
    if (const auto* stroke = std::get_if<MapStroke>(&item)) {
      out += "<path d=\"";
      append_points(out, stroke->points, stroke->closed);
      fmt::format_to(std::back_inserter(out), "\" fill=\"none\" stroke=\"{}\" stroke-width=\"{:.2f}\" stroke-linejoin=\"round\"/>\n",
                     colour(stroke->colour), stroke->width_px);
    } else if (const auto* fill = std::get_if<MapFill>(&item)) {
      out += "<path d=\"";
      append_points(out, fill->points, true);
      fmt::format_to(std::back_inserter(out), "\" fill=\"{}\" stroke=\"none\"/>\n", colour(fill->colour));
    } else if (const auto* label = std::get_if<MapLabel>(&item)) {
      // Digit height ~ 0.72 em in common sans fonts.
      fmt::format_to(std::back_inserter(out),
                     "<text x=\"{:.2f}\" y=\"{:.2f}\" transform=\"rotate({:.2f} {:.2f} {:.2f})\" font-family=\"sans-serif\" "
                     "font-size=\"{:.1f}\" text-anchor=\"middle\" dominant-baseline=\"central\" fill=\"{}\" stroke=\"{}\" "
                     "stroke-width=\"3\" paint-order=\"stroke\">{}</text>\n",
                     label->at.x, label->at.y, label->angle_deg, label->at.x, label->at.y, label->size_px / 0.72, colour(label->colour),
                     colour(label->halo), escape(label->text));
    }
  }
  out += "</svg>\n";
  return out;
}

}  // namespace sansui::io
