// The default build is portable (x86-64 baseline, SSE2), -DSANSUI_NATIVE=ON optimises for the build
// machine's CPU; both must give the same bytes (no FMA contraction, no reassociation: see
// cmake/SansuiOptions.cmake). tests/data/native_hashes.txt holds the FNV-1a hashes of a set of
// outputs as a native build on an AVX2 machine wrote them; whichever build runs this test must
// write the same bytes. To remake the list after a deliberate change of bytes, run this test with
// SANSUI_WRITE_HASHES=1 (from a native build).
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "tests/cli/cli_runner.hpp"
#include "tests/test_paths.hpp"
#include "tests/test_util.hpp"

namespace sansui::test {
namespace {

const std::filesystem::path hashes_file = std::string(sansui::test::source_dir) + "/tests/data/native_hashes.txt";

std::uint64_t file_hash(const std::filesystem::path& path) {
  const std::string bytes = read_text(path);
  return fnv1a(bytes.data(), bytes.size());
}

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SANSUI_TEST_SANITIZED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define SANSUI_TEST_SANITIZED 1
#endif

TEST(PortableBuild, WritesTheSameBytesAsTheNativeBuild) {
#ifdef SANSUI_TEST_SANITIZED
  GTEST_SKIP() << "the hashes are the optimised Release build's; the sanitizer build is neither portable nor native";
#endif
  TempDir dir("portable-bytes");
  std::filesystem::copy_file(std::string(sansui::test::source_dir) + "/tests/data/portable_scene.toml", dir / "scene.toml");
  const std::string examples = std::string(sansui::test::source_dir) + "/examples";
  for (const std::string& command : {std::string("run scene.toml --out-dir out"), std::string("solid --levels 6 -o out/field.r32"),
                                     "contour " + examples + "/contours/ridge.geojson --dem-size 257 --dem out/contour.r32",
                                     "subdivide " + examples + "/meshes/mountain80.obj --steps 3 -o out/subdivided.obj",
                                     std::string("terrain --size 257 --seed 3 --lod 1 -o out/lod.r32")})
    ASSERT_EQ(run_cli_line(command, dir.path()).exit_code, 0) << command;
  std::map<std::string, std::uint64_t> hashes;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "out"))
    if (entry.path().extension() != ".json") hashes[entry.path().filename().string()] = file_hash(entry.path());
  if (std::getenv("SANSUI_WRITE_HASHES") != nullptr) {
    std::ofstream out(hashes_file);
    out << "# FNV-1a of each output of tests/cli/portable_bytes_cli_test.cpp, as a native build writes them\n";
    for (const auto& [name, hash] : hashes) out << name << " " << fmt::format("{:016x}", hash) << "\n";
    GTEST_SKIP() << "wrote " << hashes_file;
  }
  std::ifstream in(hashes_file);
  std::map<std::string, std::string> expected;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string name, hash;
    fields >> name >> hash;
    expected[name] = hash;
  }
  ASSERT_EQ(expected.size(), hashes.size());
  for (const auto& [name, hash] : hashes) EXPECT_EQ(expected[name], fmt::format("{:016x}", hash)) << name;
}

}  // namespace
}  // namespace sansui::test
