// Map sketches for `sansui subdivide --sketch` as GeoJSON (RFC 7946): ridge and valley lines as
// LineStrings (or MultiLineStrings, Polygon rings), spot heights as Points, with heights.
//
// Coordinates are metres east and north of any origin (a projected system, not degrees).
// A point's height is its third coordinate if it has one, else the i-th entry of the feature's
// "heights" array, else the feature's "height" property (metres). "lock": true keeps the
// feature exactly as drawn through subdivision. "name" and "kind" (e.g. "ridge", "valley")
// only label the feature in messages.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "core/sketch.hpp"

namespace sansui::io {

/// Reads a sketch. Throws InputError naming the file (and feature) when it is unreadable, not
/// JSON, not GeoJSON, or a feature has no height or an unsupported geometry.
Sketch read_sketch_geojson(const std::filesystem::path& path);

/// The same from GeoJSON text; `name` stands for the file in messages.
Sketch parse_sketch_geojson(std::string_view text, const std::string& name);

}  // namespace sansui::io
