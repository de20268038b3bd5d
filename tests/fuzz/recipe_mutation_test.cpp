// The recipe readers against thousands of mutated scene files and sidecars (bit flips, cuts,
// repeated and swapped pieces, hostile numbers and nesting), generated deterministically from the
// example scenes: every one ends in a recipe or an InputError. Then the structured mutations of
// the `recipe` fuzz target (structured_mutator.hpp) with GCC, through its reader (loaded and
// checked): every one ends in a checked recipe or an InputError.
#include <algorithm>

#include <gtest/gtest.h>

#include "core/random.hpp"
#include "scene/recipe_file.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/fuzz/fuzz_readers.hpp"
#include "tests/fuzz/mutate.hpp"
#include "tests/fuzz/recipe_input.hpp"
#include "tests/fuzz/structured_mutator.hpp"
#include "tests/test_paths.hpp"
#include "tests/test_util.hpp"

namespace sansui::test {
namespace {

std::vector<std::string> seeds() {
  std::vector<std::string> texts;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(sansui::test::source_dir) + "/examples/scenes"))
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

TEST(RecipeFuzz, StructuredMutationsEndInACheckedRecipeOrAClearError) {
  TempDir scratch("recipe-structured");
  const FuzzReader& reader = fuzz_reader("recipe");
  std::vector<std::string> texts;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(sansui::test::source_dir) + "/tests/fuzz/corpus/recipe"))
    texts.push_back(read_text(entry.path()));
  std::sort(texts.begin(), texts.end());
  int accepted = 0, changed = 0, runs = 0;
  for (const std::string& seed : texts)
    for (std::uint64_t n = 0; n < 60; ++n) {
      std::string text = seed;
      for (std::uint64_t k = 0; k <= n % 4; ++k)  // up to four generations, as a fuzzing run stacks them
        if (auto next = mutate_structured(Grammar::recipe, text, n * 8 + k)) text = std::move(*next);
      changed += text != seed ? 1 : 0;
      bool read = false;
      ASSERT_NO_THROW(read = read_fuzz_input(reader, text, scratch.path())) << "input:\n" << text;
      accepted += read ? 1 : 0, ++runs;
    }
  EXPECT_GT(changed, runs * 9 / 10);
  EXPECT_GT(accepted, runs / 20);  // many stay valid: the checks behind the parser were reached
}

}  // namespace
}  // namespace sansui::test
