// The output plan (scene/output_plan.hpp): the files a run writes, each output with its sidecar
// and the files its kind writes beside it, and the checks made on them as a whole.
#include "scene/output_plan.hpp"

#include <fstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "scene/pipeline.hpp"
#include "scene/recipe_file.hpp"
#include "test_util.hpp"

namespace sansui::scene {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

Recipe parse_in(const std::string& text, const std::filesystem::path& base) {
  return parse_recipe_toml(text, "plan.toml", base).recipe;
}

std::vector<std::string> names_of(const OutputPlan& plan) {
  std::vector<std::string> names;
  for (const PlannedFile& file : plan.files) names.push_back(file.path.filename().string());
  return names;
}

TEST(OutputPlan, HoldsEveryFileTheRunWrites) {
  const test::TempDir dir("plan-files");
  const Recipe recipe = parse_in(R"(source = "midpoint"
[world]
size = 33
[[output]]
file = "t.obj"
[[output]]
file = "t.r32"
[[output]]
file = "p.csv"
)",
                                 dir.path());
  // What a run writes (checked against the directory after it).
  const OutputPlan plan = plan_outputs(recipe);
  EXPECT_THAT(names_of(plan),
              ElementsAre("t.obj", "t.obj.json", "t.mtl", "t_basecolor.png", "t.r32", "t.r32.json", "t.r32.hdr", "p.csv", "p.csv.json"));
  run_recipe(recipe);
  for (const std::string& name : names_of(plan)) EXPECT_TRUE(std::filesystem::exists(dir / name)) << name;
}

TEST(OutputPlan, AGraphNodesInputIsNotOverwritten) {
  const test::TempDir dir("plan-node-input");
  std::ofstream(dir / "in.png") << "not read";
  const std::string message = test::message_of([&] {
    check_recipe(parse_in(R"([world]
size = 33
[[node]]
id = "land"
kind = "file"
path = "in.png"
[[output]]
file = "in.png"
)",
                          dir.path()));
  });
  EXPECT_THAT(message, HasSubstr("would overwrite " + (dir / "in.png").string() + ", which node `land` path reads"));
}

TEST(OutputPlan, NamesThatDifferOnlyInAsciiCaseAreWarnedOf) {
  const test::TempDir dir("plan-case-fold");
  const Recipe recipe = parse_in(
      "source = \"midpoint\"\n[world]\nsize = 33\n[[output]]\nfile = \"Ridge.PNG\"\n[[output]]\nfile = \"ridge.png\"\n", dir.path());
  const OutputPlan plan = plan_outputs(recipe);
  ASSERT_EQ(plan.warnings.size(), 1u);
  EXPECT_THAT(plan.warnings[0], HasSubstr("output Ridge.PNG and output ridge.png differ only in case"));
}

}  // namespace
}  // namespace sansui::scene
