// Seed contours from text: GeoJSON (Polygon, MultiPolygon, or a LineString that closes; metres),
// CSV ("x,y" per line), or SVG (the first <polygon>, <polyline> or <path>, with a scale in metres
// per SVG unit; SVG's y axis points down and is flipped to north-up). The ring is checked and
// normalised: finite coordinates, at least 3 distinct vertices, non-zero area, counter-clockwise,
// no self-crossing. What can be repaired unambiguously (an almost closed line, a small
// self-crossing loop) is repaired and said in `notes`; anything else throws InputError.
// Parsers take the file's text; reading the file is the caller's business.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "contour/geometry.hpp"

namespace sansui::contour {

struct SeedContour {
  Ring ring;                       ///< counter-clockwise, simple, metres
  std::vector<std::string> notes;  ///< repairs and choices made, one line each
};

enum class SeedFormat { geojson, csv, svg };

/// The format for a file name's extension (.geojson .json .csv .svg), or nullopt.
std::optional<SeedFormat> seed_format_for(std::string_view file_name);

/// Parses `text` (the contents of `source`, named in messages) in `format`.
/// `metres_per_unit` scales SVG coordinates. [Units: m] [Range: > 0] [Default: 1]
SeedContour parse_seed(std::string_view text, SeedFormat format, std::string_view source, double metres_per_unit = 1.0);

/// Checks and normalises a ring (see above). `closed` says whether the input closed it itself
/// (a GeoJSON LineString may not); an open ring whose ends are close is closed with a note.
SeedContour normalise_seed(Ring ring, bool closed, std::string_view source);

}  // namespace sansui::contour
