// The layers of src/ (src/CMakeLists.txt): each subsystem includes only the ones below it. The
// link fails for most wrong includes; this catches the header-only ones too. Then apps/: thin
// front ends over scene/, the CLI handing scene its renderer in main.cpp only.
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "tests/test_paths.hpp"

namespace sansui {
namespace {

const std::map<std::string, std::set<std::string>> allowed = {
    {"core", {"core"}},
    {"terrain", {"core", "terrain"}},
    {"water", {"core", "water"}},
    {"solid", {"core", "solid"}},
    {"mesh", {"core", "mesh"}},
    {"vegetation", {"core", "vegetation"}},
    {"contour", {"core", "terrain", "contour"}},
    {"io", {"core", "io"}},
    {"look", {"core", "vegetation", "water", "look"}},  // the landform maps route water (look/ground_maps.hpp)
    {"render", {"core", "look", "render"}},             // draws what look/ prepared: never vegetation's or water's types
    {"scene", {"core", "terrain", "solid", "mesh", "vegetation", "contour", "io", "look", "water", "scene"}},
    {"mpi", {"core", "mpi"}},  // the exchange only; what runs over it lives in the layers it belongs to
};

const std::regex include(R"(^\s*#\s*include\s*"([a-z_]+)/)");

/// Calls `check(line number, first folder)` for each project include of `file`.
template <typename Check>
void for_each_include(const std::filesystem::path& file, Check check) {
  std::ifstream in(file);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::smatch match;
    if (std::regex_search(line, match, include)) check(number, match[1].str());
  }
}

bool is_source(const std::filesystem::path& path) {
  return path.extension() == ".hpp" || path.extension() == ".cpp";
}

TEST(Layers, EverySubsystemIncludesOnlyTheLayersBelowIt) {
  const std::filesystem::path src = std::filesystem::path(sansui::test::source_dir) / "src";
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(src)) {
    if (!is_source(entry.path())) continue;
    const std::string subsystem = entry.path().parent_path().filename().string();
    ASSERT_TRUE(allowed.contains(subsystem)) << "a new folder " << subsystem << ": add it to the layers here and in src/CMakeLists.txt";
    for_each_include(entry.path(), [&](int number, const std::string& layer) {
      EXPECT_TRUE(allowed.at(subsystem).contains(layer)) << entry.path().lexically_relative(src).string() << ":" << number << " includes "
                                                         << layer << "/ (" << subsystem << " may include only the layers below it)";
    });
    ++files;
  }
  EXPECT_GT(files, 150);
}

// The CLI reaches the library through scene/ (and core, io, the benchmark harness); only its
// main() names the renderer and the MPI ranks' exchange. The viewer draws, so it may use every layer, and its own folder.
TEST(Layers, AppsAreThinFrontEnds) {
  const std::filesystem::path apps = std::filesystem::path(sansui::test::source_dir) / "apps";
  const std::set<std::string> cli = {"apps", "core", "io", "scene", "bench"};
  // The viewer draws, so it may use render/ and look/; the engine's products (rivers, lakes,
  // plants) it takes through scene/, never from water/ or vegetation/ themselves.
  std::set<std::string> viewer = {"viewer", "apps"};
  for (const auto& [layer, below] : allowed) viewer.insert(layer);
  viewer.erase("water");
  viewer.erase("vegetation");
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(apps)) {
    if (!is_source(entry.path())) continue;
    const std::string app = entry.path().parent_path().filename().string();
    ASSERT_TRUE(app == "cli" || app == "viewer") << "a new app " << app << ": add its rules here";
    const bool cli_main = app == "cli" && entry.path().filename() == "main.cpp";
    for_each_include(entry.path(), [&](int number, const std::string& layer) {
      const bool ok = app == "viewer" ? viewer.contains(layer) : cli.contains(layer) || (cli_main && (layer == "render" || layer == "mpi"));
      EXPECT_TRUE(ok) << entry.path().lexically_relative(apps).string() << ":" << number << " includes " << layer << "/";
    });
    ++files;
  }
  EXPECT_GT(files, 25);
}

// oneTBB is behind one seam (core/parallel.hpp, core/parallel_sort.hpp and their back ends), so
// that SANSUI_PARALLEL=serial builds without it and a new scheduler would change one place.
TEST(Layers, OnlyTheParallelSeamIncludesOneTbb) {
  const std::filesystem::path root(sansui::test::source_dir);
  const std::regex tbb_include(R"(^\s*#\s*include\s*<tbb/)");
  int files = 0;
  for (const char* folder : {"src", "apps"}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root / folder)) {
      const auto extension = entry.path().extension();
      if (extension != ".hpp" && extension != ".cpp") continue;
      const std::string name = entry.path().lexically_relative(root).generic_string();
      if (name.starts_with("src/core/parallel")) continue;
      std::ifstream in(entry.path());
      std::string line;
      for (int number = 1; std::getline(in, line); ++number)
        EXPECT_FALSE(std::regex_search(line, tbb_include)) << name << ":" << number << " includes oneTBB: use core/parallel.hpp";
      ++files;
    }
  }
  EXPECT_GT(files, 150);
}

}  // namespace
}  // namespace sansui
