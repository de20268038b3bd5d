// Seed contours from text: GeoJSON (every Polygon, every polygon of a MultiPolygon, every
// LineString that closes, in any Feature, FeatureCollection or GeometryCollection; metres; holes
// are ignored with a note), CSV ("x,y" per line: one ring), or SVG (every <polygon>, <polyline>
// and every subpath of every <path>, with a scale in metres per SVG unit; SVG's y axis points
// down and is flipped to north-up). Every ring is one seed (one mountain), checked and normalised
// by contour::normalise_seed (contour/seed_input.hpp); seeds that cross or hold one another are
// refused. Nothing is dropped silently (issue 17 item 6). Parsers take the file's text; reading
// the file is the caller's business.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "contour/seed_input.hpp"

namespace sansui::io {

enum class SeedFormat { geojson, csv, svg };

/// The format for a file name's extension (.geojson .json .csv .txt .svg), or nullopt.
std::optional<SeedFormat> seed_format_for(std::string_view file_name);

/// The seed contours of one file, in file order, with the notes of their repairs.
struct SeedContours {
  std::vector<contour::Ring> rings;  ///< each counter-clockwise and simple, disjoint, metres
  std::vector<std::string> notes;
};

/// Parses `text` (the contents of `source`, named in messages) in `format`: every seed in it.
/// `metres_per_unit` scales SVG coordinates. [Units: m] [Range: > 0] [Default: 1]
SeedContours parse_seeds(std::string_view text, SeedFormat format, std::string_view source, double metres_per_unit = 1.0);

/// The same for a file that must hold exactly one seed (refused otherwise, naming the count).
contour::SeedContour parse_seed(std::string_view text, SeedFormat format, std::string_view source, double metres_per_unit = 1.0);

}  // namespace sansui::io
