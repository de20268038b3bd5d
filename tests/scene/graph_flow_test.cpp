// The flow node: routing as a node of its own. The nodes and outputs after it take its routing
// instead of routing the same heights again, and make the bytes they make without it.
#include <fstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "scene/evaluator.hpp"
#include "scene/graph.hpp"
#include "scene/pipeline.hpp"
#include "scene/recipe_file.hpp"
#include "test_util.hpp"
#include "water/erode.hpp"
#include "water/flow.hpp"
#include "water/water_test_util.hpp"

namespace sansui::scene {
namespace {

std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A graph whose mask, erosion and water outputs take `source`: "hills" (routing each for
/// itself) or "water", a flow node on the hills. Its outputs are named after `name`.
std::string graph_from(const std::string& source, const std::string& name, const std::string& world_extra = "") {
  std::string text = R"(
[world]
size = 257
cell = 10.0
)" + world_extra + R"(
[[node]]
id = "hills"
kind = "midpoint"
seed = 6

[[node]]
id = "water"
kind = "flow"
inputs = ["hills"]
)";
  text += fmt::format(R"(
[[node]]
id = "valleys"
kind = "select_flow"
inputs = ["{0}"]

[[node]]
id = "eroded"
kind = "erode"
inputs = ["{0}"]
)",
                      source);
  const std::pair<const char*, const char*> outputs[] = {
      {"valleys", "heightmap"},   {"eroded", "heightmap"},   {"eroded", "erosion_map"},    {"eroded", "deposition_map"},
      {source.c_str(), "rivers"}, {source.c_str(), "lakes"}, {source.c_str(), "flow_map"}, {source.c_str(), "wetness_map"}};
  for (const auto& [node, kind] : outputs)
    text += fmt::format("\n[[output]]\nfile = \"{}-{}-{}.{}\"\nnode = \"{}\"\nkind = \"{}\"\n", name, node == source ? "routed" : node,
                        kind, std::string(kind) == "rivers" || std::string(kind) == "lakes" ? "geojson" : "r32", node, kind);
  return text;
}

/// Runs a graph recipe; the files it wrote, by name, with their bytes.
std::vector<std::pair<std::string, std::string>> run_graph(const std::string& text, const std::filesystem::path& dir,
                                                           const RunOptions& options = {}) {
  const Recipe recipe = parse_recipe_toml(text, "flow.toml", dir).recipe;
  const RunReport report = run_recipe(recipe, options);
  std::vector<std::pair<std::string, std::string>> files;
  for (const auto& path : report.written) files.emplace_back(path.filename().string(), file_bytes(path));
  return files;
}

/// The bytes of each file, with the names' prefix (`name` of graph_from) cut off.
std::vector<std::pair<std::string, std::string>> without_prefix(std::vector<std::pair<std::string, std::string>> files) {
  for (auto& [name, bytes] : files) name = name.substr(name.find('-'));
  return files;
}

TEST(GraphFlow, NodesAndOutputsAfterAFlowNodeGiveTheBytesTheyGiveWithoutIt) {
  const test::TempDir dir("graph-flow");
  // The flow node is a node nothing takes in the graph without it: a warning, not an error.
  const auto routed = run_graph(graph_from("water", "with"), dir.path());
  const auto alone = run_graph(graph_from("hills", "without"), dir.path());
  ASSERT_EQ(routed.size(), 8u);
  EXPECT_EQ(without_prefix(routed), without_prefix(alone));
}

TEST(GraphFlow, AWorldWithAnOriginRoutesItsOwnHeightsWithTheSameBytes) {
  // The outputs' heights are placed at the origin after the graph ran, so the flow node's routing
  // (of the heights at 0, 0) is not theirs: they route the placed heights.
  const test::TempDir dir("graph-flow-origin");
  const std::string origin = "origin = [500000.0, 4000000.0]\n";
  EXPECT_EQ(without_prefix(run_graph(graph_from("water", "with", origin), dir.path())),
            without_prefix(run_graph(graph_from("hills", "without", origin), dir.path())));
}

TEST(GraphFlow, TheRoutingLivesInMemoryAndACachedRunGivesTheSameBytes) {
  const test::TempDir dir("graph-flow-cache");
  const auto uncached = run_graph(graph_from("water", "with"), dir.path());
  RunOptions options;
  options.cache_dir = dir / "cache";
  EXPECT_EQ(run_graph(graph_from("water", "with"), dir.path(), options), uncached);
  // A warm cache holds the flow node's heights, not its routing: the nodes after it are cached
  // too, and the water outputs route the heights themselves.
  EXPECT_EQ(run_graph(graph_from("water", "with"), dir.path(), options), uncached);
}

TEST(GraphFlow, TheFlowNodeCarriesTheRoutingAndPassesItsHeightsAndLayersOn) {
  const std::string text = R"(
[world]
size = 129
cell = 10.0

[[node]]
id = "hills"
kind = "midpoint"
seed = 2

[[node]]
id = "eroded"
kind = "erode"
inputs = ["hills"]

[[node]]
id = "water"
kind = "flow"
inputs = ["eroded"]
)";
  const Recipe recipe = parse_recipe_toml(text, "flow.toml", ".").recipe;
  GraphWorld world;
  world.width = world.height = 129, world.base_dir = ".";
  Evaluator evaluator;
  const auto results = evaluator.evaluate(recipe.nodes, world, {"eroded", "water"});
  const NodeProducts& eroded = results.at("eroded");
  const NodeProducts& water = results.at("water");
  EXPECT_EQ(test::fnv1a(water.grid->values()), test::fnv1a(eroded.grid->values()));
  EXPECT_EQ(water.layers.size(), 2u);
  EXPECT_EQ(water.layers.at(std::string(eroded_layer)), eroded.layers.at(std::string(eroded_layer)));  // shared, not copied
  ASSERT_NE(water.flow, nullptr);
  EXPECT_EQ(eroded.flow, nullptr);
  const water::FlowRouting fresh = water::route_flow(*eroded.grid, water::Outlets{0.0});
  EXPECT_EQ(test::fnv1a(water.flow->area_m2.values()), test::fnv1a(fresh.area_m2.values()));
  EXPECT_EQ(water.flow->stack, fresh.stack);
  // Again from memory: the routing comes back with the heights.
  const auto again = evaluator.evaluate(recipe.nodes, world, {"water"});
  EXPECT_EQ(again.at("water").flow, water.flow);
}

TEST(GraphFlow, ErosionTakesAGivenRoutingOfItsHeightsWithTheSameBytes) {
  const Heightfield hills = water::test::midpoint_terrain(129, 10.0, 8);
  water::ErosionChainParams chain;
  chain.fluvial.sea_level_m = 0.0;
  chain.fluvial.steps = 3;
  const water::FlowRouting routing = water::route_flow(hills, water::Outlets{0.0});
  for (const bool staged : {true, false}) {
    const std::optional<water::ErosionStage> stage = staged ? std::optional(water::ErosionStage::mature) : std::nullopt;
    const water::ErosionResult own = water::erode(hills, chain, stage, quiet_context());
    const water::ErosionResult given = water::erode(hills, chain, stage, quiet_context(), water::default_erosion_model, &routing);
    EXPECT_EQ(test::fnv1a(given.heights.values()), test::fnv1a(own.heights.values())) << (staged ? "staged" : "own time step");
    EXPECT_EQ(test::fnv1a(given.deposited_m.values()), test::fnv1a(own.deposited_m.values()));
  }
}

}  // namespace
}  // namespace sansui::scene
