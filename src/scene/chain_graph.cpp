// A chain recipe (a source and [[shape]] steps) read as the graph it is: the source as a node,
// then one node per step, each taking the one before. The evaluator runs it as it runs any
// recipe graph, so a chain's steps are cached one by one and a change to the last step does not
// make the terrain again.
#include <algorithm>
#include <optional>

#include <fmt/format.h>

#include "contour/generate.hpp"
#include "contour/to_dem.hpp"
#include "core/params.hpp"
#include "mesh/sketch.hpp"
#include "mesh/subdivide.hpp"
#include "scene/graph.hpp"
#include "scene/recipe.hpp"
#include "terrain/midpoint.hpp"
#include "terrain/stage_filter.hpp"

namespace sansui::scene {
namespace {

/// The node a chain's stage step is: its stage, paper_exact and height unit under the stage
/// node's keys (the sea level is the world's).
GraphNode stage_node(const ShapeStep& step, std::string id, std::string input) {
  const NodeKind& kind = *find_node_kind("stage");
  std::any params = kind.make();
  const auto& table = params::table_of<terrain::StageFilterParams>();
  for (const auto& [from, to] : {std::pair{"stage", "stage"}, {"paper_exact", "paper_exact"}, {"height_unit", "sigma"}})
    kind.set(params, to, table.find(from)->get(step.stage));
  return {std::move(id), kind.name, {std::move(input)}, std::move(params), "[[shape]] stage"};
}

/// The one sea level of a chain's steps: the world's (recipes of version 3 on), or the one every
/// step of an earlier recipe gives (none where they differ, or without steps: 0 m).
std::optional<double> steps_sea_level(const Recipe& resolved) {
  if (resolved.version >= 3 || resolved.shape.empty()) return resolved.version >= 3 ? resolved.world.sea_level_m : 0.0;
  const double first = resolved.shape.front().stage.sea_level_m;
  if (std::ranges::all_of(resolved.shape, [&](const ShapeStep& step) { return step.stage.sea_level_m == first; })) return first;
  return std::nullopt;
}

/// A contour_map node with the keys of [contour_map] and [dem]: the map on its own grid.
GraphNode contour_map_node(const Recipe& resolved) {
  const NodeKind& kind = *find_node_kind("contour_map");
  std::any params = kind.make();
  const auto& map = params::table_of<ContourMapSourceParams>();
  for (const char* key : {"file", "elevation_attribute", "spot_heights", "grid_from"})
    kind.set(params, key, map.find(key)->get(resolved.contour_map));
  const auto& dem = params::table_of<DemGridParams>();
  for (const auto& [from, to] : {std::pair{"size", "grid_size"}, {"cell", "grid_cell"}})
    kind.set(params, to, dem.find(from)->get(resolved.dem));
  return {"contour_map", kind.name, {}, std::move(params), "[contour_map]"};
}

/// A mesh node with the keys of [mesh], [subdivide], [sketch] and [dem]: the mesh on its own grid.
GraphNode mesh_node(const Recipe& resolved) {
  const NodeKind& kind = *find_node_kind("mesh");
  std::any params = kind.make();
  const auto& mesh = params::table_of<MeshSourceParams>();
  for (const char* key : {"file", "pyramid", "sketch", "measure"}) kind.set(params, key, mesh.find(key)->get(resolved.mesh));
  for (const auto& row : params::table_of<mesh::SubdivideParams>().rows) kind.set(params, row.key, row.get(resolved.subdivide));
  for (const auto& row : params::table_of<mesh::SketchParams>().rows) kind.set(params, "sketch_" + row.key, row.get(resolved.sketch));
  const auto& dem = params::table_of<DemGridParams>();
  for (const auto& [from, to] : {std::pair{"fill", "fill"}, {"size", "grid_size"}, {"cell", "grid_cell"}})
    kind.set(params, to, dem.find(from)->get(resolved.dem));
  return {"mesh", kind.name, {}, std::move(params), "[mesh]"};
}

/// A contour node with the keys of [contour_seed], [contour], [contour_dem] and [dem]: the
/// mountain on its own grid, with the plain as base level from version 2 on.
GraphNode contour_node(const Recipe& resolved) {
  const NodeKind& kind = *find_node_kind("contour");
  std::any params = kind.make();
  for (const auto& row : params::table_of<ContourSeedParams>().rows) kind.set(params, row.key, row.get(resolved.contour_seed));
  for (const auto& row : params::table_of<contour::GenerationParams>().rows) kind.set(params, row.key, row.get(resolved.contour));
  for (const auto& row : params::table_of<contour::DemParams>().rows)
    if (row.exposed) kind.set(params, row.key, row.get(resolved.contour_dem));
  const auto& dem = params::table_of<DemGridParams>();
  for (const auto& [from, to] : {std::pair{"fill", "fill"}, {"size", "grid_size"}, {"cell", "grid_cell"}})
    kind.set(params, to, dem.find(from)->get(resolved.dem));
  kind.set(params, "base_level", resolved.version >= 2);
  return {"contour", kind.name, {}, std::move(params), "[contour_seed]"};
}

/// The node a chain's source is, where it has one: a midpoint world of one whole 2^k+1 grid, or a
/// source whose grid the world takes (a heightmap file, a contour map, a mesh, a contour mountain).
std::optional<GraphNode> source_node(const Recipe& resolved) {
  const WorldParams& world = resolved.world;
  if (resolved.source == SourceKind::file) return GraphNode{"file", "file", {}, std::any(resolved.file), "[file]"};
  if (resolved.source == SourceKind::contour_map) return contour_map_node(resolved);
  if (resolved.source == SourceKind::mesh) return mesh_node(resolved);
  if (resolved.source == SourceKind::contour) return contour_node(resolved);
  if (resolved.source != SourceKind::midpoint || world.tiled || world.tile || world.lod > 0 || world.world_size ||
      terrain::levels_for_size(world.size) < 1)
    return std::nullopt;
  return GraphNode{"midpoint", "midpoint", {}, std::any(resolved.midpoint), "[midpoint]"};
}

}  // namespace

std::vector<GraphNode> chain_as_graph(const Recipe& resolved) {
  // A recipe of an earlier version is the same graph on its chain_world when its steps take one
  // sea level.
  std::optional<GraphNode> source = source_node(resolved);
  if (!resolved.nodes.empty() || !source || !steps_sea_level(resolved)) return {};
  std::vector<GraphNode> nodes{std::move(*source)};
  for (std::size_t k = 0; k < resolved.shape.size(); ++k) {
    const ShapeStep& step = resolved.shape[k];
    std::string id = fmt::format("{}-{}", step.step == StepKind::erode ? "erode" : "stage", k + 1);
    std::string input = nodes.back().id;
    if (step.step == StepKind::erode)
      nodes.push_back({std::move(id), "erode", {std::move(input)}, std::any(step), "[[shape]] erode"});
    else
      nodes.push_back(stage_node(step, std::move(id), std::move(input)));
  }
  return nodes;
}

GraphWorld graph_world(const Recipe& recipe) {
  GraphWorld world;
  world.width = world.height = static_cast<int>(recipe.world.size);
  world.cell_m = recipe.world.cell_m, world.sea_level_m = recipe.world.sea_level_m;
  const auto [east_m, south_m] = world_sample_origin(recipe.world);  // (0, 0) without an origin
  world.origin_x_m = east_m, world.origin_y_m = south_m;
  world.base_dir = recipe.base_dir.string();
  world.version = std::max(2, recipe.version);  // graphs of [[node]] tables never took erosion model 1
  return world;
}

GraphWorld chain_world(const Recipe& resolved) {
  GraphWorld world = graph_world(resolved);
  if (resolved.source != SourceKind::midpoint) world.width = world.height = 0;  // the source's own grid
  world.version = resolved.version;                                             // its erosion model (water/erode.hpp)
  if (resolved.version < 3) {
    world.sea_level_m = steps_sea_level(resolved).value_or(0.0);
    world.midpoint_datum_m = 0.0;
  }
  return world;
}

}  // namespace sansui::scene
