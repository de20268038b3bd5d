// The contour_map source (sansui contour-dem, issue 17 item 6): a DEM interpolated from a given
// contour map (contour/contours_to_dem.hpp), read from GeoJSON (io/contour_lines_geojson.hpp).
// The grid: [dem] cell or size over the contours' extent, or the grid of a heightmap
// (contour_map.grid_from); by default a cell equal to the lines' median vertex spacing (the
// resolution they were digitised or traced at), with 257 to 4097 samples along the longer side.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "contour/contours_to_dem.hpp"
#include "core/error.hpp"
#include "io/contour_lines_geojson.hpp"
#include "io/heightmap_io.hpp"
#include "io/text_file.hpp"
#include "scene/sources.hpp"

namespace sansui::scene::detail {
namespace {

double median_vertex_spacing(const contour::ContourMap& map) {
  std::vector<double> spacing;
  for (const contour::ContourLine& line : map.lines)
    for (std::size_t i = 1; i < line.points.size(); ++i) spacing.push_back(contour::distance(line.points[i - 1], line.points[i]));
  if (spacing.empty()) return 0.0;
  std::nth_element(spacing.begin(), spacing.begin() + static_cast<std::ptrdiff_t>(spacing.size() / 2), spacing.end());
  return spacing[spacing.size() / 2];
}

}  // namespace

void check_contour_map_source(const Recipe& recipe) {
  if (recipe.contour_map.file.empty()) fail("contour_map.file is missing: the contour lines to interpolate (.geojson)");
  if (recipe.dem.size && *recipe.dem.size > contour::max_contour_dem_side)
    fail("dem.size {} is not allowed for a contour map: it must be 2..{}", *recipe.dem.size, contour::max_contour_dem_side);
}

ContourMap read_contour_map(const std::filesystem::path& path, const std::string& elevation_attribute, bool spot_heights) {
  const std::string text = io::read_text_file(path, std::size_t(1) << 30, io::contour_map_padding);  // read in place
  return io::parse_contour_map(text, path.string(), elevation_attribute, spot_heights, text.capacity() - text.size());
}

nlohmann::json contour_map_statistics(const ContourMap& map) {
  return {{"contour_lines", map.lines.size()}, {"spot_heights", map.spots.size()}};
}

Produced contour_map_on_own_grid(const ContourMapInput& input, const Context& context) {
  const contour::ContourMap map = read_contour_map(input.file, input.elevation_attribute, input.spot_heights);
  contour::ContourMapGrid grid;
  if (!input.grid_from.empty()) {
    const Heightfield like = read_heightmap_with_notes(input.grid_from, context);
    grid = {like.width(), like.height(), like.cell_size_m, like.origin_x_m, like.origin_y_m};
  } else if (input.cell_m || input.size) {
    grid = contour::contour_map_grid(map, input.size.value_or(1025), input.cell_m.value_or(0.0));
  } else {
    const contour::ContourMapGrid coarse = contour::contour_map_grid(map, 2, 0.0);
    const double extent = coarse.cell_m;  // two samples along the longer side: one cell spans it
    const double spacing = median_vertex_spacing(map);
    const double samples = spacing > 0.0 ? std::clamp(std::round(extent / spacing) + 1.0, 257.0, 4097.0) : 1025.0;
    grid = contour::contour_map_grid(map, static_cast<int>(samples), 0.0);
    context.note(fmt::format("contour-dem: {} x {} samples of {:.4g} m (from the lines' vertex spacing; set --cell or --dem-size)",
                             grid.width, grid.height, grid.cell_m));
  }
  Produced produced;
  produced.heights = contour::contour_map_to_dem(map, grid, context);
  produced.statistics = contour_map_statistics(map);
  return produced;
}

ContourMapInput contour_map_input(const Recipe& recipe) {
  const ContourMapSourceParams& p = recipe.contour_map;
  return {resolve(recipe, p.file), p.elevation_attribute,
          p.spot_heights,          p.grid_from.empty() ? std::filesystem::path() : resolve(recipe, p.grid_from),
          recipe.dem.size,         recipe.dem.cell_m};
}

Produced run_contour_map_source(Recipe& recipe, const Context& context) {
  return contour_map_on_own_grid(contour_map_input(recipe), context);
}

}  // namespace sansui::scene::detail
