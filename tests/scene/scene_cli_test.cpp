// Parametric scenes through the binary (issue: climate, season, weather, time): the same scene
// file gives the same picture bytes; --explain says where every derived value came from; the
// gallery renders; bad scene values fail with the key, the value and what is allowed.
#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io/image_io.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/test_paths.hpp"
#include "tests/test_util.hpp"

namespace sansui::test {
namespace {

using ::testing::HasSubstr;

const std::string examples = std::string(sansui::test::source_dir) + "/examples/";

/// A small scene: a 129^2 island, autumn in a marine climate, clouds, late afternoon.
const char* const small_scene = R"(source = "midpoint"
[midpoint]
seed = 46
[world]
size = 129
cell = 40.0
[climate]
koppen = "Cfb"
[season]
season = "autumn"
[weather]
weather = "cloudy"
[time]
date = "2026-10-02"
time = "17:15"
latitude = 50.0
longitude = 5.0
utc_offset = 1.0
[render]
width = 240
height = 135
samples = 1
[[output]]
file = "scene.png"
kind = "render"
)";

TEST(SceneCli, TheSameSceneGivesTheSameBytes) {
  TempDir dir("scene-same");
  std::ofstream(dir / "scene.toml") << small_scene;
  ASSERT_EQ(run_cli_line("run scene.toml", dir.path()).exit_code, 0);
  const std::string first = read_text(dir / "scene.png");
  ASSERT_EQ(run_cli_line("run scene.toml", dir.path()).exit_code, 0);
  EXPECT_TRUE(read_text(dir / "scene.png") == first);
  // ... and -o writes that one picture elsewhere.
  ASSERT_EQ(run_cli_line("run scene.toml -o other.png", dir.path()).exit_code, 0);
  EXPECT_TRUE(read_text(dir / "other.png") == first);
}

// Tree and snow lines of the two kinds mixed: one line naming both keys, exit 2, no picture.
TEST(SceneCli, MixedLineKindsAreRefused) {
  TempDir dir("scene-mixed-lines");
  for (const char* land : {"[land]\nlines = \"paper\"\nsnow_line_m = 2000.0\n", "[land]\ntree_line = 0.5\n"}) {
    std::ofstream(dir / "scene.toml") << small_scene << land;
    const CliResult r = run_cli_line("run scene.toml", dir.path());
    EXPECT_EQ(r.exit_code, 2) << land;
    EXPECT_THAT(r.err, HasSubstr("read with land.lines = ")) << land;
    EXPECT_FALSE(std::filesystem::exists(dir / "scene.png")) << land;
  }
}

TEST(SceneCli, ExplainNamesTheSourceOfEveryDerivedValue) {
  TempDir dir("scene-explain");
  std::string scene = small_scene;
  scene += "[land]\ntree_line_m = 420\n";
  std::ofstream(dir / "scene.toml") << scene;
  const CliResult r = run_cli_line("run --explain scene.toml", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.all();
  int lines = 0;
  for (std::size_t start = 0; start < r.out.size();) {
    const std::size_t end = r.out.find('\n', start);
    const std::string line = r.out.substr(start, end - start);
    start = end + 1;
    const auto open = line.rfind('(');
    ASSERT_NE(open, std::string::npos) << line;
    EXPECT_GT(line.size() - open, 3u) << "no source: " << line;
    ++lines;
  }
  EXPECT_GE(lines, 18);
  EXPECT_THAT(r.out, HasSubstr("land.tree_line_m     = 420"));
  EXPECT_THAT(r.out, HasSubstr("(set in the recipe)"));
  EXPECT_THAT(r.out, HasSubstr("(climatic snow line at 50 deg (Wilhelm 1975); Cfb: -200 m; season autumn"));
  EXPECT_THAT(r.out, HasSubstr("season autumn"));
  EXPECT_THAT(r.out, HasSubstr("NOAA solar position: 2026-10-02 17:15"));
  EXPECT_FALSE(std::filesystem::exists(dir / "scene.png"));  // --explain renders nothing
}

TEST(SceneCli, TheGalleryRenders) {
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(examples + "scenes/gallery")) {
    if (entry.path().extension() != ".toml") continue;
    TempDir dir("scene-gallery-" + entry.path().stem().string());
    const CliResult r = run_cli_line("run " + entry.path().string() + " --out-dir " + dir.path().string(), dir.path());
    ASSERT_EQ(r.exit_code, 0) << entry.path() << ": " << r.all();
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
    const Image picture = io::read_png(dir / (entry.path().stem().string() + ".png"));
    EXPECT_EQ(picture.width(), 1280);
    ++scenes;
  }
  EXPECT_GE(scenes, 6);
}

/// Two named cameras and a render output for each.
const char* const two_cameras = R"(
[[camera]]
name = "south"
azimuth = 180.0
[[camera]]
name = "high"
azimuth = 45.0
elevation = 60.0
[[output]]
file = "south.png"
kind = "render"
camera = "south"
[[output]]
file = "high.png"
kind = "render"
camera = "high"
)";

TEST(SceneCli, EachRenderOutputDrawsWithTheCameraItNames) {
  TempDir dir("scene-cameras");
  std::string scene = small_scene;
  scene = scene.substr(0, scene.find("[[output]]")) + two_cameras;
  std::ofstream(dir / "scene.toml") << scene;
  const CliResult r = run_cli_line("run scene.toml", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.all();
  const std::string south = read_text(dir / "south.png");
  const std::string high = read_text(dir / "high.png");
  EXPECT_FALSE(south == high);
  // The first camera with no output naming it is the default: it draws south.png again.
  ASSERT_EQ(run_cli_line("run scene.toml -o first.png", dir.path()).exit_code, 2);  // two render outputs: -o cannot choose
  // Each picture's sidecar holds its own camera only, and rebuilds the picture byte for byte.
  const std::string sidecar = read_text(dir / "high.png.json");
  EXPECT_THAT(sidecar, HasSubstr("\"elevation\": 60"));
  EXPECT_EQ(sidecar.find("south"), std::string::npos);
  std::filesystem::rename(dir / "high.png", dir / "high-first.png");
  ASSERT_EQ(run_cli_line("run high.png.json", dir.path()).exit_code, 0);
  EXPECT_TRUE(read_text(dir / "high.png") == high);
}

struct BadScene {
  std::string label, change, message;
};

class BadSceneValue : public ::testing::TestWithParam<BadScene> {};

/// The small scene without its climate, season, weather and time, which the cases set.
const char* const plain_scene = R"(source = "midpoint"
[world]
size = 65
[render]
width = 64
height = 64
samples = 1
[[output]]
file = "scene.png"
kind = "render"
)";

TEST_P(BadSceneValue, IsRefusedWithTheKeyAndNoPicture) {
  TempDir dir("scene-bad-" + GetParam().label);
  std::ofstream(dir / "scene.toml") << plain_scene << GetParam().change << "\n";
  const CliResult r = run_cli_line("run scene.toml", dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.all();
  EXPECT_THAT(r.err, HasSubstr(GetParam().message));
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "scene.png"));
}

INSTANTIATE_TEST_SUITE_P(
    Values, BadSceneValue,
    ::testing::Values(
        BadScene{"climate", "[climate]\nkoppen = \"Xy\"", "koppen = 'Xy' is not allowed: it must be one of Af, Am, Aw, BW"},
        BadScene{"season", "[season]\nseason = \"monsoon\"", "season = 'monsoon' is not allowed: it must be one of spring, summer"},
        BadScene{"weather", "[weather]\nweather = \"hail\"", "weather = 'hail' is not allowed: it must be one of clear, cloudy"},
        BadScene{"date", "[time]\ndate = \"2026-02-30\"",
                 "date = '2026-02-30' is not allowed: it must be a date YYYY-MM-DD with the day 01..28"},
        BadScene{"time", "[time]\ntime = \"25:10\"",
                 "time = '25:10' is not allowed: it must be a time HH:MM or HH:MM:SS, 00:00 to 23:59:59"},
        BadScene{"latitude", "[time]\nlatitude = 95.0", "latitude = 95.0 is not allowed: it must be between -90 and 90 deg"},
        BadScene{"type", "[sky]\nturbidity = \"high\"", "[sky] turbidity = 'high' has the wrong type: it must be a number"},
        BadScene{"range", "[sky]\ncloud_cover = 1.5", "[sky] cloud_cover = 1.5 is not allowed: it must be between 0 and 1"},
        BadScene{"cover_slope", "[land]\ncover_slope = 120.0",
                 "[land] cover_slope = 120.0 is not allowed: it must be between 0 and 90 deg"},
        BadScene{"unnamed_cameras", "[[camera]]\nazimuth = 10.0\n[[camera]]\nazimuth = 20.0", "a scene with 2 cameras must name each"},
        BadScene{"same_camera_names", "[[camera]]\nname = \"a\"\n[[camera]]\nname = \"a\"", "two cameras are named \"a\""},
        BadScene{"unknown_camera",
                 "[[camera]]\nname = \"a\"\n[[camera]]\nname = \"b\"\n[[output]]\nfile = \"other.png\"\nkind = \"render\"\ncamera = \"c\"",
                 "names camera \"c\": the scene's cameras are a b"},
        BadScene{"camera_key", "[[camera]]\nname = \"a\"\nzoom = 2.0", "unknown key zoom in [[camera]]"}),
    [](const auto& test) { return test.param.label; });

TEST(SceneCli, AMissingHeightmapIsNamed) {
  TempDir dir("scene-missing-heightmap");
  std::ofstream(dir / "scene.toml")
      << "source = \"file\"\n[file]\npath = \"nowhere.png\"\n[[output]]\nfile = \"x.png\"\nkind = \"render\"\n";
  const CliResult r = run_cli_line("run scene.toml", dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("scene.toml:3: [file] path = \"nowhere.png\": no such file"));
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

}  // namespace
}  // namespace sansui::test
