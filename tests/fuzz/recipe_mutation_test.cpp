// The recipe readers against thousands of mutated scene files and sidecars (bit flips, cuts,
// repeated and swapped pieces, hostile numbers and nesting), generated deterministically from the
// example scenes: every one ends in a recipe or an InputError.
#include <gtest/gtest.h>

#include "core/random.hpp"
#include "scene/recipe_file.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/fuzz/mutate.hpp"
#include "tests/fuzz/recipe_input.hpp"
#include "tests/test_util.hpp"

namespace sansui::test {
namespace {

std::vector<std::string> seeds() {
  std::vector<std::string> texts;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(SANSUI_SOURCE_DIR) + "/examples/scenes"))
    texts.push_back(read_text(entry.path()));
  for (const auto& name : scene::source_names()) texts.push_back(scene::default_recipe_text(*scene::source_from_name(name)));
  texts.push_back(R"({"sansui_sidecar": 2, "provenance": {"recipe": {"source": "midpoint", "midpoint": {"seed": 3},
    "output": [{"file": "a.png"}]}}})");
  return texts;
}

TEST(RecipeFuzz, MutatedScenesAndSidecarsEndInARecipeOrAClearError) {
  TempDir dir("recipe-fuzz");
  const auto scratch = dir / "input.json";
  int accepted = 0, runs = 0;
  for (const std::string& seed : seeds())
    for (std::uint64_t n = 0; n < 600; ++n) {
      std::string text = mutate(seed, n);
      if (n % 3 == 0) text = mutate(text, n + 100000);
      ASSERT_NO_THROW(accepted += read_recipe_input(text, scratch)) << "input:\n" << text;
      ++runs;
    }
  EXPECT_GT(runs, 5000);
  EXPECT_GT(accepted, 100);  // the mutations are not all fatal: the readers were really exercised
}

}  // namespace
}  // namespace sansui::test
