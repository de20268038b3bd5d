// The recipe readers on arbitrary bytes: the body of the byte mutation test that CI runs with
// GCC (recipe_mutation_test.cpp). The libFuzzer targets of recipes are scene_toml and sidecar
// (fuzz_target.cpp) and recipe (fuzz_structured.cpp: structured mutations, then check_recipe).
// Any input must end either in a recipe or in an InputError: no crash, no hang, no other
// exception (which the CLI would report as an internal error).
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string_view>

#include "core/error.hpp"
#include "scene/recipe_file.hpp"

namespace sansui::test {

/// Reads `bytes` as a TOML scene file and, written to `scratch`, as a JSON sidecar. Returns how
/// many of the two were accepted; throws whatever is not an InputError.
inline int read_recipe_input(std::string_view bytes, const std::filesystem::path& scratch) {
  int accepted = 0;
  try {
    (void)scene::parse_recipe_toml(bytes, "fuzz.toml", scratch.parent_path());
    ++accepted;
  } catch (const InputError&) {}
  {
    std::ofstream out(scratch, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  try {
    (void)scene::load_recipe(scratch);
    ++accepted;
  } catch (const InputError&) {}
  return accepted;
}

}  // namespace sansui::test
