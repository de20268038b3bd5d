// `sansui run RECIPE`: runs a scene file (TOML) or the recipe in an output's JSON sidecar, which
// rebuilds that output byte for byte. `--print-defaults` writes a complete commented scene file.
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "apps/cli/cli_support.hpp"
#include "apps/cli/commands.hpp"
#include "core/error.hpp"
#include "scene/look.hpp"
#include "scene/pipeline.hpp"
#include "scene/recipe_file.hpp"

namespace sansui::cli {
namespace {

struct RunState {
  std::string file;
  std::string output;
  std::string out_dir;
  std::string save_recipe;
  bool print_defaults = false;
  bool explain = false;
  bool graph = false;
  bool allow_outside_paths = false;
  std::string cache;
  std::string source = "midpoint";
};

void run(const RunState& o) {
  if (o.print_defaults) {
    const auto source = scene::source_from_name(o.source);
    if (!source) fail("--source '{}' is not allowed: it must be one of {}", o.source, fmt::join(scene::source_names(), ", "));
    fmt::print("{}", scene::default_recipe_text(*source));
    return;
  }
  if (o.file.empty()) fail("no recipe: give a scene file (.toml) or an output's sidecar (.json), or --print-defaults");
  scene::LoadedRecipe loaded = scene::load_recipe(o.file);
  for (const auto& warning : loaded.warnings) fmt::print(stderr, "sansui: warning: {}\n", terminal_line(warning));
  scene::Recipe& recipe = loaded.recipe;
  if (o.graph) {
    fmt::print("{}", scene::graph_dot(recipe));
    return;
  }
  if (o.explain) {
    // Every low-level value of the look, and where it came from.
    scene::Recipe looked = recipe;
    for (const auto& line : scene::explain_terrain(recipe)) fmt::print("{:<20} = {:<28} ({})\n", line.key, line.value, line.source);
    for (const auto& line : scene::resolve_look(looked)) fmt::print("{:<20} = {:<28} ({})\n", line.key, line.value, line.source);
    return;
  }
  if (!o.output.empty()) {
    // -o takes the recipe's one output, or its one picture of the whole scene.
    std::vector<scene::Output> chosen;
    for (const auto& output : recipe.outputs)
      if (recipe.outputs.size() == 1 || scene::resolved_kind(output) == scene::OutputKind::render) chosen.push_back(output);
    if (chosen.size() != 1)
      fail("-o {} needs a recipe with one output or one render output; {} has {} outputs: change its [[output]] entries instead", o.output,
           o.file, recipe.outputs.size());
    chosen[0].file = std::filesystem::absolute(o.output).lexically_normal().lexically_relative(recipe.base_dir).string();
    recipe.outputs = chosen;
    recipe.output_rules.confined_to.clear();  // the name the user typed, wherever it is
  }
  // Every output keeps its file name and moves into the directory, made if it is missing.
  if (!o.out_dir.empty()) recipe = scene::with_outputs_in(std::move(recipe), o.out_dir);
  if (o.allow_outside_paths) recipe.output_rules.confined_to.clear();
  recipe.output_rules.follow_symlinks = follow_symlinks();
  if (!o.save_recipe.empty()) {
    scene::check_recipe(recipe);
    scene::save_recipe(o.save_recipe, recipe);
  }
  run_recipe_and_report(recipe, "run", o.cache);
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto state = std::make_shared<RunState>();
  CLI::App* command = app.add_subcommand(
      "run", "Run a recipe: a scene file (.toml) or the JSON sidecar of any output, which rebuilds that output byte for byte.");
  command->add_option("recipe", state->file, "Scene file (.toml) or sidecar (FILE.EXT.json)");
  command->add_option("-o,--out", state->output, "Write the recipe's one output here instead");
  command->add_option("--out-dir", state->out_dir, "Write every output into this directory (made if missing), keeping its file name");
  command->add_option("--save-recipe", state->save_recipe, "Also write the recipe as a scene file (TOML), file names relative to it");
  command->add_flag("--allow-outside-paths", state->allow_outside_paths,
                    "Let the recipe's outputs be written outside its folder (names with .. or absolute names in the file); without "
                    "it they are refused, so that a recipe someone sent cannot replace files elsewhere");
  command->add_flag("--print-defaults", state->print_defaults, "Print a complete commented scene file with every default, and stop");
  command->add_flag(
      "--explain", state->explain,
      "Print how the terrain is shaped (sea level, erosion) and the scene's derived low-level values (palette, snow and tree lines, sun, "
      "sky, fog), and where each came from, and stop");
  command->add_flag("--graph", state->graph,
                    "Print the recipe as a graph in Graphviz dot (its nodes, or its source, shaping steps and outputs), and stop");
  command->add_option("--cache", state->cache,
                      "Keep the results of a recipe graph's nodes in this directory, so that a rerun skips what did not change");
  command->add_option("--source", state->source,
                      "With --print-defaults: the source, midpoint, file, contour, mesh or none [Default: midpoint]");
  command->callback([state] { run(*state); });
}

}  // namespace sansui::cli
