// A chain recipe (a source and [[shape]] steps) read as the graph it is: the source as a node,
// then one node per step, each taking the one before. The evaluator runs it as it runs any
// recipe graph, so a chain's steps are cached one by one and a change to the last step does not
// make the terrain again.
#include <algorithm>

#include <fmt/format.h>

#include "core/params.hpp"
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

/// Whether every step of the chain takes `sea_level_m`, the graph world's: recipes before
/// version 3 give each step a sea level of its own, and generate around 0 m.
bool one_sea_level(const Recipe& resolved, double sea_level_m) {
  if (resolved.version < 3 && sea_level_m != 0.0) return false;
  return std::ranges::all_of(resolved.shape, [&](const ShapeStep& step) { return step.stage.sea_level_m == sea_level_m; });
}

}  // namespace

std::vector<GraphNode> chain_as_graph(const Recipe& resolved) {
  const WorldParams& world = resolved.world;
  // The midpoint node makes one whole 2^k+1 world, around the world's sea level. A recipe of an
  // earlier version is the same graph (its erode nodes take its erosion model from the graph's
  // world) when its steps' sea levels are that one.
  if (!resolved.nodes.empty() || resolved.source != SourceKind::midpoint || !one_sea_level(resolved, world.sea_level_m) || world.tiled ||
      world.tile || world.lod > 0 || world.world_size || terrain::levels_for_size(world.size) < 1)
    return {};
  std::vector<GraphNode> nodes;
  nodes.push_back({"midpoint", "midpoint", {}, std::any(resolved.midpoint), "[midpoint]"});
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

}  // namespace sansui::scene
