// Recipes as files: scene files in TOML (toml++) and the recipe inside every output's JSON
// sidecar. Reading names the file, line and key of anything wrong (pbrt-v4's habit): a value
// of the wrong type or out of range, an unknown key or section (with the nearest known key), an
// input file that does not exist, two sources; keys set in sections that neither the source nor
// any output reads are reported as warnings. Writing gives a complete, commented file: every key
// of every section the recipe uses, unset ones commented out.
//
// File names in a recipe file are relative to the file's own directory.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/recipe.hpp"

namespace sansui::scene {

struct LoadedRecipe {
  Recipe recipe;
  std::vector<std::string> warnings;  ///< "FILE:LINE: ..." one line each
};

/// Reads a scene file (.toml) or an output's sidecar (.json: the recipe in its provenance).
/// Throws InputError.
LoadedRecipe load_recipe(const std::filesystem::path& file);

/// Reads recipe text in TOML; `source` names it in messages, `base_dir` is where its relative
/// file names start. Throws InputError "SOURCE:LINE: ...".
LoadedRecipe parse_recipe_toml(std::string_view text, const std::string& source, const std::filesystem::path& base_dir);

/// The recipe as a complete, commented TOML scene file (file names as they are in `recipe`).
std::string recipe_to_toml(const Recipe& recipe, std::string_view heading = {});

/// The recipe as JSON, shaped like the TOML file (sections as objects, unset keys left out).
nlohmann::json recipe_to_json(const Recipe& recipe);

/// The same recipe with its relative file names made relative to `base_dir` instead.
Recipe rebased(Recipe recipe, const std::filesystem::path& base_dir);

/// The same recipe with every output's file moved into `dir` (made if missing), keeping its
/// name, and outputs confined to it: `sansui run --out-dir`, sansui.run(out_dir=...).
Recipe with_outputs_in(Recipe recipe, const std::filesystem::path& dir);

/// The same recipe with only output `index`.
Recipe restricted(Recipe recipe, std::size_t index);

/// Writes the recipe as a scene file at `file` (atomically), file names relative to its directory.
void save_recipe(const std::filesystem::path& file, const Recipe& recipe);

/// The commented file `sansui run --print-defaults --source NAME` writes: every key of the
/// sections the source and its example outputs read, with its default.
std::string default_recipe_text(SourceKind source);

/// The key of `candidates` nearest to `key` by edit distance, if one is near enough to be a typo.
std::optional<std::string> nearest_key(std::string_view key, const std::vector<std::string>& candidates);

}  // namespace sansui::scene
