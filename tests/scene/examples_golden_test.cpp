// Every recipe under examples/ keeps the terrain it makes: the bytes of its heights (with their
// size, cell and place) are pinned in examples_golden.txt, so a change to the engine that moves
// any example's terrain by one bit fails here. A chain of a midpoint world, written out as the
// [[node]] tables the evaluator runs it as, makes the same bytes: a user can take a chain over
// into a graph and extend it.
//
// After a deliberate change of terrain, the test prints every line of the new file; say why in
// the commit.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "core/grid.hpp"
#include "scene/evaluator.hpp"
#include "scene/graph.hpp"
#include "scene/pipeline.hpp"
#include "scene/recipe_file.hpp"
#include "scene/sources.hpp"
#include "test_util.hpp"
#include "tests/test_paths.hpp"

namespace sansui::scene {
namespace {

const std::filesystem::path examples = std::string(sansui::test::source_dir) + "/examples";
const std::filesystem::path golden_file = std::string(sansui::test::source_dir) + "/tests/scene/examples_golden.txt";

/// The example recipes that make heights, relative to examples/, sorted.
std::vector<std::string> example_recipes() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(examples))
    if (entry.path().extension() == ".toml" && entry.path().parent_path().filename() != "species")
      names.push_back(entry.path().lexically_relative(examples).generic_string());
  std::ranges::sort(names);
  return names;
}

std::uint64_t hash_of(const Heightfield& heights) {
  const double facts[] = {static_cast<double>(heights.width()), static_cast<double>(heights.height()), heights.cell_size_m,
                          heights.origin_x_m, heights.origin_y_m};
  return test::fnv1a(heights.values().data(), heights.values().size() * sizeof(float), test::fnv1a(facts, sizeof facts));
}

std::map<std::string, std::string> golden() {
  std::map<std::string, std::string> lines;
  std::ifstream in(golden_file);
  std::string name, hash;
  while (in >> name >> hash) lines[name] = hash;
  return lines;
}

TEST(Examples, EveryRecipeMakesItsGoldenHeights) {
  const auto expected = golden();
  std::string now;
  bool changed = false;
  for (const std::string& name : example_recipes()) {
    const Recipe recipe = load_recipe(examples / name).recipe;
    if (recipe.source == SourceKind::none && recipe.nodes.empty()) continue;  // solid textures only
    const std::string hash = fmt::format("{:016x}", hash_of(recipe_heights(recipe)));
    now += fmt::format("{} {}\n", name, hash);
    const auto found = expected.find(name);
    EXPECT_TRUE(found != expected.end() && found->second == hash)
        << name << " makes heights " << hash << ", pinned " << (found == expected.end() ? "nothing" : found->second);
    changed = changed || found == expected.end() || found->second != hash;
  }
  if (changed) std::cout << "The heights now (" << golden_file.string() << "):\n" << now;
}

TEST(Examples, AMidpointChainWrittenAsNodesMakesTheSameHeights) {
  int compared = 0;
  for (const std::string& name : example_recipes()) {
    const Recipe recipe = load_recipe(examples / name).recipe;
    Recipe resolved = recipe;
    settle_world(resolved);
    if (resolved.source == SourceKind::midpoint) detail::resolve_midpoint_recipe(resolved);
    std::vector<GraphNode> nodes = chain_as_graph(resolved);
    // A world that takes its source's own grid (a file, a contour map, a mesh) has no [world]
    // to be written as yet: [[node]] tables run on the world's size.
    if (nodes.empty() || !chain_world(resolved).has_grid()) continue;
    Recipe graph = resolved;
    graph.source = SourceKind::none;
    graph.shape.clear();
    graph.nodes = std::move(nodes);
    // Through the text a user would write, and read back.
    const Recipe written = parse_recipe_toml(recipe_to_toml(graph), name + " as nodes", recipe.base_dir).recipe;
    ASSERT_FALSE(written.nodes.empty()) << name;
    EXPECT_EQ(hash_of(recipe_heights(written)), hash_of(recipe_heights(recipe))) << name;
    ++compared;
  }
  EXPECT_GE(compared, 8);  // the gallery, the island and forest-walk
}

TEST(Examples, ChainsOfEarlierVersionsRunAsTheirGraphsWithTheirBytes) {
  // Recipes of versions 1 and 2 are read as graphs too when their steps take one sea level (their
  // terrain is generated around 0 m whatever it is), and the evaluator's run gives the chain's
  // bytes: version 1's erode step keeps its erosion model 1. Steps with different sea levels still
  // run as the chain.
  const std::string world = "source = \"midpoint\"\n[world]\nsize = 129\n[midpoint]\nseed = 4\n";
  const std::vector<std::pair<std::string, bool>> cases{
      {"sansui_recipe = 1\n" + world + "[[shape]]\nstep = \"erode\"\n", true},
      {"sansui_recipe = 2\n" + world + "[[shape]]\nstep = \"stage\"\nstage = \"young\"\n[[shape]]\nstep = \"erode\"\n", true},
      {"sansui_recipe = 2\n" + world + "[[shape]]\nstep = \"erode\"\nsea_level = 5.0\n", true},
      {"sansui_recipe = 2\n" + world + "[[shape]]\nstep = \"stage\"\nsea_level = 5.0\n[[shape]]\nstep = \"erode\"\nsea_level = 7.0\n",
       false},
  };
  std::vector<std::uint64_t> hashes;
  for (const auto& [text, as_graph] : cases) {
    const Recipe recipe = parse_recipe_toml(text, "earlier.toml", ".").recipe;
    Recipe resolved = recipe;
    settle_world(resolved);
    detail::resolve_midpoint_recipe(resolved);
    EXPECT_EQ(!chain_as_graph(resolved).empty(), as_graph) << text;
    Evaluator evaluator;
    hashes.push_back(hash_of(*recipe_heights(recipe, evaluator, quiet_context())));
    EXPECT_EQ(hashes.back(), hash_of(recipe_heights(recipe))) << text;  // the chain's own code
  }
  // Model 1 is not model 2: the same step in a recipe of version 2 makes other heights.
  const Recipe model_2 = parse_recipe_toml("sansui_recipe = 2\n" + world + "[[shape]]\nstep = \"erode\"\n", "v2.toml", ".").recipe;
  Evaluator evaluator;
  EXPECT_NE(hash_of(*recipe_heights(model_2, evaluator, quiet_context())), hashes[0]);
}

TEST(Examples, AGraphOfAnEarlierVersionErodesAsGraphsDo) {
  // Graphs of versions 1 to 5 erode with model 2: a [[node]] erode in a recipe of version 1 keeps
  // that (model 1 belongs to version 1's [[shape]] steps). From version 6 on, model 3.
  const std::string graph =
      "[world]\nsize = 129\n[[node]]\nid = \"m\"\nkind = \"midpoint\"\n[[node]]\nid = \"e\"\nkind = \"erode\"\ninputs = [\"m\"]\n";
  const Recipe version_1 = parse_recipe_toml("sansui_recipe = 1\n" + graph, "v1.toml", ".").recipe;
  const Recipe version_5 = parse_recipe_toml("sansui_recipe = 5\n" + graph, "v5.toml", ".").recipe;
  const Recipe current = parse_recipe_toml(graph, "now.toml", ".").recipe;
  EXPECT_EQ(hash_of(recipe_heights(version_1)), hash_of(recipe_heights(version_5)));
  EXPECT_NE(hash_of(recipe_heights(version_5)), hash_of(recipe_heights(current)));
}

}  // namespace
}  // namespace sansui::scene
