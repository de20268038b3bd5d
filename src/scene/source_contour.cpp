// The contour source: a mountain grown from one contour line (SPEC 1; Misawa, Chiba, Saito 1987,
// seeds/000). The seed comes from a file or from a DEM at a level; the contours are generated,
// their elevations optionally reshaped by a hypsometric curve, and rasterised into a DEM on the
// grid the recipe asks for (by default the source DEM's own grid, so the two compare cell by cell).
#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "contour/contours_to_dem.hpp"
#include "contour/elevations.hpp"
#include "contour/extract.hpp"
#include "contour/generate.hpp"
#include "contour/grid_frame.hpp"
#include "contour/scale.hpp"
#include "contour/seed_input.hpp"
#include "contour/to_dem.hpp"
#include "core/error.hpp"
#include "io/heightmap_io.hpp"
#include "io/hypsometry_csv.hpp"
#include "io/text_file.hpp"
#include "scene/seed_files.hpp"
#include "scene/sources.hpp"

namespace sansui::scene::detail {
namespace {

/// d for a seed taken from a DEM: the spacing the real slope gives at this interval, dz / mean
/// gradient of the cells inside the seed.
double offset_from_dem(const Heightfield& dem, const contour::Ring& seed, double interval) {
  const contour::GridFrame frame = contour::GridFrame::of(dem);
  double sum = 0.0;
  int count = 0;
  for (int j = 1; j + 1 < dem.height(); ++j)
    for (int i = 1; i + 1 < dem.width(); ++i) {
      if (!contour::contains(seed, frame.at(i, j))) continue;
      const double gx = (dem(i + 1, j) - dem(i - 1, j)) / (2.0 * dem.cell_size_m);
      const double gy = (dem(i, j + 1) - dem(i, j - 1)) / (2.0 * dem.cell_size_m);
      sum += std::sqrt(gx * gx + gy * gy);
      ++count;
    }
  const double gradient = count > 0 ? sum / count : 0.0;
  return gradient > 1e-6 ? interval / gradient : 10.0 * dem.cell_size_m;
}

/// The DEM grid: the source DEM's own (regenerating a real mountain), or a frame around the
/// contours with `size` samples along its longer side; `cell` keeps the extent.
contour::DemParams dem_params_for(const ContourInput& input, const contour::ContourTree& tree,
                                  const std::optional<Heightfield>& source_dem) {
  contour::DemParams params = input.dem;
  const DemGridParams& grid = input.grid;
  if (source_dem && !grid.size && !grid.cell_m) {
    params.width = source_dem->width();
    params.height = source_dem->height();
    params.cell_m = source_dem->cell_size_m;
    params.origin_x_m = source_dem->origin_x_m;
    params.origin_y_m = source_dem->origin_y_m;
  } else {
    // Foothills need room around the mountain to be seen: a quarter of its extent on each side.
    const double margin = params.surround == contour::Surround::foothills ? 0.25 : 0.05;
    const contour::DemParams frame = contour::dem_frame_for(tree, grid.size.value_or(1025), margin);
    params.width = frame.width, params.height = frame.height, params.cell_m = frame.cell_m;
    params.origin_x_m = frame.origin_x_m, params.origin_y_m = frame.origin_y_m;
  }
  if (grid.cell_m) {
    const double cell = *grid.cell_m;
    const double width_m = (params.width - 1) * params.cell_m, height_m = (params.height - 1) * params.cell_m;
    const double cx = params.origin_x_m + 0.5 * width_m, cy = params.origin_y_m + 0.5 * height_m;
    params.cell_m = cell;
    params.width = static_cast<int>(std::ceil(width_m / cell)) + 1;
    params.height = static_cast<int>(std::ceil(height_m / cell)) + 1;
    params.origin_x_m = cx - 0.5 * (params.width - 1) * cell;
    params.origin_y_m = cy - 0.5 * (params.height - 1) * cell;
  }
  params.base_m = grid.fill_m;
  params.offset_m = input.generation.resolved_offset_m();
  params.seed = input.generation.seed;
  return params;
}

std::string summary(const contour::ContourTree& tree, const contour::GenerationParams& params) {
  double low = INFINITY, high = -INFINITY;
  int lowest = 0, highest = 0;
  for (const auto& node : tree.nodes) {
    low = std::min(low, node.elevation_m), high = std::max(high, node.elevation_m);
    lowest = std::min(lowest, node.level), highest = std::max(highest, node.level);
  }
  return fmt::format("{} contours on levels {}..{} ({:.1f}..{:.1f} m), {} summit(s), method {}, d = {:.2f} m, dz = {:.2f} m",
                     tree.nodes.size(), lowest, highest, low, high, tree.summits().size(), contour::name_of(params.method),
                     params.resolved_offset_m(), params.interval_m);
}

}  // namespace

void check_contour_seed(const ContourSeedParams& seed, bool points, const contour::GenerationParams& given, std::string_view prefix) {
  if (!seed.file.empty() + !seed.from_dem.empty() + points != 1)
    fail("give one seed contour: a file or a DEM to take it from ({0}file or {0}from_dem{1})", prefix, points ? ", or points" : "");
  if (!seed.from_dem.empty() && !seed.level_m) fail("{0}from_dem needs {0}level: the elevation of the seed contour", prefix);
  if (!seed.file.empty() && !io::seed_format_for(seed.file))
    fail("seed file {} has an unknown extension: allowed are .geojson .json .csv .txt .svg", seed.file);
  // z0 as the run resolves it: a seed taken from a DEM stands at its level, so a base below that
  // level is allowed without z0.
  contour::GenerationParams generation = given;
  if (!generation.z0_m) generation.z0_m = seed.level_m.value_or(0.0);
  generation.validate();
}

void check_contour_source(const Recipe& recipe) {
  check_contour_seed(recipe.contour_seed, false, recipe.contour, "contour_seed.");
  recipe.contour_dem.validate();
  if (recipe.dem.size && *recipe.dem.size > contour::max_contour_dem_side)
    fail("dem.size {} is not allowed for a contour mountain: it must be 2..{}", *recipe.dem.size, contour::max_contour_dem_side);
}

ContourInput contour_input(const Recipe& recipe, bool report_times) {
  ContourInput input;
  input.seed = recipe.contour_seed;
  const auto resolved = [&](const std::string& name) { return name.empty() ? std::filesystem::path() : resolve(recipe, name); };
  input.file = resolved(input.seed.file), input.from_dem = resolved(input.seed.from_dem);
  input.hypsometry = resolved(input.seed.hypsometry);
  input.generation = recipe.contour;
  input.dem = recipe.contour_dem;
  input.grid = recipe.dem;
  input.base_level = recipe.version >= 2;
  input.report_times = report_times;
  return input;
}

GrownContours grow_contours(ContourInput& input, const Context& context) {
  const ContourSeedParams& s = input.seed;
  contour::GenerationParams& params = input.generation;
  if (!params.z0_m) params.z0_m = s.level_m.value_or(0.0);

  // The seed contour, from a DEM at a level, the seed contours of a file (one mountain each), or
  // a ring given inline.
  SeedContours seed;
  GrownContours grown;
  if (!input.points.empty()) {
    contour::Ring ring;
    for (std::size_t i = 0; i + 1 < input.points.size(); i += 2) ring.push_back({input.points[i], input.points[i + 1]});
    contour::SeedContour normalised = contour::normalise_seed(std::move(ring), true, "the contour node's points");
    seed = {{std::move(normalised.ring)}, std::move(normalised.notes)};
  } else if (!input.from_dem.empty()) {
    grown.source_dem = read_heightmap_with_notes(input.from_dem, context);
    std::optional<contour::Point> pick;
    if (s.pick_m) pick = contour::Point{(*s.pick_m)[0], (*s.pick_m)[1]};
    contour::SeedContour picked = contour::normalise_seed(contour::pick_contour(*grown.source_dem, *s.level_m, pick), true, s.from_dem);
    seed = {{std::move(picked.ring)}, std::move(picked.notes)};
    if (!params.offset_m) {
      params.offset_m = offset_from_dem(*grown.source_dem, seed.rings.front(), params.interval_m);
      seed.notes.push_back(
          fmt::format("offset d = {:.1f} m from the DEM's mean slope inside the seed (set contour.offset to choose)", *params.offset_m));
    }
  } else {
    const auto format = io::seed_format_for(s.file);
    seed = parse_seeds(io::read_text_file(input.file), *format, s.file, s.svg_scale);
  }
  // Several seeds: d from the largest, so the others, smaller, make lower mountains. They move
  // together so that the largest one's centre stands at `at`.
  const contour::Ring& largest = *std::max_element(
      seed.rings.begin(), seed.rings.end(), [](const auto& a, const auto& b) { return contour::signed_area(a) < contour::signed_area(b); });
  if (!params.offset_m) {
    const double r = contour::inradius(largest);
    params.offset_m = contour::derived_offset_m(largest, params.interval_m);
    if (input.points.empty())
      seed.notes.push_back(fmt::format(
          "offset d = {:.1f} m from the {}seed's size (inradius {:.0f} m, target relief {:.0f} m, about {:.0f} levels at dz = {:g} m; "
          "set contour.offset to choose)",
          *params.offset_m, seed.rings.size() > 1 ? "largest " : "", r, contour::target_relief_m(r), r / *params.offset_m,
          params.interval_m));
  }
  if (input.at_m) {
    const contour::Point centre = contour::centroid(largest);
    const auto [east, north] = *input.at_m;
    for (contour::Ring& ring : seed.rings)
      for (contour::Point& point : ring) point.x += east - centre.x, point.y += north - centre.y;
  }
  params.validate();
  std::optional<contour::Hypsometry> hypsometry;
  if (!input.hypsometry.empty()) hypsometry = contour::Hypsometry{io::parse_hypsometry(io::read_text_file(input.hypsometry), s.hypsometry)};
  for (const auto& note : seed.notes) context.note(note);

  contour::GenerationTimes times;
  grown.tree = contour::generate_contours(seed.rings, params, context, &times);
  contour::ContourTree& tree = grown.tree;
  if (hypsometry) {
    int top = 0;
    for (const auto& node : tree.nodes) top = std::max(top, node.level);
    contour::apply_hypsometry(tree, *hypsometry, s.relief_m.value_or(std::max(1, top) * params.interval_m));
  }
  grown.lines.push_back(summary(tree, params));
  if (input.report_times)
    grown.lines.push_back(
        fmt::format("seconds: offset+union {:.3f}, midpoint {:.3f}, fourier {:.3f}, decimate {:.3f}, loops {:.3f}, clip {:.3f}",
                    times.offset_s, times.midpoint_s, times.fourier_s, times.decimate_s, times.loops_s, times.clip_s));
  return grown;
}

Produced contour_on_own_grid(ContourInput& input, const Needs& needs, const Context& context) {
  GrownContours grown = grow_contours(input, context);
  Produced produced;
  produced.lines = std::move(grown.lines);
  if (needs.heights) {
    const contour::DemParams dem = dem_params_for(input, grown.tree, grown.source_dem);
    produced.heights = contour::contours_to_dem(grown.tree, dem, context);
    // A flat plain around the mountain is base level for erosion (recipes of version 2): water
    // leaves there, and sediment does not fill it as if it were a closed basin.
    if (dem.surround == contour::Surround::flat && input.base_level) {
      double base = INFINITY;
      for (int root : grown.tree.roots()) base = std::min(base, grown.tree.nodes[static_cast<std::size_t>(root)].elevation_m);
      produced.base_level_m = dem.base_m.value_or(base);
    }
  }
  produced.tree = std::move(grown.tree);
  return produced;
}

Produced run_contour_source(Recipe& recipe, const Needs& needs, const RunOptions& options, const Context& context) {
  ContourInput input = contour_input(recipe, options.verbose);
  Produced produced = contour_on_own_grid(input, needs, context);
  recipe.contour = input.generation;  // the offset and z0 the run chose, for the sidecars
  return produced;
}

}  // namespace sansui::scene::detail
