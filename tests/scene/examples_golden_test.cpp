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
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "core/grid.hpp"
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
    if (nodes.empty()) continue;
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

}  // namespace
}  // namespace sansui::scene
