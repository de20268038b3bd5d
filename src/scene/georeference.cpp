// The outputs' coordinate reference system: see georeference.hpp.
#include "scene/georeference.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "core/error.hpp"
#include "io/contour_lines_geojson.hpp"
#include "io/geojson_crs.hpp"
#include "io/heightmap_io.hpp"
#include "io/json_text.hpp"
#include "io/text_file.hpp"
#include "scene/seed_files.hpp"
#include "scene/sources.hpp"

namespace sansui::scene::detail {
namespace {

/// The CRS of a GeoJSON input; nullopt when the file cannot be read or parsed (the source then
/// says why, in its own words).
std::optional<io::Crs> geojson_crs(const Recipe& recipe, const std::string& file) {
  std::string text;
  try {
    text = io::read_text_file(resolve(recipe, file), std::size_t(1) << 30, io::contour_map_padding);
    // Checked as the sources will read it (a streaming pass): a file that is not JSON is theirs to report.
    return io::geojson_input_crs(text, file, recipe.georeference.force_metres, text.capacity() - text.size());
  } catch (const InputError& e) {
    if (std::string_view(e.what()).find(": not valid JSON: ") != std::string_view::npos || text.empty()) return std::nullopt;
    throw;
  }
}

/// A CSV seed says no CRS: refuses one whose numbers look like degrees (unless forced).
void refuse_csv_degrees(const Recipe& recipe, const std::string& file) {
  io::CoordinateBounds bounds;
  try {
    const auto seed = parse_seed(io::read_text_file(resolve(recipe, file)), io::SeedFormat::csv, file);
    for (const contour::Point& p : seed.ring) {
      const double x = p.x, y = p.y;
      if (!bounds.any) bounds = {x, x, y, y, true};
      bounds.min_x = std::min(bounds.min_x, x), bounds.max_x = std::max(bounds.max_x, x);
      bounds.min_y = std::min(bounds.min_y, y), bounds.max_y = std::max(bounds.max_y, y);
    }
  } catch (const InputError&) {
    return;  // an unreadable seed: the source says why, in its own words
  }
  io::refuse_degrees(bounds, file, recipe.georeference.force_metres);
}

std::optional<io::Crs> heightmap_crs(const Recipe& recipe, const std::string& file, std::vector<std::string>& notes) {
  std::string note;
  std::optional<io::Crs> crs;
  try {
    crs = io::read_heightmap_crs(resolve(recipe, file), &note);
  } catch (const InputError&) {
    return std::nullopt;  // an unreadable file: the source says why, in its own words
  }
  if (!note.empty()) notes.push_back(std::move(note));
  return crs;
}

/// The CRS of the source's input file, checking GeoJSON inputs for degrees.
std::optional<io::Crs> input_crs(const Recipe& recipe, std::vector<std::string>& notes) {
  switch (recipe.source) {
    case SourceKind::file:
      return recipe.file.path.empty() ? std::nullopt : heightmap_crs(recipe, recipe.file.path, notes);
    case SourceKind::contour: {
      const ContourSeedParams& seed = recipe.contour_seed;
      if (!seed.from_dem.empty()) return heightmap_crs(recipe, seed.from_dem, notes);
      if (!seed.file.empty() && io::seed_format_for(seed.file) == io::SeedFormat::geojson) return geojson_crs(recipe, seed.file);
      if (!seed.file.empty() && io::seed_format_for(seed.file) == io::SeedFormat::csv) refuse_csv_degrees(recipe, seed.file);
      return std::nullopt;
    }
    case SourceKind::contour_map: {
      std::optional<io::Crs> crs;
      if (!recipe.contour_map.file.empty()) crs = geojson_crs(recipe, recipe.contour_map.file);
      if (!crs && !recipe.contour_map.grid_from.empty()) crs = heightmap_crs(recipe, recipe.contour_map.grid_from, notes);
      return crs;
    }
    case SourceKind::mesh:
      return recipe.mesh.sketch.empty() ? std::nullopt : geojson_crs(recipe, recipe.mesh.sketch);
    case SourceKind::none:
    case SourceKind::midpoint:
      return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace

std::optional<io::Crs> output_crs(const Recipe& recipe, std::vector<std::string>& notes) {
  std::optional<io::Crs> given;
  const char* key = recipe.version >= 3 ? "world.crs" : "georeference.crs";
  if (!recipe.georeference.crs.empty()) {
    given = io::parse_crs(recipe.georeference.crs, fmt::format("{} (--crs)", key));
    if (given->geographic || !given->metric)
      fail("{} (--crs) {} is in {}, not metres: give a projected CRS in metres (e.g. the UTM zone, EPSG:326NN)", key, given->described(),
           given->unit);
  }
  const std::optional<io::Crs> input = input_crs(recipe, notes);
  if (given && input && !(*given == *input))
    notes.push_back(fmt::format("{} {} replaces the input's {} (the coordinates are assigned it, not transformed)", key, given->label(),
                                input->label()));
  return given ? given : input;
}

std::optional<io::Crs> named_crs(const std::optional<io::Crs>& crs, int version, bool geojson) {
  if (crs) return crs;
  if (version >= 5) return io::local_metres_crs();
  if (version == 4 && geojson) return io::version_4_local_metres_crs();
  return std::nullopt;
}

}  // namespace sansui::scene::detail
