// Node kinds that make and shape heights: sources (midpoint, constant, file, contour, contour_map) and shaping
// (stage, erode, terrace, smooth, scale, clamp). See node_kinds.hpp.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "contour/contours_to_dem.hpp"
#include "contour/generate.hpp"
#include "contour/scale.hpp"
#include "contour/to_dem.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"
#include "io/contour_lines_geojson.hpp"
#include "io/heightmap_io.hpp"
#include "io/text_file.hpp"
#include "scene/node_kinds.hpp"
#include "scene/seed_files.hpp"
#include "scene/sources.hpp"
#include "terrain/midpoint.hpp"
#include "terrain/stage_filter.hpp"
#include "water/erode.hpp"

namespace sansui::scene {

/// A constant height everywhere. [[node]] kind = "constant"
struct ConstantNode {
  double height_m = 0.0;  ///< [Units: m] [Default: 0]
};
const params::Table<ConstantNode>& parameter_table(const ConstantNode*) {
  static const auto table = params::Table<ConstantNode>("constant", "The same height everywhere")
                                .add(params::field("height", &ConstantNode::height_m).in(-1e5, 1e5).units("m").doc("The height"));
  return table;
}

/// A mountain grown from one contour line (seed 000), on the world's grid; in a world without one
/// (a chain's contour source), on its own. [[node]] kind = "contour"
struct ContourSourceNode {
  ContourSeedParams seed;      ///< the seed: a file, or a DEM at a level ([contour_seed]'s keys)
  std::vector<double> points;  ///< or the seed given inline: x0, y0, x1, y1, ... metres
  contour::GenerationParams generation;
  contour::DemParams dem = flat_surround();  ///< its surround and roughness ([contour_dem]'s keys)
  std::optional<double> fill_m;
  std::optional<std::array<double, 2>> at_m;
  // Only in a world without a grid of its own (a chain's [dem] size and cell, its contours output,
  // its verbose report and the rule of its version).
  std::optional<int> grid_size;
  std::optional<double> grid_cell_m;
  bool keep_tree = false;
  bool report_times = false;
  bool base_level = true;

  static contour::DemParams flat_surround() {
    contour::DemParams dem;
    dem.surround = contour::Surround::flat;
    return dem;
  }
};
const params::Table<ContourSourceNode>& parameter_table(const ContourSourceNode*) {
  using P = ContourSourceNode;
  static const auto table =
      params::Table<P>("contour", "A mountain grown from one contour line (Misawa et al.), on the world's grid, flat outside")
          .nest("", "", &P::seed, params::table_of<ContourSeedParams>())
          .add(params::field("points", &P::points)
                   .rule(
                       [](const params::Value& v) {
                         const auto n = std::get<std::vector<double>>(v).size();
                         return n == 0 || (n >= 6 && n % 2 == 0) ? std::string() : std::string("pairs x, y of at least 3 points");
                       },
                       "x, y pairs of at least 3 points")
                   .in(-contour::max_seed_coordinate_m, contour::max_seed_coordinate_m)
                   .units("m")
                   .unset("file's")
                   .doc("The seed contour given inline instead of file: x0, y0, x1, y1, ... (a ring, closed from the last point back to "
                        "the first; east and north), "
                        "as Python's sansui.contour(points) passes it"))
          .nest("", "", &P::generation, params::table_of<contour::GenerationParams>())
          .nest("", "", &P::dem, params::table_of<contour::DemParams>(), true)
          .add(params::field("fill", &P::fill_m)
                   .in(-1e5, 1e5)
                   .units("m")
                   .unset("z0; in a world without a grid, the lowest contour's")
                   .doc("The height of the plain around the mountain"))
          .add(params::field("at", &P::at_m)
                   .units("m")
                   .unset("the world's centre")
                   .doc("Where the seed's centre stands in the world, EAST,NORTH (north is 0 on the world's northern edge and "
                        "negative below it, as in every output's GeoJSON); in a world without a grid the seed stays where it is"))
          .add(params::field("grid_size", &P::grid_size)
                   .in(2, contour::max_contour_dem_side)
                   .unset("the world's grid; in a world without one, 1025, or a seed DEM's grid")
                   .doc("Only in a world without a grid of its own (a chain recipe's [dem] size): samples along the longer side "
                        "of a frame round the contours"))
          .add(params::field("grid_cell", &P::grid_cell_m)
                   .above(0)
                   .at_most(1e7)
                   .units("m")
                   .unset("the world's grid")
                   .doc("Only in a world without a grid of its own (a chain recipe's [dem] cell): the cell over that frame"))
          .add(params::field("keep_tree", &P::keep_tree)
                   .doc("Only in a world without a grid of its own: carry the contour lines beside the heights (a chain recipe's "
                        "contours and map outputs write them)"))
          .add(params::field("report_times", &P::report_times).doc("Add the seconds of each part of the generation to the run's report"))
          .add(params::field("base_level", &P::base_level)
                   .doc("Only in a world without a grid of its own: a flat plain around the mountain is erosion's base level "
                        "(false: the sea level alone, as chain recipes of version 1)"));
  return table;
}

/// A DEM interpolated from a given contour map (GeoJSON lines with their elevations), placed on
/// the world's grid. [[node]] kind = "contour_map"
struct ContourMapNode {
  std::string file;  ///< .geojson .json: LineString, MultiLineString, Polygon, MultiPolygon features
  std::string elevation_attribute;
  bool spot_heights = false;
  std::optional<std::array<double, 2>> at_m;
  // The map's own grid, in a world without one (a chain's [contour_map] grid_from and [dem]).
  std::string grid_from;
  std::optional<int> size;
  std::optional<double> cell_m;
  bool own_grid() const { return !grid_from.empty() || size || cell_m; }
};
const params::Table<ContourMapNode>& parameter_table(const ContourMapNode*) {
  using P = ContourMapNode;
  static const auto table =
      params::Table<P>("contour_map", "A DEM interpolated from a given contour map, on the world's grid")
          .add(params::path("file", &P::file).doc("The contour lines (.geojson .json), their coordinates in metres"))
          .add(params::field("elevation_attribute", &P::elevation_attribute)
                   .unset("the first of elev, ELEV, elevation, elevation_m, ELEVATION")
                   .doc("The features' property that holds the elevation in metres"))
          .add(params::field("spot_heights", &P::spot_heights).doc("Also read Point features as spot heights (shape summits and pits)"))
          .add(params::field("at", &P::at_m)
                   .units("m")
                   .unset("the world's centre")
                   .doc("Where the centre of the map's extent stands in the world, EAST,NORTH (north is 0 on the world's northern "
                        "edge and negative below it)"))
          .add(params::path("grid_from", &P::grid_from)
                   .doc("Only in a world without a grid of its own (a chain recipe's [contour_map] grid_from): a heightmap whose "
                        "grid (size, cell, place) the DEM takes"))
          .add(params::field("grid_size", &P::size)
                   .in(2, contour::max_contour_dem_side)
                   .unset("the world's grid; in a world without one, a cell of the lines' vertex spacing")
                   .doc("Only in a world without a grid of its own (a chain recipe's [dem] size): samples along the longer side "
                        "of the lines' extent"))
          .add(params::field("grid_cell", &P::cell_m)
                   .above(0)
                   .at_most(1e7)
                   .units("m")
                   .unset("the world's grid; in a world without one, the lines' vertex spacing")
                   .doc("Only in a world without a grid of its own (a chain recipe's [dem] cell): the cell over the lines' extent"));
  return table;
}

/// The paper's geomorphic stage filter. [[node]] kind = "stage"
struct StageNode {
  terrain::Stage stage = terrain::Stage::mature;
  bool paper_exact = false;
  std::optional<double> sigma_m;
};
const params::Table<StageNode>& parameter_table(const StageNode*) {
  using P = StageNode;
  static const auto table =
      params::Table<P>("stage", "The paper's geomorphic stage filter on the height above sea level (no erosion)")
          .add(params::choice("stage", &P::stage, terrain::stage_choices())
                   .doc("Stage: original x^0.1, young x^0.5, mature x, old, peneplain; x = height above sea level / sigma"))
          .add(params::field("paper_exact", &P::paper_exact).doc("The paper's printed old/peneplain filters, which jump at x = 1"))
          .add(params::field("sigma", &P::sigma_m).above(0).units("m").unset("the heights' standard deviation").doc("The unit of x"));
  return table;
}

/// Flat steps at a height interval (agricultural terraces, stepped strata). [[node]] kind = "terrace"
struct TerraceNode {
  double interval_m = 20.0;
  double riser = 0.2;
};
const params::Table<TerraceNode>& parameter_table(const TerraceNode*) {
  using P = TerraceNode;
  static const auto table = params::Table<P>("terrace", "Flat steps every interval metres, where the mask is 1 (everywhere without one)")
                                .add(params::field("interval", &P::interval_m).above(0).at_most(1e4).units("m").doc("Height of one step"))
                                .add(params::field("riser", &P::riser)
                                         .in(0, 1)
                                         .no_unit()
                                         .doc("Share of each step that rises to the next (0: vertical risers, 1: no flat)"));
  return table;
}

/// A smoothing (three box blurs: about a Gaussian). [[node]] kind = "smooth"
struct SmoothNode {
  double radius_m = 30.0;
};
const params::Table<SmoothNode>& parameter_table(const SmoothNode*) {
  static const auto table = params::Table<SmoothNode>("smooth", "A smoothing, where the mask is 1 (everywhere without one)")
                                .add(params::field("radius", &SmoothNode::radius_m)
                                         .at_least(0)
                                         .at_most(1e5)
                                         .units("m")
                                         .doc("Radius of the smoothing (about the Gaussian's standard deviation)"));
  return table;
}

/// heights x gain + offset. [[node]] kind = "scale"
struct ScaleNode {
  double gain = 1.0;
  double offset_m = 0.0;
};
const params::Table<ScaleNode>& parameter_table(const ScaleNode*) {
  static const auto table = params::Table<ScaleNode>("scale", "Heights times gain plus offset")
                                .add(params::field("gain", &ScaleNode::gain).in(-1e3, 1e3).no_unit().doc("Factor on the heights"))
                                .add(params::field("offset", &ScaleNode::offset_m).in(-1e5, 1e5).units("m").doc("Added after the factor"));
  return table;
}

/// Heights kept between a lowest and a highest value. [[node]] kind = "clamp"
struct ClampNode {
  std::optional<double> min_m, max_m;
};
const params::Table<ClampNode>& parameter_table(const ClampNode*) {
  static const auto table =
      params::Table<ClampNode>("clamp", "Heights kept between min and max")
          .add(params::field("min", &ClampNode::min_m).in(-1e5, 1e5).units("m").unset("no floor").doc("Lowest height"))
          .add(params::field("max", &ClampNode::max_m).in(-1e5, 1e5).units("m").unset("no ceiling").doc("Highest height"));
  return table;
}

namespace {

/// `heights` placed on the world's grid (its cell size and place); in a world without a grid, where
/// the source's own.
Heightfield on_world_grid(Heightfield heights, const GraphWorld& world) {
  if (!world.has_grid()) return heights;
  heights.cell_size_m = world.cell_m;
  heights.origin_x_m = world.origin_x_m, heights.origin_y_m = world.origin_y_m;
  return heights;
}

/// Refuses a source that needs the world's grid in a world that takes its source's.
void need_grid(const GraphWorld& world, std::string_view kind) {
  if (!world.has_grid()) fail("a {} node makes its heights on the world's grid: give [world] size", kind);
}

/// heights + mask x (shaped - heights): the change only where the mask says, softly.
Heightfield masked(const Heightfield& heights, Heightfield shaped, const Grid<float>* mask) {
  if (mask == nullptr) return shaped;
  parallel_for(0, shaped.height(), [&](int y) {
    for (int x = 0; x < shaped.width(); ++x) {
      const float m = (*mask)(x, y);
      shaped(x, y) = heights(x, y) * (1.0f - m) + shaped(x, y) * m;
    }
  });
  return shaped;
}

Heightfield run_midpoint(const terrain::MidpointParams& p, std::span<const Grid<float>* const>, const GraphWorld& world,
                         const Context& context) {
  need_grid(world, "midpoint");
  if (!world.square()) fail("a midpoint node needs a square world; the world is {}x{}", world.width, world.height);
  const int levels = terrain::levels_for_size(world.width);
  if (levels < 1) fail("a midpoint node needs a world of 2^k+1 samples a side (3, 5, 9 ... 16385); [world] size is {}", world.width);
  // Unset, the relief follows the world's extent, as the midpoint source's does (recipes of
  // version 4): the same keys give the same terrain in a graph, a source and from Python.
  terrain::MidpointParams q = p;
  if (!q.sigma_m) q.sigma_m = terrain::default_sigma_for_extent(static_cast<double>(world.width - 1) * world.cell_m, q.hurst);
  Heightfield h = terrain::generate_midpoint(q, world.width, context);
  const auto offset =
      static_cast<float>(terrain::sea_level_offset(q, levels, context) - world.midpoint_datum_m.value_or(world.sea_level_m));
  if (offset != 0.0f)
    for (float& v : h.values()) v -= offset;
  return on_world_grid(std::move(h), world);
}

NodeOutput run_contour_map(const ContourMapNode& p, std::span<const Grid<float>* const>, const GraphWorld& world, const Context& context) {
  if (p.file.empty()) fail("a contour_map node needs file: the contour lines (.geojson)");
  if (!world.has_grid()) {  // the map's own grid: the contour_map source of a chain
    detail::Produced made = detail::contour_map_on_own_grid({world.resolve(p.file), p.elevation_attribute, p.spot_heights,
                                                             p.grid_from.empty() ? "" : world.resolve(p.grid_from), p.size, p.cell_m},
                                                            context);
    NodeOutput out(std::move(*made.heights));
    out.statistics = std::move(made.statistics);
    return out;
  }
  if (p.own_grid())
    fail(
        "a contour_map node on a world with a grid takes it: grid_from, grid_size and grid_cell are for a chain recipe's [contour_map] and "
        "[dem]");
  const contour::ContourMap map = detail::read_contour_map(world.resolve(p.file), p.elevation_attribute, p.spot_heights);
  // The extent's centre, in the map's coordinates (x east, y north).
  double min_x = HUGE_VAL, max_x = -HUGE_VAL, min_y = HUGE_VAL, max_y = -HUGE_VAL;
  auto extend = [&](const contour::Point& q) {
    min_x = std::min(min_x, q.x), max_x = std::max(max_x, q.x), min_y = std::min(min_y, q.y), max_y = std::max(max_y, q.y);
  };
  for (const contour::ContourLine& line : map.lines)
    for (const contour::Point& q : line.points) extend(q);
  for (const contour::SpotHeight& spot : map.spots) extend(spot.at);
  const std::array<double, 2> at = p.at_m.value_or(world.centre_m());
  const double centre_x = 0.5 * (min_x + max_x), centre_y = 0.5 * (min_y + max_y);
  // World sample (c, r) stands at (c cell, -r cell); in the map's coordinates that is
  // (c cell + centre_x - at_x, -r cell + centre_y - at_y). Row 0 is north (origin_y is -north).
  const contour::ContourMapGrid grid{world.width, world.height, world.cell_m, centre_x - at[0], at[1] - centre_y};
  NodeOutput out(on_world_grid(contour::contour_map_to_dem(map, grid, context), world));
  out.statistics = detail::contour_map_statistics(map);
  return out;
}

/// A heightmap file: [file] of a chain, whose world is the file's grid, or a [[node]] of that kind
/// on the world's grid, whose size it must have.
Heightfield run_file(const FileSourceParams& p, std::span<const Grid<float>* const>, const GraphWorld& world, const Context& context) {
  if (p.path.empty()) fail("a file node needs path: the heightmap to read");
  io::HeightmapReadOptions options;
  options.cell_size_m = p.cell_m;
  if (p.range_m) options.range = io::HeightRange{(*p.range_m)[0], (*p.range_m)[1]};
  Heightfield h = detail::read_heightmap_with_notes(world.resolve(p.path), context, options);
  if (world.has_grid() && (h.width() != world.width || h.height() != world.height))
    fail("the file node's {} is {}x{} samples; the world is {}x{} ([world] size)", p.path, h.width(), h.height(), world.width,
         world.height);
  return on_world_grid(std::move(h), world);
}

void check_contour_node(const ContourSourceNode& p) {
  params::validate(p);
  detail::check_contour_seed(p.seed, !p.points.empty(), p.generation, "");
  if (p.grid_size && p.grid_cell_m) fail("a contour node takes grid_size or grid_cell, not both");
}

/// The contour source's input from the node's keys, paths resolved in `world`.
detail::ContourInput input_of(const ContourSourceNode& p, const GraphWorld& world) {
  detail::ContourInput input;
  input.seed = p.seed;
  const auto resolved = [&](const std::string& name) { return name.empty() ? std::filesystem::path() : world.resolve(name); };
  input.file = resolved(p.seed.file), input.from_dem = resolved(p.seed.from_dem), input.hypsometry = resolved(p.seed.hypsometry);
  input.points = p.points;
  input.generation = p.generation;
  input.dem = p.dem;
  input.grid = {p.grid_size, p.grid_cell_m, p.fill_m};
  input.base_level = p.base_level;
  input.report_times = p.report_times;
  return input;
}

/// In a world without a grid (a chain's contour source): the mountain on its own grid, with the
/// plain's base level, the offset and z0 the run chose and, with keep_tree, the contours.
NodeOutput run_contour_on_own_grid(const ContourSourceNode& p, detail::ContourInput& input, const Context& context) {
  if (p.at_m) fail("a contour node in a world without a grid keeps its seed where it is: at is for a world with a grid");
  detail::Produced made = detail::contour_on_own_grid(input, {.heights = true}, context);
  NodeOutput out(std::move(*made.heights));
  out.lines = std::move(made.lines);
  out.base_level_m = made.base_level_m;
  out.settled = {{"offset", *input.generation.offset_m}, {"z0", *input.generation.z0_m}};
  if (p.keep_tree) out.tree = std::make_shared<const contour::ContourTree>(std::move(*made.tree));
  return out;
}

NodeOutput run_contour(const ContourSourceNode& p, std::span<const Grid<float>* const>, const GraphWorld& world, const Context& context) {
  check_contour_node(p);
  detail::ContourInput input = input_of(p, world);
  if (!world.has_grid()) return run_contour_on_own_grid(p, input, context);
  if (p.grid_size || p.grid_cell_m || p.keep_tree)
    fail("a contour node on a world with a grid takes it: grid_size, grid_cell and keep_tree are for a chain recipe's [dem] and outputs");
  input.at_m = p.at_m.value_or(world.centre_m());
  detail::GrownContours grown = detail::grow_contours(input, context);
  contour::DemParams dem = input.dem;
  dem.width = world.width, dem.height = world.height;
  dem.cell_m = world.cell_m;
  dem.base_m = p.fill_m.value_or(input.generation.resolved_z0_m());
  dem.offset_m = input.generation.resolved_offset_m();
  dem.seed = input.generation.seed;
  NodeOutput out(on_world_grid(contour::contours_to_dem(grown.tree, dem, context), world));
  out.lines = std::move(grown.lines);
  return out;
}

Heightfield run_stage(const StageNode& p, std::span<const Grid<float>* const> in, const GraphWorld& world, const Context&) {
  terrain::StageFilterParams filter;
  filter.stage = p.stage, filter.paper_exact = p.paper_exact, filter.sigma_m = p.sigma_m, filter.sea_level_m = world.sea_level_m;
  Heightfield h = *in[0];
  terrain::apply_stage_filter(h, filter);
  return masked(*in[0], std::move(h), in[1]);
}

/// The metres an erosion carved or laid down where the mask lets it act (all of them without a
/// mask; none where the erosion made no such map).
Grid<float> masked_metres(Grid<float> metres, const Heightfield& heights, const Grid<float>* mask) {
  if (metres.empty()) {
    metres = Grid<float>(heights.width(), heights.height(), 0.0f);
    metres.cell_size_m = heights.cell_size_m, metres.origin_x_m = heights.origin_x_m, metres.origin_y_m = heights.origin_y_m;
  }
  if (mask != nullptr)
    for (std::size_t i = 0; i < metres.size(); ++i) metres.values()[i] *= mask->values()[i];
  return metres;
}

/// The recipe version whose erosion model the world's erode nodes take: 1 for model 1 (a chain of
/// version 1), else this sansui's.
int erosion_version(const GraphWorld& world) {
  return world.version != 0 ? world.version : recipe_version;
}

/// An erode node on heights routed as `routing_of_heights` (a flow node's), or null: routed here.
NodeOutput erode_node(const ShapeStep& p, std::span<const Grid<float>* const> in, const water::FlowRouting* routing_of_heights,
                      const GraphWorld& world, const Context& context) {
  ShapeStep step = p;
  step.step = StepKind::erode;
  step.stage.sea_level_m = world.sea_level_m;
  water::ErosionResult eroded = detail::erode_with(step, erosion_version(world), *in[0], world.base_level_m, context, routing_of_heights);
  NodeOutput out(masked(*in[0], std::move(eroded.heights), in[1]));
  out.layers.emplace(std::string(eroded_layer), masked_metres(std::move(eroded.eroded_m), *in[0], in[1]));
  out.layers.emplace(std::string(deposited_layer), masked_metres(std::move(eroded.deposited_m), *in[0], in[1]));
  return out;
}

NodeOutput run_erode(const ShapeStep& p, std::span<const Grid<float>* const> in, const GraphWorld& world, const Context& context) {
  return erode_node(p, in, nullptr, world, context);
}

Heightfield run_terrace(const TerraceNode& p, std::span<const Grid<float>* const> in, const GraphWorld& world, const Context&) {
  Heightfield h = *in[0];
  const double t = p.interval_m, flat = 1.0 - p.riser;
  parallel_for(0, h.height(), [&](int y) {
    for (int x = 0; x < h.width(); ++x) {
      const double v = static_cast<double>(h(x, y)) - world.sea_level_m;
      const double step = std::floor(v / t), within = v / t - step;
      // Flat for the first `flat` of each step, then a straight riser up to the next.
      const double rise = within <= flat ? 0.0 : (within - flat) / p.riser;
      h(x, y) = static_cast<float>(world.sea_level_m + (step + rise) * t);
    }
  });
  return masked(*in[0], std::move(h), in[1]);
}

/// One pass of a box blur of radius r along rows (clamped at the edges), in place.
void box_rows(Heightfield& h, int r) {
  parallel_for(0, h.height(), [&](int y) {
    const std::span<float> row = h.row(y);
    std::vector<double> prefix(row.size() + 1, 0.0);
    for (std::size_t x = 0; x < row.size(); ++x) prefix[x + 1] = prefix[x] + row[x];
    const int w = h.width();
    for (int x = 0; x < w; ++x) {
      const int a = std::max(0, x - r), b = std::min(w - 1, x + r);
      row[static_cast<std::size_t>(x)] =
          static_cast<float>((prefix[static_cast<std::size_t>(b) + 1] - prefix[static_cast<std::size_t>(a)]) / (b - a + 1));
    }
  });
}

Heightfield transposed(const Heightfield& h) {
  Heightfield t(h.height(), h.width(), 0.0f, h.cell_size_m);
  for (int y = 0; y < h.height(); ++y)
    for (int x = 0; x < h.width(); ++x) t(y, x) = h(x, y);
  return t;
}

Heightfield run_smooth(const SmoothNode& p, std::span<const Grid<float>* const> in, const GraphWorld& world, const Context&) {
  // Three box blurs of radius r have a standard deviation of about r (sqrt(3 ((2r+1)^2 - 1) / 12)).
  const int r = static_cast<int>(std::lround(p.radius_m / world.cell_m));
  Heightfield h = *in[0];
  if (r <= 0) return h;
  for (int pass = 0; pass < 3; ++pass) box_rows(h, r);
  h = transposed(h);
  for (int pass = 0; pass < 3; ++pass) box_rows(h, r);
  h = transposed(h);
  h.copy_metadata_from(*in[0]);
  return masked(*in[0], std::move(h), in[1]);
}

Heightfield run_scale(const ScaleNode& p, std::span<const Grid<float>* const> in, const GraphWorld&, const Context&) {
  Heightfield h = *in[0];
  for (float& v : h.values()) v = static_cast<float>(v * p.gain + p.offset_m);
  return h;
}

Heightfield run_clamp(const ClampNode& p, std::span<const Grid<float>* const> in, const GraphWorld&, const Context&) {
  if (p.min_m && p.max_m && *p.min_m > *p.max_m) fail("a clamp node's min {} is above its max {}", *p.min_m, *p.max_m);
  Heightfield h = *in[0];
  for (float& v : h.values()) {
    if (p.min_m) v = std::max(v, static_cast<float>(*p.min_m));
    if (p.max_m) v = std::min(v, static_cast<float>(*p.max_m));
  }
  return h;
}

/// The kind without these keys of its params struct's table (world facts, or the step's kind).
NodeKind without_keys(NodeKind kind, std::vector<std::string> keys) {
  std::erase_if(kind.rows, [&](const params::ParamInfo& row) { return std::find(keys.begin(), keys.end(), row.key) != keys.end(); });
  kind.set = [set = kind.set, keys](std::any& params, std::string_view key, const params::Value& value) {
    return std::find(keys.begin(), keys.end(), key) == keys.end() && set(params, key, value);
  };
  return kind;
}

}  // namespace

void add_terrain_kinds(std::vector<NodeKind>& kinds) {
  using V = ValueType;
  const InputSlot heights{"heights", V::heights, false}, mask{"mask", V::mask, true};
  kinds.push_back(kind_of<terrain::MidpointParams>(
      "midpoint", "source", "Fractal terrain by midpoint displacement (Oka et al. 1997), land_fraction of it above sea level", {},
      V::heights, run_midpoint));
  kinds.push_back(kind_of<ConstantNode>(
      "constant", "source", "The same height everywhere", {}, V::heights,
      [](const ConstantNode& p, std::span<const Grid<float>* const>, const GraphWorld& world, const Context&) {
        need_grid(world, "constant");
        return on_world_grid(Heightfield(world.width, world.height, static_cast<float>(p.height_m), world.cell_m), world);
      }));
  kinds.push_back(kind_of<FileSourceParams>(
      "file", "source", "A heightmap file of the world's size (in a chain, the world takes the file's grid)", {}, V::heights, run_file));
  kinds.push_back(kind_of<ContourSourceNode>("contour", "source",
                                             "A mountain grown from one contour line (Misawa et al.), flat at z0 around it, on the "
                                             "world's grid (in a chain, on its own)",
                                             {}, V::heights, run_contour));
  kinds.push_back(kind_of<ContourMapNode>(
      "contour_map", "source", "A DEM interpolated from a given contour map (GeoJSON lines with elevations), on the world's grid", {},
      V::heights, run_contour_map));
  kinds.push_back(
      kind_of<StageNode>("stage", "shaping", "The paper's geomorphic stage filter (no erosion)", {heights, mask}, V::heights, run_stage));
  kinds.push_back(without_keys(kind_of<ShapeStep>("erode", "shaping",
                                                  "Erosion: stream power, diffusion, droplets; `stage` is the erosion time "
                                                  "(docs/erosion.md); where the mask is 1, if one is given",
                                                  {heights, mask}, V::heights, run_erode),
                               {"step", "sea_level"}));
  kinds.back().layers = {std::string(eroded_layer), std::string(deposited_layer)};
  set_run_routed<ShapeStep>(
      kinds.back(), [](const ShapeStep& p, std::span<const Grid<float>* const> in, const water::FlowRouting& flow, const GraphWorld& world,
                       const Context& context) { return erode_node(p, in, &flow, world, context); });
  kinds.back().scratch_bytes_per_cell = 100.0;  // routing, stack, lakes, areas and the chain's grids
  kinds.back().seconds = [](const std::any& params, const GraphWorld& world) {
    const auto& step = std::any_cast<const ShapeStep&>(params);
    const detail::ErosionPlan plan = detail::plan_erosion(step, erosion_version(world), world.base_level_m);
    return water::estimated_erosion_seconds(static_cast<std::size_t>(world.cells()), plan.chain, plan.stage.has_value());
  };
  kinds.push_back(kind_of<TerraceNode>("terrace", "shaping", "Flat steps at a height interval, where the mask is 1", {heights, mask},
                                       V::heights, run_terrace));
  kinds.push_back(kind_of<SmoothNode>("smooth", "shaping", "A smoothing, where the mask is 1", {heights, mask}, V::heights, run_smooth));
  kinds.back().seconds = [](const std::any&, const GraphWorld& world) { return 1e-7 * world.cells(); };
  kinds.push_back(kind_of<ScaleNode>("scale", "shaping", "Heights times gain plus offset", {heights}, V::heights, run_scale));
  kinds.push_back(kind_of<ClampNode>("clamp", "shaping", "Heights kept between min and max", {heights}, V::heights, run_clamp));
}

}  // namespace sansui::scene
