// One budget (issue 30): each stage whose memory or time follows from its parameters estimates
// both before it allocates, and core/budget.hpp checks them in one place. A refusal is exit 2,
// one line naming the estimate, the limit and the way out, no file written, and a small process.
// The sweep at the end runs each stage at a few sizes and compares the estimate (read from the
// refusal under a tiny --max-memory) with the peak resident memory the real run adds over a
// baseline run of the same stage at its smallest.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <regex>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/cli/cli_runner.hpp"
#include "tests/cli/measured_run.hpp"
#include "tests/test_util.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define SANSUI_BUDGET_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SANSUI_BUDGET_ASAN 1
#endif
#endif

namespace sansui::test {
namespace {

using ::testing::HasSubstr;

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

/// A species file of one broadleaf species, every number inside its documented range.
std::string species_file(int branching, int depth, int leaves_per_twig) {
  return "[[species]]\nname = \"big\"\nform = \"broadleaf\"\nbranching = " + std::to_string(branching) +
         "\ndepth = " + std::to_string(depth) + "\nleaves_per_twig = " + std::to_string(leaves_per_twig) + "\n";
}

/// A 10 km square world of 65 x 65 samples, nearly all land, with dense trees and ground plants
/// written as a plants CSV.
std::string plants_scene(double spacing_m, double ground_spacing_m) {
  return "sansui_recipe = 4\nsource = \"midpoint\"\n[midpoint]\nseed = 21\nland_fraction = 0.99\n[world]\nsize = 65\ncell = 160.0\n"
         "[climate]\nkoppen = \"Cfa\"\n[vegetation]\ndensity = 1.0\nspacing = " +
         std::to_string(spacing_m) + "\nground_density = 1.0\nground_spacing = " + std::to_string(ground_spacing_m) +
         "\n[[output]]\nfile = \"plants.csv\"\nkind = \"plants\"\n";
}

/// Five nested circular contours, 100 m apart, in a projected CRS.
std::string rings_geojson() {
  std::string features;
  for (int k = 1; k <= 5; ++k) {
    const double radius = 1000.0 - 150.0 * k;
    std::string points;
    for (int i = 0; i <= 64; ++i) {
      const double angle = 2.0 * 3.141592653589793 * (i % 64) / 64.0;
      points += (i ? "," : "") + fmt::format("[{:.6f},{:.6f}]", radius * std::cos(angle), radius * std::sin(angle));
    }
    features += fmt::format(
        "{}{{\"type\":\"Feature\",\"properties\":{{\"elev\":{}}},\"geometry\":{{\"type\":\"LineString\",\"coordinates\":[{}]}}}}",
        k > 1 ? "," : "", 100 * k, points);
  }
  return "{\"type\":\"FeatureCollection\",\"crs\":{\"type\":\"name\",\"properties\":{\"name\":\"urn:ogc:def:crs:EPSG::32633\"}},"
         "\"features\":[" +
         features + "]}";
}

/// A midpoint recipe of `size` samples with `steps` copies of `step` (a [[shape]] table's keys).
std::string shape_recipe(int size, int steps, const std::string& step) {
  std::string text = "sansui_recipe = 4\nsource = \"midpoint\"\n[world]\nsize = " + std::to_string(size) + "\n";
  for (int i = 0; i < steps; ++i) text += "[[shape]]\n" + step;
  return text + "[[output]]\nfile = \"t.r32\"\nkind = \"heightmap\"\n";
}

/// Refused by the budget before work: exit 2, one line holding `message`, nothing in `out`, at
/// most 300 MB of peak memory (the sanitizer build's start-up takes about 60; a render's GL
/// library about 200) within a few seconds.
void expect_refused(const MeasuredRun& run, const std::string& message, const std::filesystem::path& out) {
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_THAT(run.err, HasSubstr(message));
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_LT(run.peak_rss_mb, 300) << run.err;
  EXPECT_LT(run.seconds, 10.0) << run.err;
  EXPECT_TRUE(files_in(out).empty()) << out;
}

class Budget : public ::testing::Test {
 protected:
  void SetUp() override {
    std::filesystem::create_directories(in());
    std::filesystem::create_directories(out());
  }
  std::filesystem::path in() const { return directory_.path() / "in"; }
  std::filesystem::path out() const { return directory_.path() / "out"; }
  std::string in(const std::string& file) const { return (in() / file).string(); }
  std::string out(const std::string& file) const { return (out() / file).string(); }
  /// A small heightmap for the render tests.
  std::string heightmap() const {
    const std::string path = in("h.r32");
    if (!std::filesystem::exists(path)) {
      const CliResult made = run_cli({"--quiet", "terrain", "--size", "65", "--no-erode", "-o", path});
      EXPECT_EQ(made.exit_code, 0) << made.all();
    }
    return path;
  }

 private:
  TempDir directory_{"budget"};
};

TEST_F(Budget, AHostileSpeciesFileIsRefusedBeforeGrowing) {
  // 90 bytes, every number in its range: 4.7e8 branches and 6.4e10 triangles (it reached 3.4 GB
  // in a minute before).
  write_text(in() / "big.toml", species_file(12, 8, 64));
  const MeasuredRun run = run_measured({"tree", "--species-file", in("big.toml"), "--species", "big", "-o", out("big.glb")}, out());
  expect_refused(
      run, "big.toml:1: the plant 'big' (branching 12, depth 8, 64 leaves per twig: 4.69e+08 branches, 6.42e+10 triangles) needs", out());
  EXPECT_THAT(run.err, HasSubstr("more than the memory limit of"));
  EXPECT_THAT(run.err, HasSubstr("(raise it with --max-memory GB, or lower its branching, depth or leaves_per_twig)"));
}

TEST_F(Budget, PlantsOverATenKilometreTerrainAreRefusedBeforePlacing) {
  write_text(in() / "plants.toml", plants_scene(8.0, 0.2));
  const MeasuredRun run = run_measured({"run", in("plants.toml"), "--out-dir", out().string()}, out());
  expect_refused(run, "vegetation: up to 1.65e+06 trees (spacing 8 m, density 1) and 2.62e+09 ground plants (ground_spacing 0.2 m", out());
  EXPECT_THAT(run.err, HasSubstr("give a larger spacing or ground_spacing, or a lower density or ground_density"));
}

TEST_F(Budget, AContourDemsWorkingArraysAreCheckedNotOnlyItsGrid) {
  // The 8193^2 DEM itself is 0.27 GB, under the limit; its working arrays are seven times that.
  write_text(in() / "rings.geojson", rings_geojson());
  const MeasuredRun run =
      run_measured({"--max-memory", "0.5", "contour-dem", in("rings.geojson"), "--dem-size", "8193", "--dem", out("d.r32")}, out());
  expect_refused(run,
                 "the DEM of 8193 x 8193 cells from the contour map (its working arrays) needs 1.88 GB, more than the memory limit of "
                 "0.5 GB (raise it with --max-memory GB, or give a smaller dem size or a larger cell)",
                 out());
}

TEST_F(Budget, TypeIIPicturesAreCheckedForTheirMemoMaps) {
  // Before, a picture counted no nodes: R = 20 passed the estimate, then the maps grew.
  const MeasuredRun run =
      run_measured({"--max-memory", "1", "solid", "--type", "II", "-R", "20", "--picture-size", "512", "--slice", out("s.png")}, out());
  expect_refused(run, "Type II at R = 20 (about 9.2e+07 nodes in its memo map for 512 px pictures) needs 3.68 GB", out());
  EXPECT_THAT(run.err, HasSubstr("use --type III or IV, a smaller R or a smaller picture size"));
}

TEST_F(Budget, APictureTooLargeIsRefusedBeforeTheGlContext) {
  const std::string heights = heightmap();
  const MeasuredRun run =
      run_measured({"--max-memory", "1", "render", heights, "--width", "8192", "--height", "8192", "-o", out("r.png")}, out());
  expect_refused(run,
                 "a 8192 x 8192 picture with 1 sample a pixel needs 1.61 GB, more than the memory limit of 1 GB (raise it with "
                 "--max-memory GB, or give a smaller width and height, or fewer samples)",
                 out());
  EXPECT_LT(run.seconds, 2.0) << run.err;  // no drawing: before, 11-17 s
}

TEST_F(Budget, ARecipesListsAreCappedBeforeTheirChecks) {
  write_text(in() / "steps.toml", shape_recipe(65, 2000, "step = \"stage\"\nstage = \"mature\"\n"));
  expect_refused(run_measured({"run", in("steps.toml"), "--out-dir", out().string()}, out()),
                 "2000 [[shape]] tables: a recipe may have at most 256", out());
  std::string outputs = shape_recipe(65, 0, "");
  for (int i = 0; i < 4096; ++i) outputs += "[[output]]\nfile = \"t" + std::to_string(i) + ".r32\"\nkind = \"heightmap\"\n";
  write_text(in() / "outputs.toml", outputs);
  expect_refused(run_measured({"run", in("outputs.toml"), "--out-dir", out().string()}, out()),
                 "4097 [[output]] tables: a recipe may have at most 4096", out());
}

TEST_F(Budget, ErodeStepsAreSummedAgainstTheWorkLimit) {
  // Each step alone, about 4 minutes, is under the ten-minute limit; the three are not.
  write_text(in() / "erode.toml", shape_recipe(1025, 3, "step = \"erode\"\nerosion_steps = 3000\n"));
  const MeasuredRun run = run_measured({"run", in("erode.toml"), "--out-dir", out().string()}, out());
  expect_refused(run,
                 "the 3 erode steps without force, on 1025x1025 cells, together would take about 12 minutes, more than the work limit "
                 "of 10 minutes",
                 out());
  EXPECT_THAT(run.err, HasSubstr("or pass force (--force) on the long steps to run it"));
}

// ---- estimate versus measured ----------------------------------------------------------------

/// The estimate a refusal names: "needs 0.0193 GB" in bytes; -1 if the run was not refused so.
double estimate_of(const MeasuredRun& run) {
  static const std::regex needs(R"(needs ([0-9.e+-]+) (GB|TB), more than the memory limit)");
  std::smatch match;
  if (!std::regex_search(run.err, match, needs)) return -1.0;
  return std::stod(match[1].str()) * (match[2].str() == "TB" ? 1e12 : 1e9);
}

struct SweepPoint {
  std::string parameter;          ///< "depth 4"
  std::vector<std::string> args;  ///< the run, without --max-memory
};

struct Stage {
  std::string name;
  std::vector<std::string> baseline;  ///< the same stage at its smallest
  std::vector<SweepPoint> points;
};

TEST_F(Budget, EstimatesAreWithinAFactorOfTwoOfTheMeasuredPeakMemory) {
  // Without transparent huge pages, which `render` and `run` ask for (apps/cli/main.cpp): in 2 MB
  // pieces the resident set measures the arenas' growth, not what was allocated (a 2048^2
  // render measured 54 MB against its 184).
  const char* const tunables = std::getenv("GLIBC_TUNABLES");
  const std::string saved_tunables = tunables != nullptr ? tunables : "";
  ::setenv("GLIBC_TUNABLES", "glibc.malloc.hugetlb=0", 1);
  struct RestoreTunables {
    bool had;
    std::string value;
    ~RestoreTunables() {
      if (had)
        ::setenv("GLIBC_TUNABLES", value.c_str(), 1);
      else
        ::unsetenv("GLIBC_TUNABLES");
    }
  } restore_tunables{tunables != nullptr, saved_tunables};
  // Inputs.
  for (const auto& [branching, depth] : {std::pair{8, 1}, {8, 4}, {12, 4}, {8, 5}})
    write_text(in() / fmt::format("tree{}-{}.toml", branching, depth), species_file(branching, depth, 16));
  for (double spacing : {64.0, 16.0, 8.0, 4.0}) write_text(in() / fmt::format("plants{}.toml", spacing), plants_scene(1000.0, spacing));
  write_text(in() / "rings.geojson", rings_geojson());
  const std::string heights = heightmap();
  const auto tree = [&](int branching, int depth) {
    return std::vector<std::string>{"tree", "--species-file", in(fmt::format("tree{}-{}.toml", branching, depth)), "--species", "big",
                                    "-o",   out("t.glb")};
  };

  const auto plants = [&](double spacing) {
    return std::vector<std::string>{"run", in(fmt::format("plants{}.toml", spacing)), "--out-dir", out().string()};
  };
  const auto dem = [&](int size) {
    return std::vector<std::string>{"contour-dem", in("rings.geojson"), "--dem-size", std::to_string(size), "--dem", out("d.r32")};
  };
  const auto solid = [&](int levels) {
    return std::vector<std::string>{"solid", "--type", "II", "-R", std::to_string(levels), "--picture-size", "96", "--slice", out("s.png")};
  };
  const auto render = [&](int side, int samples) {
    return std::vector<std::string>{
        "render", heights,     "--width", std::to_string(side), "--height", std::to_string(side), "--samples", std::to_string(samples),
        "-o",     out("r.png")};
  };

  const std::vector<Stage> stages{
      {"tree (16 leaves a twig)", tree(8, 1), {{"8^4", tree(8, 4)}, {"12^4", tree(12, 4)}, {"8^5", tree(8, 5)}}},
      {"plants (10 km, ground)",
       plants(64.0),
       {{"spacing 16 m", plants(16.0)}, {"spacing 8 m", plants(8.0)}, {"spacing 4 m", plants(4.0)}}},
      {"contour-dem", dem(129), {{"1025^2", dem(1025)}, {"2049^2", dem(2049)}, {"4097^2", dem(4097)}}},
      {"solid II slice 96 px", solid(8), {{"R 12", solid(12)}, {"R 16", solid(16)}, {"R 20", solid(20)}}},
      {"render", render(64, 1), {{"1536^2 x4", render(1536, 4)}, {"2048^2 x1", render(2048, 1)}, {"3072^2 x1", render(3072, 1)}}},
  };
#ifdef SANSUI_BUDGET_ASAN
  // AddressSanitizer's shadow memory, redzones and quarantine add 2-3x to every allocation and
  // hold freed blocks back, so the ratio says little there: the table is printed, not checked.
  constexpr bool check_ratio = false;
  // The renders' children run without the leak check, whose tracer has crashed at the exit of
  // GL-rendering commands (see cli_runner.hpp); ASan and UBSan still watch them.
  const char* const given = std::getenv("ASAN_OPTIONS");
  const std::string saved = given != nullptr ? given : "";
  ::setenv("ASAN_OPTIONS", (saved + ":detect_leaks=0").c_str(), 1);
  struct Restore {
    std::string value;
    ~Restore() { ::setenv("ASAN_OPTIONS", value.c_str(), 1); }
  } restore{saved};
#else
  constexpr bool check_ratio = true;
#endif
  constexpr double low = 0.5, high = 2.0;
  std::string table = fmt::format("{:<30} {:<12} {:>12} {:>12} {:>7}\n", "stage", "parameter", "estimate MB", "measured MB", "ratio");
  for (const Stage& stage : stages) {
    // The baseline's own estimate is taken off too (a Type II slice at R = 8 has a map of its own).
    const auto refused = [](const std::vector<std::string>& args) {
      std::vector<std::string> with_limit{"--max-memory", "0.001"};
      with_limit.insert(with_limit.end(), args.begin(), args.end());
      return with_limit;
    };
    const double baseline_estimate = std::max(estimate_of(run_measured(refused(stage.baseline), out())), 0.0);
    // A peak read once may read low (a 2048^2 render: 47 MB in one full suite, 140-177 MB in
    // others): llvmpipe and the allocator touch memory lazily, and the suite's other tests shift
    // when. A ratio outside the bounds is measured again, up to three times in all, taking the
    // stage's highest peak against the baseline's lowest.
    long baseline_mb = std::numeric_limits<long>::max();
    const auto measure_baseline = [&] {
      const MeasuredRun baseline = run_measured(stage.baseline, out());
      EXPECT_EQ(baseline.exit_code, 0) << stage.name << ": " << baseline.err;
      baseline_mb = std::min(baseline_mb, baseline.peak_rss_mb);
    };
    measure_baseline();
    for (const SweepPoint& point : stage.points) {
      const double estimate = estimate_of(run_measured(refused(point.args), out()));
      ASSERT_GT(estimate, 0.0) << stage.name << " " << point.parameter << ": not refused at 1 MB";
      long peak_mb = 0;
      double ratio = 0.0;
      for (int measured = 0; measured < 3; ++measured) {
        if (measured > 0) measure_baseline();
        const MeasuredRun run = run_measured(point.args, out());
        ASSERT_EQ(run.exit_code, 0) << stage.name << " " << point.parameter << ": " << run.err;
        peak_mb = std::max(peak_mb, run.peak_rss_mb);
        ratio = static_cast<double>(peak_mb - baseline_mb) / ((estimate - baseline_estimate) / 1e6);
        if (!check_ratio || (ratio >= low && ratio <= high)) break;
      }
      const double measured_mb = static_cast<double>(peak_mb - baseline_mb);
      const double estimate_mb = (estimate - baseline_estimate) / 1e6;
      table += fmt::format("{:<30} {:<12} {:>12.1f} {:>12.1f} {:>7.2f}\n", stage.name, point.parameter, estimate_mb, measured_mb, ratio);
      if (check_ratio) {
        EXPECT_GE(ratio, low) << stage.name << " " << point.parameter;
        EXPECT_LE(ratio, high) << stage.name << " " << point.parameter;
      }
      for (const auto& file : files_in(out())) std::filesystem::remove(out() / file);
    }
  }
  std::fputs(table.c_str(), stdout);
}

}  // namespace
}  // namespace sansui::test
