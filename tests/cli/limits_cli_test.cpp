// Limits before work (issue 15 item 4): a size from an option or a file that needs more memory
// than --max-memory allows is refused at once, with the memory it would need and the option to
// raise, before anything is allocated: the process stays small and ends within a second.
#include <fstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/cli/cli_runner.hpp"
#include "tests/cli/measured_run.hpp"
#include "tests/test_util.hpp"

namespace sansui::test {
namespace {

using ::testing::HasSubstr;

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

/// Refused with exit 2, one line naming the memory and --max-memory, in under a second (two
/// under the sanitizers' start-up), at no more than 300 MB of peak memory (the sanitizer
/// build's own start-up takes about 60).
void expect_refused_before_work(const MeasuredRun& run, const std::string& message) {
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_THAT(run.err, HasSubstr(message));
  EXPECT_THAT(run.err, HasSubstr("more than the memory limit of"));
  EXPECT_THAT(run.err, HasSubstr("(raise it with --max-memory GB)"));
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_LT(run.seconds, 2.0) << run.err;
  EXPECT_LT(run.peak_rss_mb, 300) << run.err;
}

TEST(Limits, AWorldOrTileTooLargeForMemoryIsRefusedAtOnce) {
  TempDir directory("limits-terrain");
  const MeasuredRun tile = run_measured({"--max-memory", "4", "terrain", "--world-size", "1048577", "--tile-size", "1048577", "--tile",
                                         "0,0", "-o", (directory / "t.r32").string()},
                                        directory.path());
  expect_refused_before_work(tile, "world.tile_size 1048577 (a 1048577 x 1048577 tile) needs 4.4 TB");
  // The limit is the option's: 1025 x 1025 samples (4.2 MB) pass 1 GB and not 1 MB.
  const MeasuredRun small =
      run_measured({"--max-memory", "0.001", "terrain", "--size", "1025", "-o", (directory / "s.r32").string()}, directory.path());
  expect_refused_before_work(small, "world.size 1025 (a 1025 x 1025 heightmap) needs 0.0042 GB, more than the memory limit of 0.001 GB");
  EXPECT_TRUE(files_in(directory.path()).empty());
}

TEST(Limits, ASubdivisionDemTooLargeForMemoryIsRefusedBeforeSubdividing) {
  TempDir directory("limits-subdivide");
  const MeasuredRun run = run_measured({"--max-memory", "4", "subdivide", "--pyramid", "100,50", "--steps", "8", "--dem-size", "65537",
                                        "--dem", (directory / "d.r32").string(), "-o", (directory / "m.glb").string()},
                                       directory.path());
  expect_refused_before_work(run, "dem.size 65537 (a 65537 x 65537 DEM) needs 17.2 GB");
  EXPECT_TRUE(files_in(directory.path()).empty());
}

TEST(Limits, ASubdivisionTooLargeForMemoryIsRefusedBeforeItsStep) {
  TempDir directory("limits-mesh");
  // Steps known ahead: refused before the first step.
  const MeasuredRun steps = run_measured(
      {"--max-memory", "0.2", "subdivide", "--pyramid", "10,5", "--steps", "11", "-o", (directory / "m.glb").string()}, directory.path());
  expect_refused_before_work(steps, "subdivision to 11 steps (16777216 triangles) needs 2.94 GB");
  // A forced minimum edge: refused before the step that would pass the limit.
  const MeasuredRun forced = run_measured(
      {"--max-memory", "0.2", "subdivide", "--pyramid", "10,5", "--min-edge", "0.001", "--force", "-o", (directory / "m.glb").string()},
      directory.path());
  EXPECT_EQ(forced.exit_code, 2) << forced.err;
  EXPECT_THAT(forced.err, HasSubstr("subdivision step 10 (4194304 triangles) needs 0.734 GB, more than the memory limit of 0.2 GB"));
  EXPECT_LT(forced.peak_rss_mb, 400) << forced.err;
  EXPECT_TRUE(files_in(directory.path()).empty());
}

/// The bytes of a PNG chunk: length, type, data, CRC-32.
std::string png_chunk(const std::string& type, const std::string& data) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (const char c : type + data) {
    crc ^= static_cast<unsigned char>(c);
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  crc = ~crc;
  const auto be32 = [](std::uint32_t v) { return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)}; };
  return be32(static_cast<std::uint32_t>(data.size())) + type + data + be32(crc);
}

TEST(Limits, APngDeclaringMoreSamplesThanItsBytesCanHoldIsRefusedBeforeAllocating) {
  TempDir directory("limits-png");
  // 30,000 x 30,000 16-bit grey samples, interlaced, in 100 bytes (the fuzzer's out-of-memory).
  const std::string ihdr{"\x00\x00\x75\x30\x00\x00\x75\x30\x10\x00\x00\x00\x01", 13};
  const std::string png =
      std::string("\x89PNG\r\n\x1a\n", 8) + png_chunk("IHDR", ihdr) + png_chunk("IDAT", std::string(40, 'x')) + png_chunk("IEND", "");
  write_text(directory / "big.png", png);
  const MeasuredRun run = run_measured({"compare", (directory / "big.png").string(), (directory / "big.png").string()}, directory.path());
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_THAT(run.err, HasSubstr("big.png: it declares 30000 x 30000 samples (1.8e+03 MB decoded), more than its"));
  EXPECT_LT(run.seconds, 2.0);
  EXPECT_LT(run.peak_rss_mb, 300);
}

}  // namespace
}  // namespace sansui::test
