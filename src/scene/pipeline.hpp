// Running a recipe (scene/recipe.hpp): every parameter, input and output is checked first, so
// bad input fails before any work and never leaves a file; then the source makes the heightfield,
// the shaping steps reshape it, and each output is written atomically with its JSON sidecar,
// whose provenance holds the recipe that rebuilds that one file byte for byte (same build).
// The CLI, scene files and the viewer all run recipes through here.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/context.hpp"
#include "core/grid.hpp"
#include "core/tile_exchange.hpp"
#include "scene/climate.hpp"
#include "scene/recipe.hpp"

namespace sansui::scene {

class Evaluator;

struct RunOptions {
  /// Copied into the provenance of every sidecar: program, version, command, command line.
  nlohmann::json provenance = nlohmann::json::object();
  /// Report the seconds of each step where a source measures them.
  bool verbose = false;
  /// Recipe graphs: the evaluator to run them with, whose caches outlive the run (the viewer,
  /// tests). Null: one for this run, keeping results in `cache_dir` when that is set.
  std::shared_ptr<Evaluator> evaluator;
  std::filesystem::path cache_dir;
  /// A tiled world ([world] tiled): the ranks' exchange (src/mpi/). Null: one process works
  /// through every tile.
  TileExchange* exchange = nullptr;
};

struct RunReport {
  std::vector<std::string> lines;                       ///< what the run has to say, for stdout, in order
  std::vector<std::pair<std::string, double>> seconds;  ///< wall seconds of each stage, in order ("midpoint", "sky", ...)
  std::vector<std::filesystem::path> written;           ///< the files written (not their sidecars)
  Recipe resolved;                                      ///< the recipe with defaults that depend on data filled in
};

/// Throws InputError naming the first bad parameter, missing input or unwritable output.
void check_recipe(const Recipe& recipe);

/// check_recipe(), then runs it. Notes (repairs, choices made) go to context.note(). Throws
/// InputError for bad input, Cancelled when asked to stop.
RunReport run_recipe(const Recipe& recipe, const RunOptions& options = {}, const Context& context = quiet_context());

/// Runs only the recipe's source and shaping steps, after checking their sections: the
/// heightfield its outputs would be made from (scenery(), Python's recipes). Through an evaluator
/// of its own, as every recipe runs. Throws InputError when the source makes none (source none),
/// Cancelled when asked to stop.
Heightfield recipe_heights(const Recipe& recipe, const Context& context = quiet_context());

/// recipe_heights() through `evaluator`: a terrain whose key (terrain_key) it holds is not made
/// again, nor are a graph's nodes whose keys are unchanged. The viewer's rebuilds.
std::shared_ptr<const Heightfield> recipe_heights(const Recipe& recipe, Evaluator& evaluator, const Context& context = quiet_context());

/// Everything a recipe's terrain depends on, as text: the library's version, the base directory,
/// the world, the source and the sections it reads, the shaping steps or the graph; not the
/// sections only outputs read, nor the contents of the files the source reads.
std::string terrain_key(const Recipe& recipe);

/// How the recipe shapes its terrain, for `--explain`: where the sea level comes from (a midpoint
/// world's land_fraction), each shaping step (an erode step's erosion time, steps, diffusion,
/// droplets and kept detail, or the paper's stage filter), or that the terrain is not eroded.
std::vector<ExplainedValue> explain_terrain(const Recipe& recipe);

/// The provenance written into the sidecar of `recipe.outputs[index]`: options.provenance plus
/// the recipe restricted to that output, its file names relative to the output's directory.
nlohmann::json output_provenance(const Recipe& recipe, std::size_t index, const RunOptions& options);

}  // namespace sansui::scene
