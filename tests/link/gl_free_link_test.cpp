// A program that makes heightmaps, meshes and vector files through scene/ links no GL or EGL
// library (src/CMakeLists.txt: render is the only target that links them; scene/painter.hpp).
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "tests/test_paths.hpp"

namespace sansui {
namespace {

std::string shell_output(const std::string& command) {
  std::string text;
  const std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) return text;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe.get()) != nullptr) text += buffer.data();
  return text;
}

// ldd lists the shared libraries the program loads, its dependencies' too.
std::string shared_libraries(const std::string& program) {
  return shell_output("ldd '" + program + "' 2>&1");
}

bool links_gl(const std::string& libraries) {
  for (const char* name : {"libGL.", "libGLX", "libOpenGL", "libEGL", "libepoxy", "libglfw", "libgbm"})
    if (libraries.find(name) != std::string::npos) return true;
  return false;
}

TEST(GlFreeLink, AProgramWithoutPicturesLinksNoGlOrEgl) {
  const std::string libraries = shared_libraries(sansui::test::gl_free_runner_path);
  ASSERT_NE(libraries.find("libc.so"), std::string::npos) << libraries;  // ldd worked
  EXPECT_FALSE(links_gl(libraries)) << libraries;
  // The check can see GL: the CLI draws pictures and links it.
  EXPECT_TRUE(links_gl(shared_libraries(sansui::test::cli_path)));
}

class GlFreeRun : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("sansui-gl-free-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

int run(const std::filesystem::path& dir, const std::string& text, std::string& err) {
  std::ofstream(dir / "scene.toml") << text;
  const std::string line = "'" + std::string(sansui::test::gl_free_runner_path) + "' '" + (dir / "scene.toml").string() + "' 2> '" +
                           (dir / "err").string() + "' < /dev/null";
  const int status = std::system(line.c_str());
  std::ifstream in(dir / "err");
  err.assign(std::istreambuf_iterator<char>(in), {});
  std::filesystem::remove(dir / "err");
  std::filesystem::remove(dir / "scene.toml");
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST_F(GlFreeRun, MakesHeightmapsMeshesAndRivers) {
  std::string err;
  const int status =
      run(dir_,
          "sansui_recipe = 3\nsource = \"midpoint\"\n[midpoint]\nseed = 3\n[world]\nsize = 65\n[[shape]]\nstep = \"erode\"\n"
          "[[output]]\nfile = \"t.r32\"\n[[output]]\nfile = \"t.obj\"\n[[output]]\nfile = \"rivers.geojson\"\nkind = \"rivers\"\n",
          err);
  EXPECT_EQ(status, 0) << err;
  for (const char* file : {"t.r32", "t.obj", "rivers.geojson"}) EXPECT_TRUE(std::filesystem::exists(dir_ / file)) << file;
}

TEST_F(GlFreeRun, RefusesAPictureBeforeAnyWork) {
  std::string err;
  const int status = run(dir_,
                         "sansui_recipe = 3\nsource = \"midpoint\"\n[world]\nsize = 65\n[[output]]\nfile = \"t.r32\"\n[[output]]\nfile = "
                         "\"view.png\"\nkind = \"render\"\n",
                         err);
  EXPECT_EQ(status, 2) << err;
  EXPECT_NE(err.find("cannot draw pictures"), std::string::npos) << err;
  EXPECT_TRUE(std::filesystem::is_empty(dir_));
}

}  // namespace
}  // namespace sansui
