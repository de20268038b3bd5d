// Seed contours from text: GeoJSON (every Polygon, every polygon of a MultiPolygon, every
// LineString that closes, in any Feature, FeatureCollection or GeometryCollection; metres; holes
// are ignored with a note), CSV ("x,y" per line: one ring), or SVG (every <polygon>, <polyline>
// and every subpath of every <path>, with a scale in metres per SVG unit; SVG's y axis points
// down and is flipped to north-up). Every ring is one seed (one mountain); scene/seed_files.hpp
// checks and normalises them (contour/seed_input.hpp) and refuses seeds that cross or hold one
// another. Nothing is dropped silently (issue 17 item 6). Parsers take the file's text; reading
// the file is the caller's business.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/plane_point.hpp"

namespace sansui::io {

enum class SeedFormat { geojson, csv, svg };

/// The format for a file name's extension (.geojson .json .csv .txt .svg), or nullopt.
std::optional<SeedFormat> seed_format_for(std::string_view file_name);

/// One outline as the file gives it, before any check: its points in metres, whether the format
/// closed it (a GeoJSON LineString may not), and its name for messages ("FILE (feature 2)").
struct SeedOutline {
  PlaneRing ring;
  bool closed = true;
  std::string name;
};

/// Every outline of one file, in file order, with notes on what was left out (holes).
struct SeedOutlines {
  std::vector<SeedOutline> outlines;
  std::vector<std::string> notes;
};

/// Parses `text` (the contents of `source`, named in messages) in `format`. `metres_per_unit`
/// scales SVG coordinates. [Units: m] [Range: > 0] [Default: 1] Throws InputError for text that
/// holds no outline or is not the format; the outlines themselves are checked by the caller
/// (scene/seed_files.hpp, through contour::normalise_seed).
SeedOutlines read_seed_outlines(std::string_view text, SeedFormat format, std::string_view source, double metres_per_unit = 1.0);

}  // namespace sansui::io
