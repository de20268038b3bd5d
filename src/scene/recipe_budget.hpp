// The recipe's own budget (issue 30): caps on its lists ([[shape]], [[output]], [[camera]],
// [[node]]) and the memory its copies and its sidecar take, checked with budget::check before
// any work (check_recipe calls it first, before checks that compare the list's items in pairs).
#pragma once

#include <cstddef>

#include "core/budget.hpp"
#include "scene/recipe.hpp"

namespace sansui::scene {

// The caps of the lists (max_shape_steps, max_outputs, max_cameras, max_nodes) are in
// scene/recipe.hpp, where the file reader refuses a longer list before reading it; this check
// holds them for recipes made in code too.

/// The memory a run keeps for the recipe itself: its copies (the run's resolved recipe, the
/// terrain's cache key, each output's provenance) and each sidecar's JSON text.
budget::Cost recipe_cost(const Recipe& recipe);

/// Throws InputError if a list is longer than its cap (naming the list, its count and the cap),
/// or the recipe's cost does not fit (budget::check).
void check_recipe_budget(const Recipe& recipe);

}  // namespace sansui::scene
