#include "scene/pipeline.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <string_view>
#include <unordered_set>

#include <fmt/format.h>

#include "core/budget.hpp"
#include "core/error.hpp"
#include "core/params_text.hpp"
#include "io/atomic_file.hpp"
#include "io/crs.hpp"
#include "io/extension.hpp"
#include "io/file_formats.hpp"
#include "scene/evaluator.hpp"
#include "scene/georeference.hpp"
#include "scene/look.hpp"
#include "scene/output_kinds.hpp"
#include "scene/output_plan.hpp"
#include "scene/outputs.hpp"
#include "scene/plants.hpp"
#include "scene/recipe_budget.hpp"
#include "scene/recipe_file.hpp"
#include "scene/sources.hpp"
#include "scene/tiled_world.hpp"
#include "terrain/stage_filter.hpp"
#include "water/erode.hpp"

namespace sansui::scene {
namespace detail {

std::filesystem::path resolve(const Recipe& recipe, const std::string& path) {
  const std::filesystem::path p(path);
  return p.is_absolute() || recipe.base_dir.empty() ? p : recipe.base_dir / p;
}

double recipe_sea_level(const Recipe& recipe) {
  if (recipe.version >= 3) return recipe.world.sea_level_m;
  for (const ShapeStep& step : recipe.shape)
    if (step.step == StepKind::stage) return step.stage.sea_level_m;
  return 0.0;
}

}  // namespace detail

namespace {

/// The erosion model of a recipe version (water/erode.hpp): 1 for version 1, 2 for versions 2 to
/// 5, 3 for version 6, 4 since.
int erosion_model(int version) {
  return version == 1 ? 1 : version < 6 ? 2 : version == 6 ? 3 : 4;
}

/// What a node's result gives the outputs: its heights (placed on the world's grid, where [world]
/// origin puts a generated world, as check_world_origin allows) and the metres its erosions carved
/// and laid down.
detail::Produced produced_of(const NodeProducts& products, const WorldParams& world) {
  detail::Produced produced;
  produced.heights = *products.grid;
  if (const auto eroded = products.layers.find(std::string(eroded_layer)); eroded != products.layers.end())
    produced.eroded_m = *eroded->second;
  if (const auto deposited = products.layers.find(std::string(deposited_layer)); deposited != products.layers.end())
    produced.deposited_m = *deposited->second;
  produced.routed = {products.flow, world.sea_level_m};  // a flow node's outlets: the world's sea
  if (products.report) produced.statistics = products.report->statistics, produced.lines = products.report->lines;
  if (products.mesh) produced.mesh = *products.mesh;
  if (products.tree) produced.tree = *products.tree;
  return produced;
}

/// The evaluator a run uses: the caller's, whose caches outlive the run, or one for this run that
/// keeps results only while a later node needs them (the graph's memory budget).
std::shared_ptr<Evaluator> run_evaluator(const RunOptions& options) {
  if (options.evaluator) return options.evaluator;
  auto evaluator = std::make_shared<Evaluator>();
  evaluator->keep_in_memory(0);
  return evaluator;
}

/// Progress of a chain run as a graph, under the stages a chain has always shown ("terrain",
/// "erosion"): a node's own stages without its id in front, and not the node's start and end.
Context chain_progress(const Context& context, const std::vector<GraphNode>& nodes) {
  Context chain = context;
  if (!context.on_progress) return chain;
  std::vector<std::string> ids;
  ids.reserve(nodes.size());
  for (const GraphNode& node : nodes) ids.push_back(node.id);
  chain.on_progress = [&context, ids](std::string_view stage, double fraction) {
    for (const std::string& id : ids) {
      if (stage == id) return;
      if (stage.starts_with(id + ": ")) stage.remove_prefix(id.size() + 2);
    }
    context.on_progress(stage, fraction);
  };
  return chain;
}

bool has_source_of_heights(const Recipe& recipe) {
  return recipe.source != SourceKind::none || !recipe.nodes.empty();
}

/// What the outputs ask of the source.
detail::Needs needs_of(const Recipe& recipe) {
  detail::Needs needs;
  for (const Output& output : recipe.outputs) {
    switch (output_kind_info(*resolved_kind(output)).input) {
      case OutputInput::contour_tree:
        needs.tree = true;
        break;
      case OutputInput::mesh:
        if (recipe.source == SourceKind::mesh)
          needs.mesh = true;
        else
          needs.heights = true;
        break;
      case OutputInput::nothing:
        break;
      case OutputInput::heights:
        needs.heights = true;
        break;
    }
  }
  return needs;
}

std::string list(const std::vector<std::string>& items) {
  std::string text;
  for (const auto& item : items) text += (text.empty() ? "" : " ") + item;
  return text;
}

std::vector<std::string> camera_names(const Recipe& recipe) {
  std::vector<std::string> names{recipe.render.camera.name};
  for (const look::Camera& camera : recipe.more_cameras) names.push_back(camera.name);
  return names;
}

/// An erosion_map or deposition_map output needs an erosion: an erode step in a chain; in a graph,
/// an erode node or a shaping node after one (the nodes that carry the erosion's layers).
void check_erosion_output(const Recipe& recipe, std::size_t index, const std::string& name) {
  const Output& output = recipe.outputs[index];
  if (recipe.nodes.empty()) {
    if (std::ranges::none_of(recipe.shape, [](const ShapeStep& s) { return s.step == StepKind::erode; }))
      fail("{} output {} needs an erode step: add [[shape]] step = \"erode\" (or --erode on the command line)", name, output.file);
    return;
  }
  const GraphNode& node = output_node(recipe, index);
  if (std::ranges::count(layers_of(recipe.nodes, node.id), eroded_layer) == 0)
    fail(
        "{} output {} takes node `{}` ({}), which carries no erosion: name an erode node, or a shaping node after one "
        "(blends, masks and sources do not carry erosion maps)",
        name, output.file, node.id, node.kind);
}

/// Every output: a name without control characters that stays where it may (check_output_names),
/// a kind that fits the source, an extension that fits the kind, a directory that can be
/// written; then every file of the run checked as a whole (plan_outputs: no two the same, none
/// an input, none a device, FIFO or link).
void check_outputs(const Recipe& recipe) {
  if (recipe.outputs.empty()) fail("no output: the recipe writes nothing (add an [[output]], or -o FILE on the command line)");
  check_output_names(recipe);
  for (std::size_t index = 0; index < recipe.outputs.size(); ++index) {
    const Output& output = recipe.outputs[index];
    const auto kind = resolved_kind(output);
    if (!kind)
      fail("output {} has an unknown extension '{}': a kind is taken {}; or name its kind", output.file, io::lower_extension(output.file),
           inferred_kinds_text());
    const OutputKindInfo& info = output_kind_info(*kind);
    const std::string name(info.name);
    if (output.file.empty()) {
      if (info.printed) continue;
      fail("a {} output has no file name", name);
    }
    const auto extensions = extensions_for(*kind);
    const std::string extension = io::lower_extension(output.file);
    if (std::find(extensions.begin(), extensions.end(), extension) == extensions.end())
      fail("{} output {} has the extension '{}': allowed are {}", name, output.file, extension, list(extensions));
    const bool needs_contours = info.input == OutputInput::contour_tree;
    if (needs_contours && recipe.source != SourceKind::contour)
      fail("{} output {} needs a contour source (source is {})", name, output.file, source_name(recipe.source));
    if (info.input != OutputInput::nothing && !needs_contours && !has_source_of_heights(recipe))
      fail("{} output {} needs a heightfield: give a source (midpoint, file, contour or mesh)", name, output.file);
    if (*kind == OutputKind::tree) check_tree_species(recipe);
    if (info.erode_step) check_erosion_output(recipe, index, name);
    if (!output.camera.empty() && *kind != OutputKind::render)
      fail("{} output {} names camera \"{}\": only render outputs have a camera", name, output.file, output.camera);
    if (camera_for(recipe, output) == nullptr)
      fail("render output {} names camera \"{}\": the scene's cameras are {}", output.file, output.camera, list(camera_names(recipe)));
    io::check_writable(detail::resolve(recipe, output.file));
  }
  plan_outputs(recipe);
}

/// Cameras must be told apart: each of several has a name, no two the same.
void check_cameras(const Recipe& recipe) {
  if (recipe.more_cameras.empty()) return;
  for (const look::Camera& camera : recipe.more_cameras) camera.validate();
  const std::vector<std::string> names = camera_names(recipe);
  std::unordered_set<std::string_view> seen;  // linear: a scene may have thousands of cameras
  for (const std::string& name : names) {
    if (name.empty()) fail("a scene with {} cameras must name each: [[camera]] name = \"...\"", names.size());
    if (!seen.insert(name).second) fail("two cameras are named \"{}\": names must differ", name);
  }
}

void check_sections(const Recipe& recipe) {
  const params::Table<Recipe>& table = recipe_table();
  for (const Section& section : recipe_sections()) {
    if (!section_used(recipe, section)) continue;
    for (const auto& row : table.rows)
      if (section_of(row.key) == section.name) params::require_allowed(row, row.get(recipe), row.key);
  }
  for (const ShapeStep& step : recipe.shape) {
    params::validate(step);
    if (step.step == StepKind::erode) step.erosion.fluvial.validate();
  }
}

void check_source(const Recipe& recipe) {
  detail::source_entry(recipe.source).check(recipe);
}

detail::Produced run_source_kind(Recipe& recipe, const detail::Needs& needs, const RunOptions& options, const Context& context) {
  return detail::source_entry(recipe.source).run(recipe, needs, options, context);
}

/// The source's products, with the outputs' coordinate system: found (and inputs in degrees
/// refused) before any work.
detail::Produced run_source(Recipe& recipe, const detail::Needs& needs, const RunOptions& options, const Context& context) {
  std::vector<std::string> notes;
  std::optional<io::Crs> crs = detail::output_crs(recipe, notes);
  for (const auto& note : notes) context.note(note);
  detail::Produced produced = run_source_kind(recipe, needs, options, context);
  produced.crs = std::move(crs);
  return produced;
}

water::ErosionStage erosion_stage(terrain::Stage stage) {
  switch (stage) {
    case terrain::Stage::young:
      return water::ErosionStage::young;
    case terrain::Stage::old:
      return water::ErosionStage::old;
    case terrain::Stage::peneplain:
      return water::ErosionStage::peneplain;
    case terrain::Stage::original:
    case terrain::Stage::mature:
      break;
  }
  return water::ErosionStage::mature;
}

/// One line on an erode step's erosion, for --explain and the run's report.
std::string erosion_summary(const ShapeStep& step, int version) {
  const int model = erosion_model(version);
  const water::ErosionChainParams& chain = step.erosion;
  const std::string time = !step.time_from_stage ? fmt::format("{} steps of {:g} yr", chain.fluvial.steps, chain.fluvial.time_step_yr)
                           : step.stage.stage == terrain::Stage::original
                               ? std::string("no stream power")
                               : fmt::format("{:g} response times of stream power in {} steps",
                                             water::stage_response_times(erosion_stage(step.stage.stage), model), chain.fluvial.steps);
  const std::string diffusion = chain.fluvial.diffusivity_m2_per_yr
                                    ? fmt::format("{:g} m^2/yr", *chain.fluvial.diffusivity_m2_per_yr)
                                    : fmt::format("{:g} cells^2 per response time", water::diffusion_per_tau);
  const std::string droplets = chain.droplets.droplets ? fmt::format("{} droplets", *chain.droplets.droplets)
                                                       : fmt::format("{:g} droplets per cell", chain.droplets.droplets_per_cell);
  return fmt::format("{} (model {}), uplift {:g} m/yr, diffusion {}, {} thermal iterations, {}, fine detail kept x{:g}", time, model,
                     chain.fluvial.uplift_m_per_yr, diffusion, chain.thermal.iterations, droplets, chain.keep_detail);
}

/// Work estimated over this is announced with its expected time before it starts. [Units: s]
constexpr double announced_work_s = 30.0;

}  // namespace

detail::ErosionPlan detail::plan_erosion(const ShapeStep& step, int version, std::optional<double> base_level_m) {
  ErosionPlan plan;
  plan.model = erosion_model(version);
  plan.chain = step.erosion;
  plan.chain.fluvial.sea_level_m = std::max(step.stage.sea_level_m, base_level_m.value_or(step.stage.sea_level_m));
  if (step.time_from_stage) {
    if (step.stage.stage == terrain::Stage::original)
      plan.chain.fluvial.steps = 0;
    else
      plan.stage = erosion_stage(step.stage.stage);
  }
  return plan;
}

namespace {

/// What one erode step costs on a width x height grid, as erode_with checks it.
budget::Cost erosion_cost(const ShapeStep& step, const detail::ErosionPlan& plan, int width, int height) {
  const bool from_stage = plan.stage.has_value();
  water::ErosionChainParams planned = step.erosion;
  planned.fluvial.sea_level_m = plan.chain.fluvial.sea_level_m;
  const std::size_t cells = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  budget::Cost cost;
  cost.seconds = water::estimated_erosion_seconds(cells, planned, from_stage);
  cost.what = fmt::format("the erosion of {}x{} cells ({} stream-power steps, {} thermal iterations, {} droplets)", width, height,
                          step.erosion.fluvial.steps, plan.chain.thermal.iterations, water::droplet_count(plan.chain.droplets, cells));
  cost.smaller = "lower erosion_steps, thermal_iterations or droplets";
  return cost;
}

}  // namespace

water::ErosionResult detail::erode_with(const ShapeStep& step, int version, const Heightfield& heights, std::optional<double> base_level_m,
                                        const Context& context, const water::FlowRouting* routing_of_heights) {
  const ErosionPlan plan = plan_erosion(step, version, base_level_m);
  const budget::Cost cost = erosion_cost(step, plan, heights.width(), heights.height());
  budget::check(cost, step.force);
  if (cost.seconds > announced_work_s)
    context.note(fmt::format("{} will take about {} on 2 cores", cost.what, budget::format_seconds(cost.seconds)));
  // One bar for the whole erosion. The routing given is under the step's sea level: it is taken
  // only where that is the erosion's base level too (no higher base level of the source's).
  const bool same_outlets =
      routing_of_heights != nullptr && plan.chain.fluvial.sea_level_m == std::optional<double>(step.stage.sea_level_m);
  return water::erode(heights, plan.chain, plan.stage, part_of(context, "erosion", 0.0, 1.0), plan.model,
                      same_outlets ? routing_of_heights : nullptr);
}

namespace {

/// One erode step: detail::erode_with, with the source's own base level (a flat plain around a
/// contour mountain), its maps added to the produced ones.
void erode_step(const ShapeStep& step, int version, Heightfield& heights, detail::Produced& produced, const Context& context) {
  water::ErosionResult result = detail::erode_with(step, version, heights, produced.base_level_m, context);
  heights = std::move(result.heights);
  auto add = [](std::optional<Grid<float>>& sum, const Grid<float>& more) {
    if (!sum) {
      sum = more;
      return;
    }
    for (std::size_t i = 0; i < sum->size() && i < more.size(); ++i) sum->values()[i] += more.values()[i];
  };
  if (!result.eroded_m.empty()) add(produced.eroded_m, result.eroded_m);
  if (!result.deposited_m.empty()) add(produced.deposited_m, result.deposited_m);
  produced.lines.push_back(fmt::format("eroded, {}: {}", terrain::stage_name(step.stage.stage), erosion_summary(step, version)));
}

void apply_steps(const Recipe& recipe, detail::Produced& produced, const Context& context) {
  detail::apply_shape_steps(recipe, produced, produced.shape_steps_done, recipe.shape.size(), context);
  if (produced.apron) {
    // The steps left after a tile is made are pointwise (stage filters), so the apron takes them alike.
    detail::Produced apron;
    apron.heights = std::move(produced.apron);
    detail::apply_shape_steps(recipe, apron, produced.shape_steps_done, recipe.shape.size(), context);
    produced.apron = std::move(apron.heights);
  }
}

}  // namespace

namespace {

/// The erode steps without force among steps [first, end), summed (each one alone is checked by
/// erode_with): three steps of seven minutes each are 21 minutes of work, over the limit.
void check_erosion_total(const Recipe& recipe, int width, int height, std::size_t first, std::size_t end) {
  budget::Cost cost;
  int steps = 0;
  for (std::size_t k = first; k < end && k < recipe.shape.size(); ++k)
    if (const ShapeStep& step = recipe.shape[k]; step.step == StepKind::erode && !step.force) {
      cost.seconds += water::estimated_erosion_seconds(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), step.erosion);
      ++steps;
    }
  if (steps < 2) return;
  cost.what = fmt::format("the {} erode steps without force, on {}x{} cells, together", steps, width, height);
  cost.smaller = "lower their erosion_steps, thermal_iterations or droplets, or erode in fewer steps";
  cost.force = "force (--force) on the long steps";
  budget::check(cost);
}

}  // namespace

void detail::apply_shape_steps(const Recipe& recipe, Produced& produced, std::size_t first, std::size_t end, const Context& context) {
  Heightfield& heights = *produced.heights;
  check_erosion_total(recipe, heights.width(), heights.height(), first, end);
  for (std::size_t k = first; k < end && k < recipe.shape.size(); ++k) {
    const ShapeStep& step = recipe.shape[k];
    if (step.step == StepKind::stage) terrain::apply_stage_filter(heights, step.stage);
    if (step.step == StepKind::erode) erode_step(step, recipe.version, heights, produced, context);
  }
}

namespace {

/// The first node of a graph whose input has a position of its own (a heightmap, a drawing,
/// polygons in the outputs' metres), or nullptr.
const GraphNode* positioned_node(const Recipe& recipe) {
  static constexpr std::array<std::string_view, 5> kinds{"file", "contour", "contour_map", "mesh", "mask_polygon"};
  const auto found =
      std::ranges::find_if(recipe.nodes, [](const GraphNode& node) { return std::ranges::find(kinds, node.kind) != kinds.end(); });
  return found == recipe.nodes.end() ? nullptr : &*found;
}

/// [world] origin places a generated world: the midpoint source, or a graph made only of
/// generated nodes (midpoint, constant) and what shapes them. A file, contour or mesh source keeps
/// its input's position, as does a graph that reads one.
void check_world_origin(const Recipe& recipe) {
  if (!recipe.world.origin_m) return;
  const auto [east, north] = *recipe.world.origin_m;
  const GraphNode* positioned = positioned_node(recipe);
  if (positioned != nullptr || (recipe.nodes.empty() && recipe.source != SourceKind::midpoint))
    fail("world.origin {},{} places a generated world (a midpoint source or node); this recipe's {} keeps its input's position",
         params::format_number(east), params::format_number(north),
         positioned != nullptr ? fmt::format("{} node '{}'", positioned->kind, positioned->id)
                               : fmt::format("{} source", source_name(recipe.source)));
  if (recipe.world.crs.empty()) return;
  const io::Crs crs = io::parse_crs(recipe.world.crs, "world.crs");
  if (const std::string problem = io::area_of_use_problem(crs, east, north); !problem.empty()) fail("world.origin {}", problem);
}

}  // namespace

void check_recipe(const Recipe& recipe) {
  if (recipe.world.tiled) {
    // Checked per rank's share, with grids as VRT mosaics (tiled_world.hpp).
    check_world_origin(recipe);
    check_sections(recipe);
    check_output_names(recipe);
    check_tiled_world(recipe);
    return;
  }
  check_recipe_budget(recipe);  // first: later checks compare list items in pairs
  if (recipe.nodes.empty() && recipe.version < 3 && recipe.world.sea_level_m != 0.0)
    fail(
        "world.sea_level {} m is read by recipes of version 3 on and by graphs; in this recipe of version {}, the sea level is the "
        "[[shape]] step's sea_level",
        recipe.world.sea_level_m, recipe.version);
  if (recipe.version < 3 && !recipe.world.crs.empty())
    fail("world.crs {} is read by recipes of version 3 on; in this recipe of version {}, the CRS is [georeference] crs", recipe.world.crs,
         recipe.version);
  check_world_origin(recipe);
  if (const std::string problem = look::mixed_lines_problem(recipe.render.land); !problem.empty()) fail("{}", problem);
  check_graph(recipe);
  check_sections(recipe);
  check_source(recipe);
  check_cameras(recipe);
  check_outputs(recipe);
  detail::check_output_settings(recipe);
}

std::string terrain_key(const Recipe& recipe) {
  // Without its outputs, a recipe's JSON holds only the sections its source reads; a graph's
  // nodes read the world.
  Recipe key = recipe;
  key.outputs.clear();
  key.more_cameras.clear();
  return fmt::format("terrain {}|{}|{}|{}", SANSUI_VERSION, recipe.base_dir.generic_string(), params::text_of(recipe.world),
                     recipe_to_json(key).dump());
}

namespace {

/// The terrain of a chain the evaluator cannot yet run as a graph (chain_as_graph: the other
/// sources, tiles, windows): its source, then its steps.
Heightfield chain_heights(const Recipe& resolved, const Context& context) {
  check_sections(resolved);
  check_source(resolved);
  if (!has_source_of_heights(resolved)) fail("the recipe has no source of heights: give a source (midpoint, file, contour or mesh)");
  Recipe working = resolved;
  detail::Needs needs;
  needs.heights = true;
  detail::Produced produced = run_source(working, needs, {}, context);
  if (!produced.heights) fail("the {} source made no heightfield", source_name(working.source));
  apply_steps(working, produced, context);
  return std::move(*produced.heights);
}

}  // namespace

Heightfield recipe_heights(const Recipe& recipe, const Context& context) {
  // The one engine: an evaluator of this call's own, which keeps nothing once it is done.
  Evaluator evaluator;
  evaluator.keep_in_memory(0);
  return *recipe_heights(recipe, evaluator, context);
}

std::shared_ptr<const Heightfield> recipe_heights(const Recipe& recipe, Evaluator& evaluator, const Context& context) {
  Recipe resolved = recipe;
  settle_world(resolved);
  if (resolved.base_dir.empty()) resolved.base_dir = std::filesystem::current_path();
  if (!resolved.nodes.empty()) {
    check_graph(resolved);
    const std::string target = final_node(resolved.nodes).id;
    return evaluator.evaluate(resolved.nodes, graph_world(resolved), {target}, context).at(target).grid;
  }
  if (resolved.source == SourceKind::midpoint || resolved.source == SourceKind::file || resolved.source == SourceKind::contour_map ||
      resolved.source == SourceKind::mesh) {
    check_sections(resolved);
    check_source(resolved);
    if (resolved.source == SourceKind::midpoint) detail::resolve_midpoint_recipe(resolved);
    if (resolved.source == SourceKind::mesh) detail::resolve_mesh_recipe(resolved);
    if (const std::vector<GraphNode> nodes = chain_as_graph(resolved); !nodes.empty()) {
      const std::string& target = nodes.back().id;
      // The cached grid itself: going back to a terrain makes nothing again.
      return evaluator.evaluate(nodes, chain_world(resolved), {target}, chain_progress(context, nodes)).at(target).grid;
    }
  }
  return evaluator.cached("terrain", terrain_key(resolved), [&] { return chain_heights(resolved, context); });
}

std::vector<ExplainedValue> explain_terrain(const Recipe& recipe) {
  std::vector<ExplainedValue> lines;
  if (recipe.source == SourceKind::midpoint) {
    const terrain::MidpointParams& m = recipe.midpoint;
    if (m.paper_sea_level)
      lines.push_back(
          {"midpoint.paper_sea_level", "true", "sea level at the generator's zero (the paper): the land's share depends on the seed"});
    else
      lines.push_back({"midpoint.land_fraction", fmt::format("{:g}", m.land_fraction),
                       fmt::format("heights shifted so that {:g} % of the whole world is above sea level (0 m)", 100.0 * m.land_fraction)});
    if (m.sigma_m) {
      lines.push_back({"midpoint.sigma", fmt::format("{:g}", *m.sigma_m), "set in the recipe"});
    } else {
      const double extent = detail::world_extent_m(recipe.world);
      lines.push_back({"midpoint.sigma", fmt::format("{:.4g}", terrain::default_sigma_for_extent(extent, m.hurst)),
                       fmt::format("follows the world: 250 m x ({:g} m / 10240 m)^{:g}", extent, m.hurst)});
    }
  }
  if (recipe.source == SourceKind::none) return lines;
  bool eroded = false;
  for (std::size_t k = 0; k < recipe.shape.size(); ++k) {
    const ShapeStep& step = recipe.shape[k];
    const std::string key = fmt::format("shape[{}]", k + 1);
    const std::string stage(terrain::stage_name(step.stage.stage));
    if (step.step == StepKind::erode) {
      eroded = true;
      lines.push_back({key, "erode " + stage, erosion_summary(step, recipe.version)});
    } else {
      lines.push_back({key, "stage " + stage, "the paper's geomorphic filter on the heights: no erosion"});
    }
  }
  if (!eroded)
    lines.push_back(
        {"erosion", "none", "the raw terrain, not drained: add [[shape]] step = \"erode\" (sansui terrain erodes unless told --no-erode)"});
  return lines;
}

nlohmann::json output_provenance(const Recipe& recipe, std::size_t index, const RunOptions& options) {
  nlohmann::json provenance = options.provenance.is_object() ? options.provenance : nlohmann::json::object();
  const std::filesystem::path file = detail::resolve(recipe, recipe.outputs[index].file);
  provenance["recipe"] = recipe_to_json(rebased(restricted(recipe, index), std::filesystem::absolute(file).parent_path()));
  return provenance;
}

namespace {

/// A recipe graph's run: the evaluator computes the nodes the outputs take; each node's outputs
/// are written from its heights, with the world's sea level.
void run_graph(Recipe& resolved, const RunOptions& options, const Context& context, RunReport& report) {
  if (resolved.world.tile || resolved.world.lod > 0 || resolved.world.world_size)
    fail("world.tile, world.lod and world.world_size are not yet read by recipe graphs: give world.size");
  const std::shared_ptr<Evaluator> evaluator = run_evaluator(options);
  const std::size_t warnings_before = evaluator->warnings().size();
  std::vector<std::string> targets;
  for (std::size_t k = 0; k < resolved.outputs.size(); ++k) {
    const std::string& id = output_node(resolved, k).id;
    if (std::find(targets.begin(), targets.end(), id) == targets.end()) targets.push_back(id);
  }
  const auto start = std::chrono::steady_clock::now();
  const auto results = evaluator->evaluate(resolved.nodes, graph_world(resolved), targets, context);
  report.seconds.emplace_back("graph", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  for (std::size_t w = warnings_before; w < evaluator->warnings().size(); ++w) context.note(evaluator->warnings()[w]);
  // The outputs read the world's sea level.
  if (resolved.version >= 3) {
    settle_world(resolved);
  } else {
    resolved.render.sea_level_m = resolved.world.sea_level_m;
    if (!resolved.flow.sea_level_m) resolved.flow.sea_level_m = resolved.world.sea_level_m;
  }
  std::vector<std::string> notes;
  const std::optional<io::Crs> crs = detail::output_crs(resolved, notes);
  for (const auto& note : notes) context.note(note);
  for (const std::string& target : targets) {
    Recipe group = resolved;
    group.outputs.clear();
    for (std::size_t k = 0; k < resolved.outputs.size(); ++k)
      if (output_node(resolved, k).id == target) group.outputs.push_back(resolved.outputs[k]);
    detail::Produced produced = produced_of(results.at(target), resolved.world);
    produced.crs = crs;
    detail::write_outputs(group, produced, options, context, report);
  }
}

}  // namespace

namespace {

/// A recipe whose terrain the caches may keep: a midpoint source (its heights depend only on its
/// sections and steps) whose outputs need nothing but the heights.
bool terrain_cacheable(const Recipe& recipe, const detail::Needs& needs) {
  if (recipe.source != SourceKind::midpoint || needs.tree || needs.mesh) return false;
  // A tile's apron (for its splat map) is made with its heights, not kept in the cache.
  if (detail::needs_apron(recipe) && (recipe.world.tile || recipe.world.lod > 0)) return false;
  return std::none_of(recipe.outputs.begin(), recipe.outputs.end(), [](const Output& output) {
    const auto kind = resolved_kind(output);
    return output_kind_info(*kind).erode_step;
  });
}

int runs_so_far(const Evaluator& evaluator) {
  int runs = 0;
  for (const auto& [id, count] : evaluator.counters().runs) runs += count;
  return runs;
}

/// A chain run as the graph it is read as (`nodes`, chain_as_graph): the evaluator makes and
/// caches each step's result, as it does for any recipe graph.
detail::Produced chain_through_graph(Recipe& resolved, const std::vector<GraphNode>& nodes, const RunOptions& options,
                                     const Context& context) {
  // The chain's own checks first, in its words: the outputs' CRS (inputs in degrees refused), each
  // erode step, then the steps together. A world that takes its source's grid is checked by the
  // evaluator once the source has run.
  std::vector<std::string> notes;
  const std::optional<io::Crs> crs = detail::output_crs(resolved, notes);
  for (const auto& note : notes) context.note(note);
  if (resolved.source == SourceKind::midpoint) {
    const int size = static_cast<int>(resolved.world.size);
    for (const ShapeStep& step : resolved.shape)
      if (step.step == StepKind::erode)
        budget::check(erosion_cost(step, detail::plan_erosion(step, resolved.version, std::nullopt), size, size), step.force);
    check_erosion_total(resolved, size, size, 0, resolved.shape.size());
  }
  const std::shared_ptr<Evaluator> evaluator = run_evaluator(options);
  const int runs_before = runs_so_far(*evaluator);
  const std::string& target = nodes.back().id;
  const NodeProducts products = evaluator->evaluate(nodes, chain_world(resolved), {target}, chain_progress(context, nodes)).at(target);
  // What the source chose for keys left unset (a contour mountain's offset and z0: [contour]'s
  // keys of the same names), as the chain's source records them in its sidecars.
  if (resolved.source == SourceKind::contour && products.report)
    for (const auto& [key, value] : products.report->settled)
      if (const auto* row = params::table_of<contour::GenerationParams>().find(key)) row->set(resolved.contour, value);
  detail::Produced produced = produced_of(products, resolved.world);
  produced.crs = crs;
  if (runs_so_far(*evaluator) == runs_before) {
    produced.lines.emplace_back("terrain from the cache: its source and shaping steps are unchanged");
    return produced;
  }
  for (const ShapeStep& step : resolved.shape)
    if (step.step == StepKind::erode)
      produced.lines.push_back(
          fmt::format("eroded, {}: {}", terrain::stage_name(step.stage.stage), erosion_summary(step, resolved.version)));
  return produced;
}

/// The source's products and the shaping steps, or the terrain from the caches.
detail::Produced make_terrain(Recipe& resolved, const detail::Needs& needs, const RunOptions& options, const Context& context) {
  Recipe placed = resolved;
  if (placed.source == SourceKind::midpoint) detail::resolve_midpoint_recipe(placed);
  if (placed.source == SourceKind::mesh) detail::resolve_mesh_recipe(placed);
  // A mesh or contour mountain whose outputs want no heights (a .glb, contour lines) is not
  // rasterised: the source runs alone.
  const bool graph = (placed.source != SourceKind::mesh && placed.source != SourceKind::contour) || needs.heights;
  if (std::vector<GraphNode> nodes = graph ? chain_as_graph(placed) : std::vector<GraphNode>{}; !nodes.empty()) {
    GraphNode& source = nodes.front();
    if (placed.source == SourceKind::mesh && needs.mesh)  // the mesh output writes the fine mesh itself
      source.node_kind().set(source.params, "keep_mesh", true);
    if (placed.source == SourceKind::contour) {  // the contours and map outputs write the lines
      source.node_kind().set(source.params, "keep_tree", needs.tree);
      source.node_kind().set(source.params, "report_times", options.verbose);
    }
    resolved = std::move(placed);
    return chain_through_graph(resolved, nodes, options, context);
  }
  if (!options.evaluator || !terrain_cacheable(resolved, needs)) {
    detail::Produced produced = run_source(resolved, needs, options, context);
    if (produced.heights) apply_steps(resolved, produced, context);
    return produced;
  }
  detail::resolve_midpoint_recipe(resolved);
  std::vector<std::string> lines;
  bool made = false;
  const auto heights = options.evaluator->cached("terrain", terrain_key(resolved), [&] {
    Recipe working = resolved;
    detail::Produced produced = run_source(working, needs, options, context);
    apply_steps(working, produced, context);
    lines = std::move(produced.lines);
    made = true;
    return std::move(*produced.heights);
  });
  detail::Produced produced;
  produced.heights = *heights;
  std::vector<std::string> notes;
  produced.crs = detail::output_crs(resolved, notes);
  for (const auto& note : notes) context.note(note);
  produced.lines = made ? std::move(lines) : std::vector<std::string>{"terrain from the cache: its source and shaping steps are unchanged"};
  return produced;
}

}  // namespace

RunReport run_recipe(const Recipe& recipe, const RunOptions& given, const Context& context) {
  if (recipe.world.tiled) return run_tiled_world(recipe, given, context);  // checks with every rank's agreement
  check_recipe(recipe);
  for (const std::string& warning : plan_outputs(recipe).warnings) context.note("warning: " + warning);
  const auto& sections = recipe_sections();
  const auto season = std::find_if(sections.begin(), sections.end(), [](const Section& s) { return s.name == "season"; });
  if (season != sections.end() && section_used(recipe, *season))
    if (const std::string contradiction = season_contradiction(recipe); !contradiction.empty()) context.note("warning: " + contradiction);
  // With a cache directory, results are kept there (and one evaluator serves the whole run).
  RunOptions options = given;
  if (!options.evaluator && !options.cache_dir.empty()) {
    options.evaluator = std::make_shared<Evaluator>(options.cache_dir);
    options.evaluator->keep_in_memory(0);  // one run: kept on disk, in memory only while needed
    for (const std::string& warning : options.evaluator->warnings()) context.note(warning);
  }
  if (!recipe.nodes.empty()) {
    io::OutputBatch batch;
    RunReport report;
    report.resolved = recipe;
    if (report.resolved.base_dir.empty()) report.resolved.base_dir = std::filesystem::current_path();
    run_graph(report.resolved, options, context, report);
    batch.commit();
    return report;
  }
  io::OutputBatch batch;  // all outputs or none: renamed into place together once every one is written
  RunReport report;
  report.resolved = recipe;
  Recipe& resolved = report.resolved;
  settle_world(resolved);
  if (resolved.base_dir.empty()) resolved.base_dir = std::filesystem::current_path();
  const detail::Needs needs = needs_of(resolved);
  const auto start = std::chrono::steady_clock::now();
  const std::size_t noted = options.evaluator ? options.evaluator->warnings().size() : 0;
  detail::Produced produced = make_terrain(resolved, needs, options, context);
  if (options.evaluator)
    for (std::size_t w = noted; w < options.evaluator->warnings().size(); ++w) context.note(options.evaluator->warnings()[w]);
  report.seconds.emplace_back(std::string(source_name(resolved.source)),
                              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  for (auto& line : produced.lines) report.lines.push_back(std::move(line));
  detail::write_outputs(resolved, produced, options, context, report);
  batch.commit();
  return report;
}

}  // namespace sansui::scene
