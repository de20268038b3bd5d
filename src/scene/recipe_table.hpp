// Recipes built as TOML tables in memory (the Python module's dicts), read without going through
// text: toml++'s printer has undefined behaviour on some numbers (it takes the integer part of a
// negative log10 for arrays of values between 0 and 1), so a table is never printed to be parsed.
#pragma once

#include <filesystem>
#include <string>

#include <toml++/toml.h>

#include "scene/recipe_file.hpp"

namespace sansui::scene {

/// Reads a recipe given as a TOML table; `source` names it in messages, `base_dir` is where its
/// relative file names start. Throws InputError "SOURCE: ...". The caller bounds its nesting.
LoadedRecipe parse_recipe_table(const toml::table& root, const std::string& source, const std::filesystem::path& base_dir);

}  // namespace sansui::scene
