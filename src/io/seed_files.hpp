// Seed contours from text: GeoJSON (Polygon, MultiPolygon, or a LineString that closes; metres),
// CSV ("x,y" per line), or SVG (the first <polygon>, <polyline> or <path>, with a scale in metres
// per SVG unit; SVG's y axis points down and is flipped to north-up). The ring is then checked and
// normalised by contour::normalise_seed (contour/seed_input.hpp). Parsers take the file's text;
// reading the file is the caller's business.
#pragma once

#include <optional>
#include <string_view>

#include "contour/seed_input.hpp"

namespace sansui::io {

enum class SeedFormat { geojson, csv, svg };

/// The format for a file name's extension (.geojson .json .csv .txt .svg), or nullopt.
std::optional<SeedFormat> seed_format_for(std::string_view file_name);

/// Parses `text` (the contents of `source`, named in messages) in `format`.
/// `metres_per_unit` scales SVG coordinates. [Units: m] [Range: > 0] [Default: 1]
contour::SeedContour parse_seed(std::string_view text, SeedFormat format, std::string_view source, double metres_per_unit = 1.0);

}  // namespace sansui::io
