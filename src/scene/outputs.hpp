// Writing the outputs of a recipe (internal to scene/): each file atomically with its sidecar.
#pragma once

#include "core/context.hpp"
#include "scene/pipeline.hpp"
#include "scene/sources.hpp"

namespace sansui::scene::detail {

/// Checks of the sections the outputs read, beyond single values (throws InputError).
void check_output_settings(const Recipe& recipe);

/// Writes every output of `recipe` from what the source made; adds a report line per file.
void write_outputs(const Recipe& recipe, Produced& produced, const RunOptions& options, const Context& context, RunReport& report);

}  // namespace sansui::scene::detail
