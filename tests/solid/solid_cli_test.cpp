// `sansui solid` end to end: the real binary, its outputs, and every bad input with its message,
// exit code 2 and no file left behind.
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/image_io.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/test_util.hpp"

namespace sansui {
namespace {

using CliRun = test::CliResult;
using test::run_cli_line;

std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(SolidCli, WritesTheVolumeAndThePictures) {
  test::TempDir dir("solid-cli");
  const std::string d = dir.path().string();
  const CliRun run = run_cli_line("solid --type III --levels 5 --seed 3 -o " + d + "/f.r32 --sphere " + d + "/s.png --cube " + d +
                                  "/c.png --slice-at z=50% --slice " + d + "/l.png --picture-size 64 --texture green-marble");
  ASSERT_EQ(run.exit_code, 0) << run.all();
  EXPECT_EQ(std::filesystem::file_size(dir / "f.r32"), 33u * 33u * 33u * 4u);
  const auto json = nlohmann::json::parse(std::ifstream(dir / "f.r32.json"));
  EXPECT_EQ(json["size"], nlohmann::json({33, 33, 33}));
  EXPECT_EQ(json["provenance"]["recipe"]["solid"]["type"], "III");
  for (const char* png : {"s.png", "c.png", "l.png"}) {
    const Image image = io::read_png(dir / png);
    EXPECT_EQ(image.width(), 64) << png;
    EXPECT_EQ(image.height(), 64) << png;
  }
}

TEST(SolidCli, EveryTypeWritesTheSameBytes) {
  test::TempDir dir("solid-cli-types");
  std::string first;
  for (const char* type : {"I", "II", "III", "IV"}) {
    const std::string name = std::string(type) + ".r32";
    const CliRun run =
        run_cli_line(std::string("solid --type ") + type + " --levels 5 --r2 3 --beta 0.4 --corners 1,0,0,0,0,0,0,-1 -o " +
                     (dir / name).string() + " --sphere " + (dir / (std::string(type) + ".png")).string() + " --picture-size 48");
    ASSERT_EQ(run.exit_code, 0) << run.all();
    const std::string bytes = file_bytes(dir / name) + file_bytes(dir / (std::string(type) + ".png"));
    if (first.empty()) first = bytes;
    EXPECT_EQ(bytes, first) << "type " << type;
  }
}

struct BadInput {
  std::string arguments;  // %D stands for a file in the test's directory
  std::string message;
};

class SolidCliBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(SolidCliBadInput, FailsWithAMessageAndLeavesNoFile) {
  test::TempDir dir("solid-cli-bad");
  auto with_dir = [&](std::string text) {
    for (std::size_t at; (at = text.find("%D")) != std::string::npos;) text.replace(at, 2, dir.path().string());
    return text;
  };
  const CliRun run = run_cli_line("solid " + with_dir(GetParam().arguments));
  EXPECT_EQ(run.exit_code, 2) << run.all();
  EXPECT_EQ(run.all(), "sansui: " + with_dir(GetParam().message) + "\n");
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, SolidCliBadInput,
    ::testing::Values(
        BadInput{"--levels 0 --sphere %D/s.png", "--levels 0 is not allowed: it must be between 1 and 20"},
        BadInput{"--type III --levels 21 --sphere %D/s.png", "--levels 21 is not allowed: it must be between 1 and 20"},
        BadInput{"--type I --levels 9 --memory 100 -o %D/f.r32",
                 "Type I at R = 9 needs 540.0 MB for its 513^3 lattice, more than the 100.0 MB of memory available: use --type III or IV"},
        BadInput{"--type II --levels 9 --memory 100 -o %D/f.r32",
                 "Type II at R = 9 needs about 5.4 GB for the 1.35e+08 nodes of its map, more than the 100.0 MB of memory available: use "
                 "--type III or IV"},
        BadInput{"--type IV --levels 8 --r2 9 --sphere %D/s.png", "solid.r2 9 is not allowed: it must be 0..R (R = 8)"},
        BadInput{"--beta 0 --sphere %D/s.png", "--beta 0 is not allowed: it must be > 0 and <= 100"},
        BadInput{"--beta -2 --sphere %D/s.png", "--beta -2 is not allowed: it must be > 0 and <= 100"},
        BadInput{"--corners 0,0,0,nan,0,0,0,0 --sphere %D/s.png",
                 "--corners 0,0,0,nan,0,0,0,0 is not allowed: it must be 8 numbers, all finite"},
        BadInput{"--corners 1,2,3 --sphere %D/s.png", "--corners 1,2,3 is not allowed: it must be 8 numbers"},
        BadInput{"--levels 6 --slice-at z=65 --slice %D/l.png",
                 "solid.slice_at 'z=65' is outside the block: V must be in [0, 64] (or 0%..100%)"},
        BadInput{"--slice-at w=3 --slice %D/l.png",
                 "--slice-at 'w=3' is not allowed: it must be AXIS=V with AXIS x, y or z and V in lattice units 0..2^R or a percentage, "
                 "e.g. z=50%"},
        BadInput{
            "--texture granite --sphere %D/s.png",
            "--texture 'granite' is not allowed: it must be one of white-marble, green-marble, oak, pine, strata, marble, wood, field"},
        BadInput{"--type V --sphere %D/s.png", "--type 'V' is not allowed: it must be one of I, II, III, IV"},
        BadInput{"-o %D/f.png", "volume output %D/f.png has the extension '.png': allowed are .r32"},
        BadInput{"--sphere %D/missing/s.png", "cannot write %D/missing/s.png: directory %D/missing does not exist"},
        BadInput{"--picture-size 4 --sphere %D/s.png", "--picture-size 4 is not allowed: it must be between 8 and 8192 px"},
        BadInput{"--levels 4", "no output: the recipe writes nothing (add an [[output]], or -o FILE on the command line)"}));

}  // namespace
}  // namespace sansui

namespace sansui {
namespace {

TEST(SolidCli, BenchPrintsThePapersTables) {
  const CliRun run =
      run_cli_line("bench solid --exp1-from 2 --exp1-to 4 --exp2-from 3 --exp2-to 5 --memory-levels 4 --r2 2 --skip-targets");
  ASSERT_EQ(run.exit_code, 0) << run.all();
  for (const char* heading : {"Experiment 1: every lattice point", "Experiment 2: the voxels on the surface", "Memory at R = 4",
                              "C3 = 13 x 19 x R", "How far each type goes"})
    EXPECT_NE(run.all().find(heading), std::string::npos) << heading;
  EXPECT_NE(run.all().find("4,913"), std::string::npos) << run.all();  // R = 4 has 17^3 points
  EXPECT_EQ(run.all().find("(failed)"), std::string::npos) << run.all();
  const CliRun bad = run_cli_line("bench solid --exp1-to 13");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(bad.all(), "sansui: --exp1-to 13 is not allowed: it must be between 1 and 12\n");
}

}  // namespace
}  // namespace sansui

namespace sansui {
namespace {

TEST(SolidCli, RenderColoursCliffsWithRock) {
  test::TempDir dir("solid-cli-rock");
  const std::string d = dir.path().string();
  ASSERT_EQ(run_cli_line("terrain --size 129 --seed 1 --cell 40 -o " + d + "/t.r32").exit_code, 0);
  const std::string common = "render " + d + "/t.r32 --width 240 --height 160 --samples 1";
  const CliRun plain = run_cli_line(common + " -o " + d + "/plain.png");
  ASSERT_EQ(plain.exit_code, 0) << plain.all();
  const CliRun strata = run_cli_line(common + " --rock strata -o " + d + "/strata.png");
  ASSERT_EQ(strata.exit_code, 0) << strata.all();
  const CliRun marble = run_cli_line(common + " --rock marble --rock-scale 400 -o " + d + "/marble.png");
  ASSERT_EQ(marble.exit_code, 0) << marble.all();
  EXPECT_NE(file_bytes(dir / "plain.png"), file_bytes(dir / "strata.png"));
  EXPECT_NE(file_bytes(dir / "strata.png"), file_bytes(dir / "marble.png"));

  const CliRun bad = run_cli_line(common + " --rock granite -o " + d + "/bad.png");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(bad.all(),
            "sansui: --rock-texture 'granite' is not allowed: it must be one of none, white-marble, green-marble, oak, pine, strata, "
            "marble, wood\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.png"));
  const CliRun bad_scale = run_cli_line(common + " --rock strata --rock-scale 0 -o " + d + "/bad.png");
  EXPECT_EQ(bad_scale.exit_code, 2);
  EXPECT_EQ(bad_scale.all(), "sansui: --rock-scale 0 is not allowed: it must be > 0 and <= 10000000 m\n");
}

}  // namespace
}  // namespace sansui
