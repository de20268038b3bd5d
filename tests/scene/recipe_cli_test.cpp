// Recipes through the binary: every command's --save-recipe file, run by `sansui run`, gives the
// command's bytes again; so does every output's own sidecar; --print-defaults files load and run;
// bad scene files fail with one line, exit 2 and no file.
#include <fstream>
#include <map>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/cli/cli_runner.hpp"
#include "tests/test_paths.hpp"
#include "tests/test_util.hpp"

namespace sansui::test {
namespace {

using ::testing::HasSubstr;

const std::string examples = std::string(sansui::test::source_dir) + "/examples/";

std::string with_examples(std::string text) {
  for (std::size_t at; (at = text.find("%E")) != std::string::npos;) text.replace(at, 2, examples);
  return text;
}

std::map<std::string, std::string> outputs_in(const std::filesystem::path& dir, const std::vector<std::string>& names) {
  std::map<std::string, std::string> bytes;
  for (const auto& name : names) bytes[name] = read_text(dir / name);
  return bytes;
}

void remove_outputs(const std::filesystem::path& dir, const std::vector<std::string>& names) {
  for (const auto& name : names) {
    std::filesystem::remove(dir / name);
    std::filesystem::remove(dir / (name + ".json"));
  }
}

struct CommandCase {
  std::string label;
  std::string arguments;             // run in the test's directory; %E: the examples directory
  std::vector<std::string> outputs;  // files the command writes there
};

class RecipeCli : public ::testing::TestWithParam<CommandCase> {};

TEST_P(RecipeCli, TheSavedRecipeAndEverySidecarRebuildTheSameBytes) {
  TempDir dir("recipe-cli-" + GetParam().label);
  const auto& outputs = GetParam().outputs;
  // An input heightmap for the commands that read one.
  ASSERT_EQ(run_cli_line("terrain --size 65 --seed 4 -o input.png", dir.path()).exit_code, 0);
  const CliResult first = run_cli_line(with_examples(GetParam().arguments) + " --save-recipe recipe.toml", dir.path());
  ASSERT_EQ(first.exit_code, 0) << first.all();
  const auto expected = outputs_in(dir.path(), outputs);
  for (const auto& [name, bytes] : expected) ASSERT_FALSE(bytes.empty()) << name;

  // The scene file, run from elsewhere: its file names are relative to itself.
  remove_outputs(dir.path(), outputs);
  const CliResult again = run_cli_line("run " + (dir / "recipe.toml").string(), std::filesystem::temp_directory_path());
  ASSERT_EQ(again.exit_code, 0) << again.all();
  EXPECT_EQ(again.err.find("warning"), std::string::npos) << again.err;
  for (const auto& [name, bytes] : outputs_in(dir.path(), outputs)) EXPECT_TRUE(bytes == expected.at(name)) << name << " differs";

  // Each output's sidecar holds the recipe of that one file.
  for (const auto& name : outputs) {
    const auto sidecar = nlohmann::json::parse(read_text(dir / (name + ".json")));
    ASSERT_EQ(sidecar["provenance"]["recipe"]["output"].size(), 1u) << name;
    EXPECT_EQ(sidecar["provenance"]["recipe"]["output"][0]["file"], name);
    std::filesystem::remove(dir / name);
    const CliResult rebuilt = run_cli_line("run " + (dir / (name + ".json")).string(), std::filesystem::temp_directory_path());
    ASSERT_EQ(rebuilt.exit_code, 0) << name << ": " << rebuilt.all();
    EXPECT_TRUE(read_text(dir / name) == expected.at(name)) << name << " rebuilt from its sidecar differs";
  }
}

INSTANTIATE_TEST_SUITE_P(
    Commands, RecipeCli,
    ::testing::Values(CommandCase{"terrain",
                                  "terrain --size 129 --seed 3 --stage young -o t.png -o t.r32 -o t.tif -o t.raw -o t.obj -o t.glb",
                                  {"t.png", "t.r32", "t.tif", "t.raw", "t.obj", "t.glb"}},
                      CommandCase{"tile", "terrain --world-size 257 --tile 1,0 --tile-size 129 --lod 1 -o tile.png", {"tile.png"}},
                      CommandCase{"render", "render input.png --rock strata --width 160 --height 96 --samples 1 -o r.png", {"r.png"}},
                      CommandCase{"render_top", "render input.png --view top --width 96 --samples 1 --no-shadows -o top.png", {"top.png"}},
                      CommandCase{"contour",
                                  "contour %E/contours/c_shape.csv --contours c.geojson --map c.svg --map c.png --dem c.r32 --dem-size 129 "
                                  "--dem-noise 2 --render cr.png --width 160 --height 96 --samples 1",
                                  {"c.geojson", "c.svg", "c.png", "c.r32", "cr.png"}},
                      CommandCase{"contour_from_dem",
                                  "contour --from-dem %E/dem/jacksboro_ridge.tif --level 800 --dem m.tif --contours m.geojson",
                                  {"m.tif", "m.geojson"}},
                      CommandCase{"compare",
                                  "compare %E/dem/jacksboro_ridge.tif %E/dem/jacksboro_ridge.tif --json cmp.json --map-real mr.svg "
                                  "--map-generated mg.png --map-width 300",
                                  {"cmp.json", "mr.svg", "mg.png"}},
                      CommandCase{"solid",
                                  "solid --levels 5 --sphere s.png --cube c.png --slice l.png --slice-at x=25% -o v.r32 --picture-size 48",
                                  {"s.png", "c.png", "l.png", "v.r32"}},
                      CommandCase{
                          "subdivide",
                          "subdivide %E/meshes/mountain80.obj --steps 3 -o m.glb -o m.obj --dem m.png --dem-size 129 --preview p.png "
                          "--render mr.png --width 160 --height 96 --samples 1",
                          {"m.glb", "m.obj", "m.png", "p.png", "mr.png"}},
                      CommandCase{"sketch",
                                  "subdivide --sketch %E/sketches/mountain80.geojson --sketch-frame 50 --steps 2 --dem s.r32 --dem-size 65",
                                  {"s.r32"}}),
    [](const auto& test) { return test.param.label; });

TEST(RecipeCli, DefaultsOfEverySourceRun) {
  TempDir dir("recipe-defaults");
  ASSERT_EQ(run_cli_line("terrain --size 129 --seed 4 -o heightmap.png", dir.path()).exit_code, 0);
  std::filesystem::copy_file(examples + "contours/ridge.geojson", dir / "seed.geojson");
  for (const char* source : {"midpoint", "file", "contour", "mesh", "none"}) {
    const CliResult printed = run_cli_line(std::string("run --print-defaults --source ") + source, dir.path());
    ASSERT_EQ(printed.exit_code, 0) << printed.all();
    std::ofstream(dir / "defaults.toml") << printed.out;
    const CliResult run = run_cli_line("run defaults.toml", dir.path());
    EXPECT_EQ(run.exit_code, 0) << source << ": " << run.all();
    EXPECT_EQ(run.err.find("warning"), std::string::npos) << run.err;
    EXPECT_TRUE(std::filesystem::exists(dir / (std::string(source) == "none" ? "sphere.png" : "render.png"))) << source;
    std::filesystem::remove(dir / "render.png");
  }
}

struct BadScene {
  std::string label;
  std::string text;
  std::string message;
};

class BadSceneCli : public ::testing::TestWithParam<BadScene> {};

TEST_P(BadSceneCli, IsOneLineExitTwoAndNoFile) {
  TempDir dir("recipe-bad-" + GetParam().label);
  std::ofstream(dir / "scene.toml") << GetParam().text;
  TempDir outputs("recipe-bad-outputs-" + GetParam().label);
  expect_rejected(run_cli_line("run " + (dir / "scene.toml").string() + " --out-dir " + outputs.path().string()), GetParam().message,
                  outputs.path());
}

INSTANTIATE_TEST_SUITE_P(
    Files, BadSceneCli,
    ::testing::Values(BadScene{"not_toml", "this is not toml\n", "scene.toml:1: not valid TOML"},
                      BadScene{"unknown_key", "[midpoint]\nhurts = 0.5\n[[output]]\nfile = \"a.png\"\n", "did you mean `hurst`?"},
                      BadScene{"wrong_type", "[world]\nsize = \"big\"\n[[output]]\nfile = \"a.png\"\n",
                               "scene.toml:2: [world] size = 'big' has the wrong type: it must be a whole number"},
                      BadScene{"out_of_range", "[world]\nsize = 1000\n[[output]]\nfile = \"a.png\"\n",
                               "scene.toml:2: [world] size = 1000 is not allowed: it must be 2^k+1 or an Unreal landscape size (505, 1009, "
                               "2017, 4033, 8129...) between 3 and 16385"},
                      BadScene{"unknown_source", "source = \"lava\"\n", "scene.toml:1: source = 'lava' is not allowed"},
                      BadScene{"missing_input",
                               "source = \"file\"\n[file]\npath = \"nowhere.tif\"\n[[output]]\nfile = \"r.png\"\nkind = \"render\"\n",
                               "scene.toml:3: [file] path = \"nowhere.tif\": no such file"},
                      BadScene{"two_sources", "[midpoint]\nseed = 1\n[mesh]\npyramid = [10, 5]\n", "two sources"},
                      BadScene{"no_output", "source = \"midpoint\"\n", "no output"},
                      BadScene{"newer", "sansui_recipe = 8\n", "newer than this sansui reads"}),
    [](const auto& test) { return test.param.label; });

TEST(RecipeCli, ASidecarFromANewerVersionIsRefused) {
  TempDir dir("recipe-newer-sidecar");
  std::ofstream(dir / "a.png.json") << R"({"sansui_sidecar": 3, "provenance": {"recipe": {"source": "midpoint"}}})";
  const CliResult r = run_cli_line("run a.png.json", dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("this sidecar has version 3, newer than this sansui reads (2): run it with a newer sansui"));
}

TEST(RecipeCli, TheExampleScenesRunWithoutWarnings) {
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(examples + "scenes")) {
    if (entry.path().extension() != ".toml") continue;
    TempDir dir("recipe-example-" + entry.path().stem().string());
    const CliResult r = run_cli_line("run " + entry.path().string() + " --out-dir " + dir.path().string(), dir.path());
    EXPECT_EQ(r.exit_code, 0) << entry.path() << ": " << r.all();
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
    const auto written = files_in(dir.path());
    EXPECT_GE(written.size(), 4u) << entry.path();  // at least two files and their sidecars
    ++scenes;
  }
  EXPECT_GE(scenes, 4);
}

TEST(RecipeCli, OutputCanBeRedirected) {
  TempDir dir("recipe-redirect");
  ASSERT_EQ(run_cli_line("terrain --size 65 -o a.r32", dir.path()).exit_code, 0);
  const CliResult r = run_cli_line("run a.r32.json -o b.r32", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.all();
  EXPECT_EQ(read_text(dir / "a.r32"), read_text(dir / "b.r32"));
}

}  // namespace
}  // namespace sansui::test
