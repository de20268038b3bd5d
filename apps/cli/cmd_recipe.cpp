// The recipe commands (terrain, render, contour, compare, solid, subdivide): each is built from
// its scene::CommandSpec, fills a recipe from its options and runs it. `--save-recipe FILE`
// also writes the recipe as a scene file that `sansui run FILE` runs to the same bytes.
#include <algorithm>
#include <filesystem>
#include <memory>

#include "apps/cli/bind_params.hpp"
#include "apps/cli/cli_support.hpp"
#include "apps/cli/commands.hpp"
#include "scene/commands.hpp"
#include "scene/pipeline.hpp"
#include "scene/recipe_file.hpp"

namespace sansui::cli {
namespace {

struct CommandState {
  scene::Recipe recipe;
  std::string save_recipe;
  std::string cache;
  bool erode = false;
  scene::ShapeStep erode_step;  // --erode without a stage step: its options land here
};

bool is_positional(const scene::CommandSpec& spec, const std::string& key) {
  for (const auto& positional : spec.positionals)
    if (positional.key == key) return true;
  return false;
}

void add_recipe_command(CLI::App& app, const scene::CommandSpec& spec, RecipeMode mode) {
  auto state = std::make_shared<CommandState>();
  state->recipe = scene::default_recipe(spec.source);
  scene::Recipe& recipe = state->recipe;
  CLI::App* command = app.add_subcommand(spec.name, spec.help);
  const auto& table = scene::recipe_table();

  for (const auto& positional : spec.positionals) {
    const auto* row = table.find(positional.key);
    command->add_option_function<std::string>(
        positional.name, [row, &recipe](const std::string& text) { row->set(recipe, text); }, row->help);
  }
  for (const auto& use : spec.sections)
    bind_table<scene::Recipe>(*command, table, recipe, use.prefix, use.group, [&](const params::Param<scene::Recipe>& row) {
      return scene::section_of(row.key) == use.section && !is_positional(spec, row.key);
    });
  // The world's facts, also for commands that take no other key of [world]: one sea level for
  // the terrain, the picture and the rivers (--sea-level), and the CRS (--crs) where outputs
  // are georeferenced.
  const auto binds = [&](std::string_view section) {
    return std::any_of(spec.sections.begin(), spec.sections.end(), [&](const auto& use) { return use.section == section; });
  };
  if (!binds("world") && spec.source != scene::SourceKind::none)
    bind_table<scene::Recipe>(*command, table, recipe, "", "World", [&](const params::Param<scene::Recipe>& row) {
      return row.key == "world.sea_level" || (row.key == "world.crs" && binds("georeference"));
    });
  if (spec.stage_step) {
    // The terrain is eroded unless told --no-erode (then the step is the paper's stage filter).
    recipe.shape.assign(1, scene::default_erode_step());
    state->erode = true;
    bind_table<scene::ShapeStep>(*command, params::table_of<scene::ShapeStep>(), recipe.shape[0], "", "Geomorphic stage and erosion",
                                 [](const auto& row) { return row.key != "step"; });
  } else if (spec.erode_option) {
    state->erode_step.step = scene::StepKind::erode;
    // Prefixed: the step's keys (stage, ...) beside those of the command's other sections.
    bind_table<scene::ShapeStep>(*command, params::table_of<scene::ShapeStep>(), state->erode_step, "erode-", "Erosion (--erode)",
                                 [](const auto& row) { return row.key != "step"; });
  }
  if (spec.erode_option)
    command
        ->add_flag("--erode,!--no-erode", state->erode,
                   spec.stage_step ? "Erode the terrain (the default): stream power, hillslope diffusion, thermal and droplet erosion "
                                     "(docs/erosion.md), --stage is the erosion time; --no-erode: the raw fractal, --stage the paper's "
                                     "geomorphic filter"
                                   : "Erode the terrain: stream power, hillslope diffusion, thermal and droplet erosion (docs/erosion.md)")
        ->group(spec.stage_step ? "Geomorphic stage and erosion" : "Erosion (--erode)");
  for (const auto& output : spec.outputs) {
    const auto kind = output.kind;
    auto add = [&recipe, kind](const std::string& file) { recipe.outputs.push_back({file, kind, {}, {}}); };
    CLI::Option* option = output.repeatable ? command->add_option_function<std::vector<std::string>>(
                                                  output.names,
                                                  [add](const std::vector<std::string>& files) {
                                                    for (const auto& f : files) add(f);
                                                  },
                                                  output.help)
                                            : command->add_option_function<std::string>(output.names, add, output.help);
    option->group("Outputs");
  }
  command
      ->add_option("--save-recipe", state->save_recipe,
                   "Also write this command as a scene file (TOML) that `sansui run` runs to the same bytes")
      ->group("Outputs");
  command
      ->add_option("--cache", state->cache,
                   "Keep the terrain (and the coarse eroded world that tiles share) in this directory, so that a rerun or "
                   "another tile skips what did not change")
      ->group("Outputs");
  command->callback([state, spec, mode] {
    scene::Recipe& filled = state->recipe;
    filled.base_dir = std::filesystem::current_path();
    filled.output_rules.follow_symlinks = follow_symlinks();
    if (spec.stage_step) filled.shape[0].step = state->erode ? scene::StepKind::erode : scene::StepKind::stage;
    if (state->erode && !spec.stage_step) filled.shape.push_back(state->erode_step);
    for (const auto& output : spec.fixed_outputs) filled.outputs.push_back(output);
    scene::settle_world(filled);
    if (mode == RecipeMode::check_only) return scene::check_recipe(filled);
    if (!state->save_recipe.empty()) {
      scene::check_recipe(filled);
      scene::save_recipe(state->save_recipe, filled);
    }
    run_recipe_and_report(filled, spec.name, state->cache);
  });
}

}  // namespace

void add_recipe_commands(CLI::App& app, RecipeMode mode) {
  for (const auto& spec : scene::command_specs()) add_recipe_command(app, spec, mode);
}

}  // namespace sansui::cli
