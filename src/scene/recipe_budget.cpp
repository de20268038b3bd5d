// The recipe's own budget: see recipe_budget.hpp.
#include "scene/recipe_budget.hpp"

#include <string_view>

#include "core/error.hpp"

namespace sansui::scene {
namespace {

/// Measured: a sidecar's JSON holds about 900 bytes per [[shape]] step (100,000 steps made a
/// 91 MB sidecar), about as much per camera and node, and about 200 bytes per output. The JSON
/// document in memory is about 8 times its text (nlohmann::json's nodes and strings), and a run
/// holds a few copies of the recipe and its JSON at once.
constexpr double sidecar_bytes_per_item = 900.0;
constexpr double sidecar_bytes_per_output = 200.0;
constexpr double json_document_factor = 8.0;
constexpr double copies = 3.0;

void check_count(std::size_t count, std::size_t cap, std::string_view list, std::string_view items) {
  if (count > cap) fail("the recipe has {} {} {}, more than the limit of {}: split it into several recipes", count, list, items, cap);
}

}  // namespace

budget::Cost recipe_cost(const Recipe& recipe) {
  const auto items = static_cast<double>(recipe.shape.size() + recipe.more_cameras.size() + recipe.nodes.size());
  const auto outputs = static_cast<double>(recipe.outputs.size());
  const double text = 2000.0 + sidecar_bytes_per_item * items + sidecar_bytes_per_output * outputs;
  const auto count = [](std::size_t n) { return static_cast<double>(n); };
  const double structs = count(sizeof(Recipe)) + count(sizeof(ShapeStep)) * count(recipe.shape.size()) +
                         count(sizeof(look::Camera)) * count(recipe.more_cameras.size()) +
                         count(sizeof(GraphNode)) * count(recipe.nodes.size()) + count(sizeof(Output)) * outputs;
  budget::Cost cost;
  // Each output's provenance (the recipe's JSON) is built while the outputs are written.
  cost.bytes = copies * (structs + json_document_factor * text) + text * outputs;
  cost.seconds = 0.0;  // linear in the lists, which the caps keep short
  cost.what = fmt::format("the recipe ({} [[shape]] steps, {} [[output]] tables, {} [[camera]] tables, {} [[node]] tables)",
                          recipe.shape.size(), recipe.outputs.size(), recipe.more_cameras.size(), recipe.nodes.size());
  cost.smaller = "split it into several recipes";
  return cost;
}

void check_recipe_budget(const Recipe& recipe) {
  check_count(recipe.shape.size(), max_shape_steps, "[[shape]]", "steps");
  check_count(recipe.outputs.size(), max_outputs, "[[output]]", "tables");
  check_count(recipe.more_cameras.size() + 1, max_cameras, "[[camera]]", "tables");  // render.camera is the first
  check_count(recipe.nodes.size(), max_nodes, "[[node]]", "tables");
  budget::check(recipe_cost(recipe));
}

}  // namespace sansui::scene
