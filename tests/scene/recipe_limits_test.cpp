// Limits of recipes read from files (issue 30): values a sidecar cannot mean are errors naming
// their key, not defaults or wrapped numbers; every list has a cap that its message names; a
// documented range is the one the code applies.
#include <filesystem>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "scene/pipeline.hpp"
#include "scene/recipe_file.hpp"
#include "tests/test_util.hpp"

namespace sansui::scene {
namespace {

using test::message_of;
using ::testing::HasSubstr;
using ::testing::Not;

std::filesystem::path scratch_dir() {
  static const std::filesystem::path dir = [] {
    auto path = std::filesystem::temp_directory_path() / ("sansui-recipe-limits-" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
    return path;
  }();
  return dir;
}

/// Loads a sidecar holding `recipe` and returns the error, or "(no error)".
std::string sidecar_message(const nlohmann::json& recipe) {
  const auto file = scratch_dir() / "x.r32.json";
  std::ofstream(file) << nlohmann::json{{"sansui_sidecar", 2}, {"provenance", {{"version", SANSUI_VERSION}, {"recipe", recipe}}}}.dump();
  return message_of([&] { (void)load_recipe(file); });
}

nlohmann::json small_recipe() {
  return {{"sansui_recipe", 4}, {"source", "midpoint"}, {"world", {{"size", 33}}}, {"output", {{{"file", "x.r32"}}}}};
}

TEST(RecipeLimits, ASmallSidecarLoads) {
  EXPECT_EQ(sidecar_message(small_recipe()), "(no error)");
}

TEST(RecipeLimits, NullInASidecarIsAnErrorNamingTheKeyNotTheDefault) {
  nlohmann::json recipe = small_recipe();
  recipe["world"]["size"] = nullptr;
  EXPECT_THAT(sidecar_message(recipe), HasSubstr("world.size is null: give it a value, or leave the key out"));
  recipe = small_recipe();
  recipe["output"][0]["file"] = nullptr;
  EXPECT_THAT(sidecar_message(recipe), HasSubstr("output[0].file is null"));
}

TEST(RecipeLimits, AWholeNumberPast2To63IsNotReadAsNegative) {
  nlohmann::json recipe = small_recipe();
  recipe["midpoint"] = {{"seed", 18446744073709551615ULL}};
  const std::string message = sidecar_message(recipe);
  EXPECT_THAT(message, HasSubstr("midpoint.seed = 18446744073709551615 is too large: a whole number in a recipe is at most 2^63 - 1"));
  EXPECT_THAT(message, Not(HasSubstr("= -1")));
}

TEST(RecipeLimits, AListOverItsLimitNamesTheLimit) {
  nlohmann::json recipe = small_recipe();
  recipe["source"] = "contour";
  recipe["contour"] = {{"offset_schedule", std::vector<double>((std::size_t{1} << 20) + 1, 1.0)}};
  const std::string message = sidecar_message(recipe);
  EXPECT_THAT(message, HasSubstr("(1048577 values)"));
  EXPECT_THAT(message, HasSubstr("a list of at most 1048576 numbers"));
  EXPECT_EQ(message.find('\n'), std::string::npos);
}

std::string repeated(const std::string& text, std::size_t count) {
  std::string out;
  for (std::size_t i = 0; i < count; ++i) out += text;
  return out;
}

std::string scene_message(const std::string& text) {
  return message_of([&] { (void)parse_recipe_toml(text, "scene.toml", scratch_dir()); });
}

TEST(RecipeLimits, EveryListHasACapThatItsMessageNames) {
  EXPECT_THAT(scene_message("[world]\nsize = 33\n" + repeated("[[shape]]\nstep = \"stage\"\n", max_shape_steps + 1)),
              HasSubstr("scene.toml:3: 257 [[shape]] tables: a recipe may have at most 256"));
  EXPECT_THAT(scene_message("[world]\nsize = 33\n" + repeated("[[output]]\nfile = \"a.r32\"\n", max_outputs + 1)),
              HasSubstr("4097 [[output]] tables: a recipe may have at most 4096"));
  EXPECT_THAT(scene_message(repeated("[[camera]]\nname = \"a\"\n", max_cameras + 1)),
              HasSubstr("4097 [[camera]] tables: a recipe may have at most 4096"));
  EXPECT_THAT(scene_message(repeated("[[node]]\nid = \"a\"\nkind = \"midpoint\"\n", max_nodes + 1)),
              HasSubstr("1025 [[node]] tables: a recipe may have at most 1024"));
  // At the caps, a file reads.
  EXPECT_EQ(scene_message("[world]\nsize = 33\n" + repeated("[[shape]]\nstep = \"stage\"\n", max_shape_steps)), "(no error)");
}

TEST(RecipeLimits, ManyCamerasAreCheckedWithoutQuadraticWork) {
  // 4096 cameras and 4096 render outputs: the name checks are linear (the check of 150,000
  // cameras took 36 s when each name was compared with every one before it).
  std::string text = "[render]\nwidth = 16\nheight = 16\n[world]\nsize = 33\n";
  for (std::size_t i = 0; i < max_cameras; ++i) text += "[[camera]]\nname = \"c" + std::to_string(i) + "\"\n";
  text += "[[output]]\nfile = \"a.png\"\nkind = \"render\"\ncamera = \"c4095\"\n";
  LoadedRecipe loaded = parse_recipe_toml(text, "scene.toml", scratch_dir());
  EXPECT_NO_THROW(check_recipe(loaded.recipe));
  loaded.recipe.more_cameras.back().name = "c7";
  EXPECT_THAT(message_of([&] { check_recipe(loaded.recipe); }), HasSubstr("two cameras are named \"c7\""));
}

TEST(RecipeLimits, DemSizeOfAContourMapOrMountainIsRefusedAtTheLimitTheDocsGive) {
  std::ofstream(scratch_dir() / "lines.geojson") << R"({"type": "FeatureCollection", "features": []})";
  LoadedRecipe map = parse_recipe_toml(
      "source = \"contour_map\"\n[contour_map]\nfile = \"lines.geojson\"\n[dem]\nsize = 32769\n"
      "[[output]]\nfile = \"d.r32\"\n",
      "scene.toml", scratch_dir());
  EXPECT_THAT(message_of([&] { check_recipe(map.recipe); }),
              HasSubstr("dem.size 32769 is not allowed for a contour map: it must be 2..32768"));
}

}  // namespace
}  // namespace sansui::scene
