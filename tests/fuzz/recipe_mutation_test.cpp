// The recipe readers against thousands of mutated scene files and sidecars (bit flips, cuts,
// repeated and swapped pieces, hostile numbers and nesting), generated deterministically from the
// example scenes: every one ends in a recipe or an InputError.
#include <gtest/gtest.h>

#include "core/random.hpp"
#include "scene/recipe_file.hpp"
#include "tests/cli/cli_runner.hpp"
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

std::string mutate(const std::string& text, std::uint64_t n) {
  auto pick = [&](int k, std::size_t size) { return static_cast<std::size_t>(rng::uniform(77, n, k, 0) * static_cast<double>(size)); };
  std::string out = text;
  const std::size_t at = out.empty() ? 0 : pick(0, out.size());
  switch (n % 8) {
    case 0:
      if (!out.empty()) out[at] = static_cast<char>(out[at] ^ (1 << pick(1, 8)));
      break;
    case 1:
      out.resize(at);
      break;
    case 2:
      out.insert(at, out.substr(pick(2, out.size()), pick(3, 40)));
      break;
    case 3:
      out.erase(at, pick(4, 30));
      break;
    case 4:
      out.insert(at, std::vector<std::string>{"1e999", "-1", "nan", "9223372036854775808", "\"\"", "[[", "{", "\n[x]\n", "= =", "\xff\xfe",
                                              "[[output]]\n", "-0"}[pick(5, 12)]);
      break;
    case 5:
      out.insert(at, std::string(pick(6, 3000), "[{\"a"[pick(7, 4)]));
      break;
    case 6:
      out.replace(at, 1, 1, "\n=.,[]{}\"'#"[pick(8, 11)]);
      break;
    default:
      for (int k = 0; k < 4; ++k)
        if (!out.empty()) out[pick(10 + k, out.size())] = static_cast<char>(pick(20 + k, 256));
      break;
  }
  return out;
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
