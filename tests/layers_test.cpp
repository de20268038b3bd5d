// The layers of src/ (src/CMakeLists.txt): each subsystem includes only the ones below it. The
// link fails for most wrong includes; this catches the header-only ones too.
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>

#include <gtest/gtest.h>

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
    {"io", {"core", "contour", "mesh", "solid", "vegetation", "water", "io"}},
    {"render", {"core", "vegetation", "water", "render"}},
    {"scene", {"core", "terrain", "solid", "mesh", "vegetation", "contour", "io", "render", "water", "scene"}},
};

TEST(Layers, EverySubsystemIncludesOnlyTheLayersBelowIt) {
  const std::filesystem::path src = std::filesystem::path(SANSUI_SOURCE_DIR) / "src";
  const std::regex include(R"(^\s*#\s*include\s*"([a-z_]+)/)");
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(src)) {
    const auto extension = entry.path().extension();
    if (extension != ".hpp" && extension != ".cpp") continue;
    const std::string subsystem = entry.path().parent_path().filename().string();
    ASSERT_TRUE(allowed.contains(subsystem)) << "a new folder " << subsystem << ": add it to the layers here and in src/CMakeLists.txt";
    std::ifstream in(entry.path());
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      std::smatch match;
      if (std::regex_search(line, match, include)) {
        EXPECT_TRUE(allowed.at(subsystem).contains(match[1].str()))
            << entry.path().lexically_relative(src).string() << ":" << number << " includes " << match[1] << "/ (" << subsystem
            << " may include only the layers below it)";
      }
    }
    ++files;
  }
  EXPECT_GT(files, 150);
}

}  // namespace
}  // namespace sansui
