// libFuzzer target for the recipe readers (scene files and sidecars). Build with clang:
//   CC=clang CXX=clang++ cmake -S . -B build-fuzz -DSANSUI_FUZZ=ON -DSANSUI_NATIVE=OFF && cmake --build build-fuzz --target fuzz_recipe
//   mkdir -p build-fuzz/corpus && build-fuzz/fuzz_recipe build-fuzz/corpus examples/scenes/
#include <unistd.h>

#include "tests/fuzz/recipe_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const auto scratch = std::filesystem::temp_directory_path() / ("sansui-fuzz-" + std::to_string(::getpid()) + ".json");
  sansui::test::read_recipe_input(std::string_view(reinterpret_cast<const char*>(data), size), scratch);
  return 0;
}
