// The recipe's own budget (issue 30): caps on its lists ([[shape]], [[output]], [[camera]],
// [[node]]) and the memory its copies and its sidecar take, checked with budget::check before
// any work (check_recipe calls it first, before checks that compare the list's items in pairs).
#pragma once

#include <cstddef>

#include "core/budget.hpp"
#include "scene/recipe.hpp"

namespace sansui::scene {

/// The most items of each recipe list: far more than any scene uses (the gallery's longest has 4
/// shaping steps and 6 outputs), few enough that the checks that compare the items in pairs and
/// the sidecars stay small.
inline constexpr std::size_t max_shape_steps = 1000;
inline constexpr std::size_t max_outputs = 1000;
inline constexpr std::size_t max_cameras = 1000;
inline constexpr std::size_t max_nodes = 1000;

/// The memory a run keeps for the recipe itself: its copies (the run's resolved recipe, the
/// terrain's cache key, each output's provenance) and each sidecar's JSON text.
budget::Cost recipe_cost(const Recipe& recipe);

/// Throws InputError if a list is longer than its cap (naming the list, its count and the cap),
/// or the recipe's cost does not fit (budget::check).
void check_recipe_budget(const Recipe& recipe);

}  // namespace sansui::scene
