// Where a recipe handed to the module comes from: a scene file's path, a dict shaped like a scene
// file, or a sansui.Recipe. Shared by sansui.Recipe and run() (recipes.cpp) and scenery()
// (scenery.cpp), so every function takes the same recipes with the same messages.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

#include "scene/recipe.hpp"

namespace sansui::python {

namespace py = pybind11;

/// A recipe and the warnings its reading gave: what sansui.Recipe holds.
struct PyRecipe {
  scene::Recipe recipe;
  std::vector<std::string> warnings;
};

/// A recipe from a dict shaped like a scene file; relative file names start at `base_dir`.
/// Throws TypeError for what TOML cannot hold, ValueError for a bad recipe (no line numbers).
PyRecipe recipe_from_dict(py::handle dict, const std::filesystem::path& base_dir);

/// `source` as a recipe: None (empty), a dict, a sansui.Recipe or a path (str, os.PathLike).
/// Throws TypeError for anything else.
PyRecipe recipe_from(py::handle source);

/// A JSON value as the Python value json.loads() gives.
py::object json_to_python(const nlohmann::json& json);

}  // namespace sansui::python
