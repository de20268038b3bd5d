// `sansui render` as a user runs it: the real binary, no display.
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/color.hpp"
#include "io/image_io.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/test_util.hpp"

namespace sansui {
namespace {

test::CliResult run_cli(const std::string& arguments, const test::TempDir& dir) {
  return test::run_cli_line(arguments, dir.path());
}

class RenderCli : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_EQ(run_cli("terrain --size 129 --seed 7 --cell 40 -o terrain.r32", dir_).exit_code, 0); }
  test::TempDir dir_{"render-cli"};
};

TEST_F(RenderCli, DrawsBothViews) {
  const test::CliResult perspective = run_cli("render terrain.r32 --width 320 --height 180 --samples 1 -o view.png", dir_);
  ASSERT_EQ(perspective.exit_code, 0) << perspective.err;
  const Image image = io::read_png(dir_ / "view.png");
  EXPECT_EQ(image.width(), 320);
  EXPECT_EQ(image.height(), 180);

  // The block in the sky: the backdrop's blue above it.
  const test::CliResult block = run_cli("render terrain.r32 --view block --width 320 --height 180 --samples 1 -o block.png", dir_);
  ASSERT_EQ(block.exit_code, 0) << block.err;
  const Image block_image = io::read_png(dir_ / "block.png");
  EXPECT_GT(block_image(10, 2).b, block_image(10, 2).r);

  const test::CliResult top = run_cli("render terrain.r32 --view top --width 200 --sun 135,20 --samples 1 -o top.png", dir_);
  ASSERT_EQ(top.exit_code, 0) << top.err;
  const Image top_image = io::read_png(dir_ / "top.png");
  EXPECT_EQ(top_image.width(), 200);
  EXPECT_EQ(top_image.height(), 200);  // the terrain's aspect by default
}

TEST_F(RenderCli, BadInputGivesOneLineExitTwoAndNoFile) {
  const struct {
    std::string arguments, message;
  } cases[] = {
      {"--view oblique", "--view 'oblique' is not allowed: it must be one of perspective, block, top, front, side"},
      {"--width 8", "--width 8 is not allowed: it must be between 16 and 8192 px"},
      {"--sun 45", "--sun 45 is not allowed: it must be 2 numbers"},
      {"--sun 45,100", "--sun 45,100 is not allowed: it must be AZIMUTH,ELEVATION with the elevation -90..90"},
      {"--camera-elevation 0", "camera.elevation 0 is below 1 degree: an orbiting camera stays above its target"},
      {"--fov 1", "--camera-fov 1 is not allowed: it must be between 5 and 120 deg"},
      {"--target 0.5", "--camera-target 0.5 is not allowed: it must be 2 numbers"},
      {"--exaggeration -2", "--exaggeration -2 is not allowed: it must be between 0.1 and 20"},
      {"--exaggeration nan", "--exaggeration nan is not allowed"},
      {"--snow-line 3", "--snow-line 3 is not allowed: it must be between 0 and 1"},
      {"--samples 0", "--samples 0 is not allowed: it must be between 1 and 16"},
  };
  for (const auto& c : cases) {
    const test::CliResult run = run_cli("render terrain.r32 " + c.arguments + " -o bad.png", dir_);
    EXPECT_EQ(run.exit_code, 2) << c.arguments;
    EXPECT_THAT(run.err, ::testing::HasSubstr(c.message)) << c.arguments;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_FALSE(std::filesystem::exists(dir_ / "bad.png")) << c.arguments;
  }
  const test::CliResult jpeg = run_cli("render terrain.r32 -o bad.jpg", dir_);
  EXPECT_EQ(jpeg.exit_code, 2);
  EXPECT_THAT(jpeg.err, ::testing::HasSubstr("render output bad.jpg has the extension '.jpg': allowed are .png"));
  const test::CliResult missing_dir = run_cli("render terrain.r32 -o nowhere/bad.png", dir_);
  EXPECT_EQ(missing_dir.exit_code, 2);
  EXPECT_THAT(missing_dir.err, ::testing::HasSubstr("nowhere"));
  const test::CliResult missing_input = run_cli("render missing.r32 -o bad.png", dir_);
  EXPECT_EQ(missing_input.exit_code, 2);
  EXPECT_THAT(missing_input.err, ::testing::HasSubstr("missing.r32"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "bad.png"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "bad.jpg"));
}

TEST_F(RenderCli, CorruptOrNanHeightmapsAreRejected) {
  std::ofstream(dir_ / "corrupt.png", std::ios::binary) << "\x89PNG\r\n\x1a\n this is not a picture";
  const float with_nan[4] = {1.0f, 2.0f, std::nanf(""), 4.0f};
  std::ofstream(dir_ / "nan.r32", std::ios::binary).write(reinterpret_cast<const char*>(with_nan), sizeof with_nan);
  for (const char* input : {"corrupt.png", "nan.r32"}) {
    const test::CliResult run = run_cli(std::string("render ") + input + " -o bad.png", dir_);
    EXPECT_EQ(run.exit_code, 2) << input;
    EXPECT_THAT(run.err, ::testing::HasSubstr(input));
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_FALSE(std::filesystem::exists(dir_ / "bad.png"));
  }
}

}  // namespace
}  // namespace sansui
