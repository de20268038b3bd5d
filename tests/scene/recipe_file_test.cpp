// Scene files and sidecar recipes: every value survives writing and reading, defaults load back,
// and every kind of bad file is refused with its file, line, key and what is allowed.
#include "scene/recipe_file.hpp"

#include <algorithm>
#include <fstream>
#include <map>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "scene/commands.hpp"
#include "scene/params_doc.hpp"
#include "scene/pipeline.hpp"
#include "tests/test_paths.hpp"
#include "tests/test_util.hpp"

namespace sansui::scene {
namespace {

using test::message_of;

using ::testing::HasSubstr;

/// Where the test scenes stand, with the input files they name.
const std::filesystem::path& scene_dir() {
  static const std::filesystem::path dir = [] {
    auto path = std::filesystem::temp_directory_path() / ("sansui-recipe-file-" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
    for (const char* name : {"some \"file\" name.png", "heightmap.png", "seed.geojson", "contours.geojson"})
      std::ofstream(path / name) << "x";
    return path;
  }();
  return dir;
}

LoadedRecipe parse(const std::string& text) {
  return parse_recipe_toml(text, "scene.toml", scene_dir());
}

std::string error_of(const std::string& text) {
  return message_of([&] { parse(text); });
}

/// A value the row allows that differs from `current` where it can.
params::Value other_value(const params::ParamInfo& row, const params::Value& current) {
  const auto& limits = row.limits;
  const double low = limits.min.value_or(-1000.0), high = limits.max.value_or(1000.0);
  double number = low + 0.37 * (high - low);
  if (limits.min && limits.max && high - low > 1e6) number = low + 7.0;  // type-sized ranges
  if (row.kind == params::Kind::integer || limits.whole) number = std::floor(number) + 1.0;
  if (limits.max) number = std::min(number, high);
  switch (row.kind) {
    case params::Kind::flag:
      return std::holds_alternative<bool>(current) ? !std::get<bool>(current) : true;  // an unset optional flag: set it
    case params::Kind::integer:
      return static_cast<std::int64_t>(number);
    case params::Kind::real:
      return number + 0.123456789;
    case params::Kind::choice:
      return limits.choices.back();
    case params::Kind::text:
    case params::Kind::path:
      return std::string("some \"file\" name.png");
    case params::Kind::reals: {
      std::vector<double> numbers;
      for (std::size_t i = 0; i < std::max<std::size_t>(limits.min_count, 1); ++i)
        numbers.push_back(number + static_cast<double>(i) * (limits.whole ? 1.0 : 0.01));
      return numbers;
    }
  }
  return current;
}

TEST(RecipeFile, EveryKeyKeepsAnyValueThroughTomlAndJson) {
  // One recipe that reads every section: a contour source with every kind of output.
  Recipe recipe = default_recipe(SourceKind::contour);
  for (OutputKind kind : {OutputKind::heightmap, OutputKind::mesh, OutputKind::render, OutputKind::contours, OutputKind::map,
                          OutputKind::preview, OutputKind::volume, OutputKind::comparison})
    recipe.outputs.push_back({"out" + std::string(output_kind_name(kind)), kind, {}});
  recipe.shape.push_back({});
  const auto& table = recipe_table();
  int changed = 0;
  for (const auto& row : table.rows) {
    if (!row.exposed || row.key == "source") continue;
    params::Value value = other_value(row, row.get(recipe));
    if (!params::check(row, value).empty()) continue;  // a rule (2^k+1, AXIS=V) this generator does not know
    row.set(recipe, value);
    ++changed;
  }
  EXPECT_GT(changed, 120);
  // Mesh and world sections are not read by a contour source; check them through their own sources.
  for (SourceKind source : {SourceKind::contour, SourceKind::midpoint, SourceKind::mesh, SourceKind::file}) {
    recipe.source = source;
    const std::string text = recipe_to_toml(recipe);
    const LoadedRecipe back = parse(text);
    EXPECT_TRUE(back.warnings.empty()) << back.warnings.front();
    EXPECT_EQ(recipe_to_json(back.recipe), recipe_to_json(recipe)) << text;
    EXPECT_EQ(recipe_to_toml(back.recipe), text);
  }
}

TEST(RecipeFile, DefaultsOfEverySourceLoadBackUnchanged) {
  for (const std::string& name : source_names()) {
    const std::string text = default_recipe_text(*source_from_name(name));
    const LoadedRecipe loaded = parse(text);
    EXPECT_TRUE(loaded.warnings.empty()) << name;
    EXPECT_EQ(loaded.recipe.source, *source_from_name(name));
    EXPECT_FALSE(loaded.recipe.outputs.empty()) << name;
    EXPECT_THAT(recipe_to_toml(loaded.recipe), HasSubstr("[[output]]"));
  }
}

TEST(RecipeFile, BadFilesNameTheFileLineKeyAndWhatIsAllowed) {
  EXPECT_THAT(error_of("source = \n"), HasSubstr("scene.toml:1: not valid TOML"));
  EXPECT_EQ(
      error_of("source = \"midpoint\"\n[midpoint]\nhurts = 0.5\n"),
      "scene.toml:3: unknown key `hurts` in [midpoint]: did you mean `hurst`? (its keys: seed, hurst, sigma, additions, land_fraction, "
      "paper_sea_level)");
  EXPECT_THAT(error_of("[world]\nhurst = 0.5\n"), HasSubstr("scene.toml:2: unknown key `hurst` in [world]: `hurst` belongs in [midpoint]"));
  EXPECT_EQ(error_of("[midpoint]\nhurst = \"smooth\"\n"),
            "scene.toml:2: [midpoint] hurst = 'smooth' has the wrong type: it must be a number");
  EXPECT_EQ(error_of("[midpoint]\nhurst = 1.5\n"), "scene.toml:2: [midpoint] hurst = 1.5 is not allowed: it must be > 0 and <= 1");
  EXPECT_EQ(error_of("[midpoint]\nseed = -1\n"),
            "scene.toml:2: [midpoint] seed = -1 is not allowed: it must be a whole number between 0 and 2^63 - 1");
  EXPECT_EQ(error_of("source = \"volcano\"\n"),
            "scene.toml:1: source = 'volcano' is not allowed: it must be one of none, midpoint, file, contour, mesh, contour_map");
  EXPECT_THAT(error_of("[contour_seed]\nfile = \"no-such-seed.geojson\"\n"),
              HasSubstr("scene.toml:2: [contour_seed] file = \"no-such-seed.geojson\": no such file"));
  EXPECT_EQ(error_of("[midpoint]\nseed = 2\n[contour]\noffset = 5.0\n"),
            "scene.toml: two sources: [contour] belongs to the contour source and [midpoint] to the midpoint source; say which with "
            "source = \"...\"");
  EXPECT_THAT(error_of("sansui_recipe = 8\n"), HasSubstr("scene.toml:1: this recipe has version 8, newer than this sansui reads (7)"));
  // One sea level from version 3 on: the keys older recipes gave it in are refused, naming the new one.
  EXPECT_THAT(error_of("[[shape]]\nstep = \"stage\"\nsea_level = 5.0\n"),
              HasSubstr("scene.toml:3: [[shape]] sea_level is a key of recipes before version 3 (this one has version 7): give [world] "
                        "sea_level instead"));
  EXPECT_THAT(error_of("[render]\nsea_level = 5.0\n"), HasSubstr("scene.toml:2: [render] sea_level is a key of recipes before version 3"));
  EXPECT_THAT(error_of("[flow]\nsea_level = 5.0\n"), HasSubstr("scene.toml:2: [flow] sea_level is a key of recipes before version 3"));
  EXPECT_THAT(error_of("[world]\ncrs = \"banana\"\n"), HasSubstr("scene.toml:2: [world] crs = 'banana' is not allowed"));
  EXPECT_THAT(error_of("[world]\ncrs = \"EPSG:4326\"\n"), HasSubstr("scene.toml:2: [world] crs = 'EPSG:4326' is not allowed"));
  EXPECT_THAT(error_of("[world]\nsea_level = 1e9\n"), HasSubstr("scene.toml:2: [world] sea_level = 1000000000.0 is not allowed"));
  // Keys of version 4 in an older file, and their bad values.
  EXPECT_THAT(
      error_of("sansui_recipe = 3\n[world]\norigin = [500000.0, 5200000.0]\n"),
      HasSubstr("scene.toml:3: [world] origin is a key of recipes of version 4 on (this one has version 3): write sansui_recipe = 4"));
  EXPECT_THAT(error_of("[world]\norigin = [1.0]\n"), HasSubstr("scene.toml:2: [world] origin"));
  EXPECT_THAT(error_of("[land]\nlines = \"table4\"\n"), HasSubstr("scene.toml:2: [land] lines = 'table4' is not allowed"));
  EXPECT_THAT(error_of("[season]\nseason = \"monsoon\"\n"), HasSubstr("scene.toml:2: [season] season = 'monsoon' is not allowed"));
  EXPECT_THAT(
      error_of("[georeference]\ncrs = \"EPSG:32633\"\n"),
      HasSubstr("scene.toml:2: [georeference] crs is a key of recipes before version 3 (this one has version 7): give [world] crs"));
  EXPECT_EQ(error_of("sansui_recipe = 2\n[[shape]]\nstep = \"stage\"\nsea_level = 5.0\n[render]\nsea_level = 7.0\n"), "(no error)");
  EXPECT_THAT(error_of("[midpont]\nseed = 1\n"), HasSubstr("scene.toml:1: unknown section `midpont`: did you mean `midpoint`?"));
  EXPECT_THAT(error_of("[[output]]\nfile = \"a.png\"\nkind = \"photo\"\n"),
              HasSubstr("scene.toml:3: [[output]] kind = 'photo' is not allowed: it must be one of heightmap,"));
  EXPECT_THAT(error_of("[camera]\nazimuth = 10.0\nfov = 500.0\n"), HasSubstr("scene.toml:3: [camera] fov = 500.0 is not allowed"));
}

TEST(RecipeFile, Version3HasOneSeaLevelAndOlderRecipesKeepEachSectionsOwn) {
  const std::string world = "source = \"midpoint\"\n[world]\nsize = 65\n";
  const LoadedRecipe v3 = parse(world + "sea_level = 40.0\n[[shape]]\nstep = \"stage\"\n[[shape]]\nstep = \"erode\"\n");
  ASSERT_EQ(v3.recipe.version, recipe_version);
  for (const ShapeStep& step : v3.recipe.shape) EXPECT_EQ(step.stage.sea_level_m, 40.0);
  EXPECT_EQ(v3.recipe.render.sea_level_m, 40.0);
  EXPECT_EQ(v3.recipe.flow.sea_level_m, 40.0);
  // Written again, the sea level is one key of [world].
  std::string text = recipe_to_toml(v3.recipe);
  std::size_t keys = 0;
  for (auto at = text.find("\nsea_level = "); at != std::string::npos; at = text.find("\nsea_level = ", at + 1)) ++keys;
  EXPECT_EQ(keys, 1u) << text;
  EXPECT_EQ(recipe_to_toml(parse(text).recipe), text);
  // The CRS is the world's too.
  EXPECT_EQ(parse(world + "crs = \"EPSG:32633\"\n").recipe.georeference.crs, "EPSG:32633");
  // Without a sea, rivers end at the map's edge and low ground holds lakes, as in older recipes.
  const LoadedRecipe dry = parse(world + "sea_level = 40.0\n[render]\nsea = false\n");
  EXPECT_FALSE(dry.recipe.flow.sea_level_m.has_value());

  // The midpoint world's land fraction lies above the world's sea level (before: above 0 m).
  const Heightfield raw = recipe_heights(parse("source = \"midpoint\"\n[world]\nsize = 257\nsea_level = 40.0\n").recipe);
  const auto land = std::ranges::count_if(raw.values(), [](float h) { return h > 40.0f; });
  EXPECT_NEAR(static_cast<double>(land) / static_cast<double>(raw.size()), 0.7, 0.01);

  // A version 2 recipe keeps each section's own sea level, so its sidecars rebuild their bytes.
  const LoadedRecipe mixed = parse("sansui_recipe = 2\n" + world +
                                   "[[shape]]\nstep = \"stage\"\nsea_level = 40.0\n[render]\nsea_level = 7.0\n"
                                   "[[output]]\nfile = \"view.png\"\nkind = \"render\"\n");
  EXPECT_EQ(mixed.recipe.shape.front().stage.sea_level_m, 40.0);
  EXPECT_EQ(mixed.recipe.render.sea_level_m, 7.0);
  text = recipe_to_toml(mixed.recipe);
  EXPECT_THAT(text, HasSubstr("sea_level = 40.0"));
  EXPECT_THAT(text, HasSubstr("sea_level = 7.0"));
}

TEST(RecipeFile, KeysNoSourceOrOutputReadsAreWarnedAbout) {
  const LoadedRecipe loaded = parse("source = \"midpoint\"\n[contour]\noffset = 5.0\n[[output]]\nfile = \"a.png\"\n");
  ASSERT_EQ(loaded.warnings.size(), 1u);
  EXPECT_EQ(loaded.warnings[0],
            "scene.toml:3: [contour] offset is set but never used: the midpoint source and the outputs do not read [contour]");
}

TEST(RecipeFile, SidecarsFromANewerSansuiOrWithoutARecipeAreRefused) {
  test::TempDir dir("recipe-sidecars");
  std::ofstream(dir / "newer.png.json") << R"({"sansui_sidecar": 99, "provenance": {"recipe": {}}})";
  EXPECT_THAT(message_of([&] { load_recipe(dir / "newer.png.json"); }),
              HasSubstr("this sidecar has version 99, newer than this sansui reads"));
  std::ofstream(dir / "old.png.json") << R"({"sansui_sidecar": 1, "provenance": {"parameters": {}}})";
  EXPECT_THAT(message_of([&] { load_recipe(dir / "old.png.json"); }), HasSubstr("this sidecar holds no recipe"));
  std::ofstream(dir / "other.json") << R"({"type": "FeatureCollection"})";
  EXPECT_THAT(message_of([&] { load_recipe(dir / "other.json"); }), HasSubstr("not a Sansui sidecar"));
  std::ofstream(dir / "broken.json") << "{";
  EXPECT_THAT(message_of([&] { load_recipe(dir / "broken.json"); }), HasSubstr("broken.json: not valid JSON: parse error at line 1"));
}

TEST(RecipeFile, FileNamesAreRelativeToTheRecipeFile) {
  Recipe recipe = default_recipe(SourceKind::file);
  recipe.base_dir = "/data/work";
  recipe.file.path = "dems/a.tif";
  recipe.outputs.push_back({"out/render.png", OutputKind::render, {}, {}});
  const Recipe moved = rebased(recipe, "/data/work/scenes");
  EXPECT_EQ(moved.file.path, "../dems/a.tif");
  EXPECT_EQ(moved.outputs[0].file, "../out/render.png");
  EXPECT_EQ(rebased(moved, "/data/work").file.path, "dems/a.tif");
  recipe.file.path = "/abs/a.tif";
  EXPECT_EQ(rebased(recipe, "/elsewhere").file.path, "/abs/a.tif");
}

TEST(RecipeFile, NearestKeyFindsTypos) {
  EXPECT_EQ(nearest_key("hurts", {"seed", "hurst", "sigma"}), "hurst");
  EXPECT_EQ(nearest_key("sea_levle", {"sea_level", "stage"}), "sea_level");
  EXPECT_EQ(nearest_key("banana", {"seed", "hurst", "sigma"}), std::nullopt);
}

TEST(ParamsDoc, TheCheckedInFileIsUpToDate) {
  std::ifstream in(std::string(sansui::test::source_dir) + "/docs/params.md");
  const std::string checked_in{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_TRUE(checked_in == params_markdown()) << "docs/params.md is stale: run build/sansui params > docs/params.md";
}

}  // namespace
}  // namespace sansui::scene

namespace sansui::scene {
namespace {

// One meaning per name: a key that appears in several sections has one unit and one kind, and an
// option name means one recipe key in every command.
TEST(RecipeNames, AKeyInSeveralSectionsHasOneUnitAndKind) {
  std::map<std::string, const params::Param<Recipe>*> seen;
  for (const auto& row : recipe_table().rows) {
    if (!row.exposed) continue;
    const std::string name = row.key.substr(row.key.rfind('.') + 1);
    const auto [it, fresh] = seen.emplace(name, &row);
    if (fresh) continue;
    EXPECT_EQ(it->second->unit, row.unit) << it->second->key << " and " << row.key << " share a name: give them one unit or two names";
    EXPECT_EQ(it->second->kind, row.kind) << it->second->key << " and " << row.key;
  }
}

TEST(RecipeNames, AnOptionHasOneUnitAndKindInEveryCommand) {
  std::map<std::string, const params::Param<Recipe>*> option_row;
  for (const auto& spec : command_specs())
    for (const auto& use : spec.sections)
      for (const auto& row : recipe_table().rows) {
        if (!row.exposed || section_of(row.key) != use.section) continue;
        const std::string option = "--" + use.prefix + row.flag;
        const auto [it, fresh] = option_row.emplace(option, &row);
        EXPECT_EQ(it->second->unit, row.unit) << option << " is " << it->second->key << " in one command and " << row.key << " in "
                                              << spec.name;
        EXPECT_EQ(it->second->kind, row.kind) << option << " is " << it->second->key << " and " << row.key;
      }
  EXPECT_GT(option_row.size(), 120u);
}

}  // namespace
}  // namespace sansui::scene
